// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// Splitting one line of a delimited text export (CSV with ',' or ';', optionally with
// RFC 4180 double quotes) into fields without allocating: the shared helper of the CSV-like
// log readers (CoScope CSV, SavvyCAN GVRET, IXXAT exports).

#include "core/logio/TextScan.h"

#include <QString>

#include <array>
#include <string_view>

namespace coscope::logio {

class CsvFields {
public:
    static constexpr size_t kMax = 80;  // 6 fixed columns + 64 data bytes and some slack

    // Splits `line` at `sep`. A field in double quotes may hold the separator; its quotes are
    // removed (a doubled quote inside stays doubled). Fields are trimmed of blanks.
    CsvFields(std::string_view line, char sep) {
        size_t i = 0;
        for (;;) {
            while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
            std::string_view field;
            if (i < line.size() && line[i] == '"') {
                const size_t start = ++i;
                while (i < line.size()) {
                    if (line[i] == '"') {
                        if (i + 1 < line.size() && line[i + 1] == '"') {
                            i += 2;
                            continue;
                        }
                        break;
                    }
                    ++i;
                }
                field = line.substr(start, i - start);
                if (i < line.size()) ++i;  // closing quote
                while (i < line.size() && line[i] != sep) ++i;
            } else {
                const size_t start = i;
                while (i < line.size() && line[i] != sep) ++i;
                field = line.substr(start, i - start);
            }
            if (count_ < kMax) fields_[count_++] = trimmed(field);
            else overflow_ = true;
            if (i >= line.size()) break;
            ++i;  // separator
        }
    }

    size_t size() const { return count_; }
    bool overflow() const { return overflow_; }
    // Field i, or an empty view past the end.
    std::string_view operator[](size_t i) const { return i < count_ ? fields_[i] : std::string_view(); }

private:
    std::array<std::string_view, kMax> fields_{};
    size_t count_ = 0;
    bool overflow_ = false;
};

// A token for a diagnostic message (cut at 40 characters).
inline QString quoted(std::string_view t) {
    const bool cut = t.size() > 40;
    return QLatin1Char('\'') + QString::fromLatin1(t.data(), qsizetype(cut ? 40 : t.size())) +
           (cut ? QStringLiteral("...'") : QStringLiteral("'"));
}

inline bool containsNoCase(std::string_view hay, std::string_view needle) {
    if (needle.empty()) return true;
    for (size_t i = 0; i + needle.size() <= hay.size(); ++i)
        if (equalsNoCase(hay.substr(i, needle.size()), needle)) return true;
    return false;
}

}  // namespace coscope::logio
