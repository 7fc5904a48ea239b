// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/logio/CaptureGapText.h"

#include "core/logio/TextScan.h"

#include <QString>

namespace coscope::logio {

namespace {
constexpr std::string_view kPrefix = "CoScope: gap in the capture";

// The signed decimal after `key` in `text`.
bool numberAfter(std::string_view text, std::string_view key, int64_t* value) {
    const size_t at = text.find(key);
    if (at == std::string_view::npos) return false;
    size_t i = at + key.size();
    const bool negative = i < text.size() && text[i] == '-';
    if (negative) ++i;
    const size_t start = i;
    uint64_t v = 0;
    for (; i < text.size() && text[i] >= '0' && text[i] <= '9'; ++i) {
        if (i - start >= 19) return false;
        v = v * 10 + uint64_t(text[i] - '0');
    }
    if (i == start) return false;
    *value = negative ? -int64_t(v) : int64_t(v);
    return true;
}
}  // namespace

QByteArray captureGapText(int64_t lostNs, int64_t backNs) {
    return QStringLiteral(
               "CoScope: gap in the capture before this frame: the adapter was lost for %1 s, frames in between are "
               "missing "
               "(lost_ns=%2 back_ns=%3)")
        .arg(double(backNs - lostNs) / 1e9, 0, 'f', 1)
        .arg(lostNs)
        .arg(backNs)
        .toUtf8();
}

bool parseCaptureGapText(std::string_view text, int64_t* lostNs, int64_t* backNs) {
    text = trimmed(text);
    if (text.substr(0, kPrefix.size()) != kPrefix) return false;
    int64_t lost = 0, back = 0;
    if (!numberAfter(text, "(lost_ns=", &lost) || !numberAfter(text, " back_ns=", &back)) return false;
    *lostNs = lost;
    *backNs = back;
    return true;
}

}  // namespace coscope::logio
