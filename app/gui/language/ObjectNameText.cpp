// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/language/ObjectNameText.h"

#include "app/gui/language/CoreText.h"

#include "dissectors/ObjectNames.h"
#include "dissectors/VendorTable.h"
#include "eds/DictionaryLibrary.h"

#include <algorithm>
#include <utility>
#include <vector>

namespace coscope::gui {

namespace {

struct Ref {
    uint16_t index = 0;
    uint8_t sub = 0;
    QString english;  // the name as the dissector wrote it; empty = the dictionary's displayName()
};

QString replaced(const QString& namesFrom, const std::vector<Ref>& refs, const QString& english) {
    const QString lang = dissect::vendorTextLanguage();
    if (namesFrom.isEmpty() || english.isEmpty() || (lang != u"zh_TW" && lang != u"zh_CN") || refs.empty())
        return english;
    const eds::DictionaryPtr dict = eds::DictionaryLibrary::shared().loadShared(namesFrom);
    if (!dict || dict->bundledName.isEmpty()) return english;
    std::vector<std::pair<QString, QString>> names;  // English -> local
    for (const Ref& r : refs) {
        if (!dict->entry(r.index, r.sub)) continue;
        const QString en = r.english.isEmpty() ? dict->displayName(r.index, r.sub) : r.english;
        const QString local = dissect::localDisplayName(*dict, r.index, r.sub, lang);
        if (!en.isEmpty() && local != en) names.emplace_back(en, local);
    }
    // Longest first: "Modes of operation display" before "Modes of operation".
    std::sort(names.begin(), names.end(), [](const auto& a, const auto& b) { return a.first.size() > b.first.size(); });
    QString out = english;
    for (const auto& [en, local] : names) out.replace(en, local);
    return out;
}

}  // namespace

QString localObjectNames(const dissect::Dissection& d, const QString& english) {
    if (d.namesFrom.isEmpty()) return english;
    std::vector<Ref> refs;
    const dissect::FlatField* index = d.find("sdo.index");
    const dissect::FlatField* sub = d.find("sdo.sub");
    const auto number = [](const dissect::FlatField* f) {
        return f->kind == dissect::FlatField::Kind::UInt ? static_cast<int64_t>(f->u) : f->i;
    };
    if (index && sub) refs.push_back({static_cast<uint16_t>(number(index)), static_cast<uint8_t>(number(sub)), {}});
    if (d.hasTransfer) refs.push_back({d.transfer.index, d.transfer.sub, d.transfer.name});
    for (int i = 0; i < d.signalCount; ++i) {
        const dissect::PdoSignal& s = d.pdoSignals[static_cast<size_t>(i)];
        if (!s.raw) refs.push_back({s.index, s.sub, s.name});
    }
    return replaced(d.namesFrom, refs, english);
}

QString localObjectName(const dissect::SdoTransferRecord& t) {
    return replaced(t.namesFrom, {{t.index, t.sub, t.name}}, t.name);
}

QString localSignalName(const dissect::SignalInfo& s) {
    if (s.key.raw) return s.name;  // the user named it
    // SignalInfo::dictionary is the node's library name: replaced() loads it and names its
    // objects only when it is the bundled one (a user's file of that name stays as written).
    if (!s.digital) return replaced(s.dictionary, {{s.key.index, s.key.sub, {}}}, s.name);
    const QString word = s.name.section(QStringLiteral(": "), 0, 0), bit = s.name.section(QStringLiteral(": "), 1);
    return replaced(s.dictionary, {{s.key.index, s.key.sub, word}}, word) + QStringLiteral(": ") + coreText(bit);
}

}  // namespace coscope::gui
