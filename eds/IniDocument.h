// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "eds/Diagnostic.h"

#include <QByteArray>
#include <QHash>
#include <QString>

#include <vector>

namespace coscope::eds {

// The INI layer of CiA 306 files (EDS/DCF), lenient:
//  - section names and keys are case-insensitive (the original spelling is kept);
//  - lines starting with ';' or '#' are comments; CR LF and LF both end a line;
//  - a line that is not "[section]" or "key=value" is warned about and skipped;
//  - text after "]" on a section line is ignored (a warning unless it is a comment);
//  - DUPLICATES: the FIRST occurrence wins. A repeated key in a section is warned about with
//    its line and ignored. A repeated section is merged into the first one (its new keys are
//    added, keys already present are warned about and ignored).
struct IniEntry {
    QString key;    // as written
    QString value;  // trimmed
    int line = 0;
};

struct IniSection {
    QString name;  // as written
    int line = 0;
    std::vector<IniEntry> entries;
    QHash<QString, int> byKey;  // lower-case key -> position in entries

    const IniEntry* find(const QString& lowerKey) const {
        auto it = byKey.constFind(lowerKey);
        return it == byKey.constEnd() ? nullptr : &entries[static_cast<size_t>(*it)];
    }
    QString value(const QString& lowerKey) const {
        const IniEntry* e = find(lowerKey);
        return e ? e->value : QString();
    }
};

class IniDocument {
public:
    static IniDocument parse(const QString& text, DiagnosticSink& sink);

    const std::vector<IniSection>& sections() const { return sections_; }
    const IniSection* section(const QString& lowerName) const {
        auto it = byName_.constFind(lowerName);
        return it == byName_.constEnd() ? nullptr : &sections_[static_cast<size_t>(*it)];
    }

private:
    std::vector<IniSection> sections_;
    QHash<QString, int> byName_;  // lower-case name -> position
};

}  // namespace coscope::eds
