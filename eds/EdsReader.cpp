// SPDX-License-Identifier: GPL-3.0-or-later
#include "eds/EdsReader.h"

#include "core/od/NumberText.h"
#include "eds/IniDocument.h"
#include "eds/TextDecoding.h"
#include "eds/XddReader.h"

#include <QFile>

#include <map>
#include <set>

namespace coscope::eds {

using namespace coscope::od;

int ReadResult::warningCount() const {
    int n = 0;
    for (const auto& d : diagnostics) n += d.severity == Diagnostic::Severity::Warning;
    return n;
}

int ReadResult::errorCount() const {
    int n = 0;
    for (const auto& d : diagnostics) n += d.severity == Diagnostic::Severity::Error;
    return n;
}

namespace {

// Drops an inline comment (" # ..." or " ; ...") after a value; *stripped tells whether one was found.
QString stripInlineComment(const QString& v, bool* stripped) {
    qsizetype cut = -1;
    for (qsizetype i = 1; i < v.size(); ++i) {
        if ((v[i] == u'#' || v[i] == u';') && (v[i - 1] == u' ' || v[i - 1] == u'\t')) {
            cut = i;
            break;
        }
    }
    if (stripped) *stripped = cut >= 0;
    return cut >= 0 ? v.left(cut).trimmed() : v;
}

// Section name kinds for objects (CiA 306 4.5, 4.6).
enum class Kind { Object, Sub, Name, Value, Denotation, ObjectLinks, Other };

Kind classify(const QString& lower, std::uint16_t* index, int* sub) {
    if (lower.size() < 4) return Kind::Other;
    bool ok = false;
    const uint idx = lower.left(4).toUInt(&ok, 16);
    if (!ok || lower[0] == u'+' || lower[0] == u'-') return Kind::Other;
    for (int i = 0; i < 4; ++i)
        if (!lower[i].isLetterOrNumber()) return Kind::Other;
    *index = static_cast<std::uint16_t>(idx);
    const QString rest = lower.mid(4);
    if (rest.isEmpty()) return Kind::Object;
    if (rest.startsWith(QLatin1String("sub"))) {
        const QString s = rest.mid(3);
        const uint v = s.toUInt(&ok, 16);
        if (!ok || s.size() > 3 || s.isEmpty() || v > 0xFF || s.startsWith(u'+') || s.startsWith(u'-'))
            return Kind::Other;
        *sub = static_cast<int>(v);
        return Kind::Sub;
    }
    if (rest == u"name") return Kind::Name;
    if (rest == u"value") return Kind::Value;
    if (rest == u"denotation") return Kind::Denotation;
    if (rest == u"objectlinks") return Kind::ObjectLinks;
    return Kind::Other;
}

class Builder {
public:
    Builder(const IniDocument& doc, DiagnosticSink& sink, ObjectDictionary& od) : doc_(doc), sink_(sink), od_(od) {}

    void run() {
        classifySections();
        readFileInfo();
        readDeviceInfo();
        readCommissioning();
        readDummyUsage();
        readDynamicChannels();
        readComments();
        readObjects();
        impliedPdos();
    }

private:
    // ---- value helpers ----
    std::optional<std::uint64_t> number(const IniEntry* e, const QString& section) {
        if (!e || e->value.isEmpty()) return std::nullopt;
        if (auto n = parseIntegerText(e->value, TextStyle::Eds); n && !n->negative) return n->magnitude;
        bool stripped = false;
        const QString v = stripInlineComment(e->value, &stripped);
        if (stripped) {
            if (auto n = parseIntegerText(v, TextStyle::Eds); n && !n->negative) {
                sink_.warning(e->line, QStringLiteral("inline comment after %1 in [%2] ignored").arg(e->key, section));
                return n->magnitude;
            }
        }
        sink_.warning(e->line,
                      QStringLiteral("%1='%2' in [%3] is not a number; ignored").arg(e->key, e->value, section));
        return std::nullopt;
    }
    std::optional<std::uint64_t> number(const IniSection* s, const char* lowerKey) {
        return s ? number(s->find(QString::fromLatin1(lowerKey)), s->name) : std::nullopt;
    }
    bool flag(const IniSection* s, const char* lowerKey) { return number(s, lowerKey).value_or(0) != 0; }

    static void keepExtra(const IniSection& s, ExtraKeys& extra, std::initializer_list<const char*> known) {
        for (const IniEntry& e : s.entries) {
            const QString k = e.key.toLower();
            bool isKnown = false;
            for (const char* kk : known)
                if (k == QLatin1String(kk)) isKnown = true;
            if (!isKnown) extra.append({e.key, e.value});
        }
    }

    // ---- sections ----
    void classifySections() {
        static const char* special[] = {
            "fileinfo",        "deviceinfo",          "dummyusage",          "mandatoryobjects",
            "optionalobjects", "manufacturerobjects", "devicecommissioning", "devicecomissioning",
            "comments",        "dynamicchannels"};
        for (const IniSection& s : doc_.sections()) {
            const QString lower = s.name.toLower();
            std::uint16_t index = 0;
            int sub = 0;
            switch (classify(lower, &index, &sub)) {
            case Kind::Object: objects_[index] = &s; continue;
            case Kind::Sub:
                if (!subs_[index].emplace(sub, &s).second)
                    sink_.warning(s.line,
                                  QStringLiteral("[%1] repeats sub-index %2 of [%3] (first at line %4); ignored")
                                      .arg(s.name)
                                      .arg(sub)
                                      .arg(hex4(index))
                                      .arg(subs_[index][sub]->line));
                continue;
            case Kind::Name: names_[index] = &s; continue;
            case Kind::Value: values_[index] = &s; continue;
            case Kind::Denotation: denotations_[index] = &s; continue;
            case Kind::ObjectLinks: links_[index] = &s; continue;
            case Kind::Other: break;
            }
            bool isSpecial = false;
            for (const char* sp : special)
                if (lower == QLatin1String(sp)) isSpecial = true;
            if (!isSpecial) {
                ExtraSection x;
                x.name = s.name;
                for (const IniEntry& e : s.entries) x.keys.append({e.key, e.value});
                od_.extraSections.push_back(std::move(x));
            }
        }
    }

    void readFileInfo() {
        const IniSection* s = doc_.section(QStringLiteral("fileinfo"));
        if (!s) return;
        FileInfo& f = od_.fileInfo;
        f.fileName = s->value(QStringLiteral("filename"));
        f.fileVersion = s->value(QStringLiteral("fileversion"));
        f.fileRevision = s->value(QStringLiteral("filerevision"));
        f.edsVersion = s->value(QStringLiteral("edsversion"));
        f.description = s->value(QStringLiteral("description"));
        f.creationTime = s->value(QStringLiteral("creationtime"));
        f.creationDate = s->value(QStringLiteral("creationdate"));
        f.createdBy = s->value(QStringLiteral("createdby"));
        f.modificationTime = s->value(QStringLiteral("modificationtime"));
        f.modificationDate = s->value(QStringLiteral("modificationdate"));
        f.modifiedBy = s->value(QStringLiteral("modifiedby"));
        keepExtra(*s, f.extraKeys,
                  {"filename", "fileversion", "filerevision", "edsversion", "description", "creationtime",
                   "creationdate", "createdby", "modificationtime", "modificationdate", "modifiedby"});
    }

    void readDeviceInfo() {
        const IniSection* s = doc_.section(QStringLiteral("deviceinfo"));
        if (!s) {
            sink_.warning(0, QStringLiteral("no [DeviceInfo] section"));
            return;
        }
        DeviceInfo& d = od_.device;
        auto u32 = [&](const char* k) -> std::optional<std::uint32_t> {
            const auto v = number(s, k);
            if (v && *v > 0xFFFFFFFFu) {
                sink_.warning(s->find(QString::fromLatin1(k))->line,
                              QStringLiteral("%1 does not fit 32 bits; ignored").arg(QString::fromLatin1(k)));
                return std::nullopt;
            }
            return v ? std::optional<std::uint32_t>(static_cast<std::uint32_t>(*v)) : std::nullopt;
        };
        d.vendorName = s->value(QStringLiteral("vendorname"));
        d.vendorNumber = u32("vendornumber");
        d.productName = s->value(QStringLiteral("productname"));
        d.productNumber = u32("productnumber");
        d.revisionNumber = u32("revisionnumber");
        d.orderCode = s->value(QStringLiteral("ordercode"));
        for (int rate : {10, 20, 50, 125, 250, 500, 800, 1000}) {
            const QByteArray k = "baudrate_" + QByteArray::number(rate);
            if (flag(s, k.constData())) d.baudRates << rate;
        }
        d.simpleBootUpMaster = flag(s, "simplebootupmaster");
        d.simpleBootUpSlave = flag(s, "simplebootupslave");
        d.granularity = static_cast<int>(number(s, "granularity").value_or(8));
        d.dynamicChannelsSupported = flag(s, "dynamicchannelssupported");
        d.groupMessaging = static_cast<int>(number(s, "groupmessaging").value_or(0));
        d.nrOfRxPdo = static_cast<int>(std::min<std::uint64_t>(number(s, "nrofrxpdo").value_or(0), 512));
        d.nrOfTxPdo = static_cast<int>(std::min<std::uint64_t>(number(s, "nroftxpdo").value_or(0), 512));
        d.lssSupported = flag(s, "lss_supported");
        d.compactPdo = static_cast<int>(number(s, "compactpdo").value_or(0) & 0xFF);
        keepExtra(*s, d.extraKeys, {"vendorname",        "vendornumber",   "productname",
                                    "productnumber",     "revisionnumber", "ordercode",
                                    "baudrate_10",       "baudrate_20",    "baudrate_50",
                                    "baudrate_125",      "baudrate_250",   "baudrate_500",
                                    "baudrate_800",      "baudrate_1000",  "simplebootupmaster",
                                    "simplebootupslave", "granularity",    "dynamicchannelssupported",
                                    "groupmessaging",    "nrofrxpdo",      "nroftxpdo",
                                    "lss_supported",     "compactpdo"});
    }

    void readCommissioning() {
        const IniSection* good = doc_.section(QStringLiteral("devicecommissioning"));
        const IniSection* old = doc_.section(QStringLiteral("devicecomissioning"));
        const IniSection* s = good ? good : old;
        if (good && old)
            sink_.warning(
                old->line,
                QStringLiteral(
                    "both [DeviceCommissioning] and [DeviceComissioning]; the first spelling at line %1 is used")
                    .arg(good->line));
        if (!s) return;
        Commissioning& c = od_.commissioning;
        if (const auto id = number(s, "nodeid")) {
            if (*id < 1 || *id > 127)
                sink_.warning(s->find(QStringLiteral("nodeid"))->line,
                              QStringLiteral("NodeID %1 is outside 1..127; ignored").arg(*id));
            else c.nodeId = static_cast<std::uint8_t>(*id);
        }
        c.nodeName = s->value(QStringLiteral("nodename"));
        c.baudRate = static_cast<int>(std::min<std::uint64_t>(number(s, "baudrate").value_or(0), 1000000));
        c.netNumber = static_cast<std::uint32_t>(number(s, "netnumber").value_or(0));
        c.networkName = s->value(QStringLiteral("networkname"));
        c.canopenManager = flag(s, "canopenmanager");
        if (const auto v = number(s, "lss_serialnumber")) c.lssSerialNumber = static_cast<std::uint32_t>(*v);
        keepExtra(*s, c.extraKeys,
                  {"nodeid", "nodename", "baudrate", "netnumber", "networkname", "canopenmanager", "lss_serialnumber"});
    }

    void readDummyUsage() {
        const IniSection* s = doc_.section(QStringLiteral("dummyusage"));
        if (!s) return;
        for (int i = 1; i <= 7; ++i) {
            const QByteArray k = "dummy000" + QByteArray::number(i);
            od_.dummyUsage[static_cast<size_t>(i)] = flag(s, k.constData());
        }
    }

    void readDynamicChannels() {
        const IniSection* s = doc_.section(QStringLiteral("dynamicchannels"));
        if (!s) return;
        const int n = static_cast<int>(std::min<std::uint64_t>(number(s, "nrofseg").value_or(0), 64));
        for (int i = 1; i <= n; ++i) {
            DynamicChannel ch;
            const QString si = QString::number(i);
            ch.type = static_cast<DataType>(number(s->find(QStringLiteral("type") + si), s->name).value_or(0) & 0xFFFF);
            ch.dir = s->value(QStringLiteral("dir") + si).toLower();
            const IniEntry* range = s->find(QStringLiteral("range") + si);
            if (range) {
                const auto a = parseIntegerText(range->value.section(u'-', 0, 0), TextStyle::Eds);
                const auto b = parseIntegerText(range->value.section(u'-', 1, 1), TextStyle::Eds);
                if (a && b && a->magnitude <= 0xFFFF && b->magnitude <= 0xFFFF) {
                    ch.rangeFirst = static_cast<std::uint16_t>(a->magnitude);
                    ch.rangeLast = static_cast<std::uint16_t>(b->magnitude);
                } else {
                    sink_.warning(range->line, QStringLiteral("Range%1='%2' is not FIRST-LAST").arg(si, range->value));
                }
            }
            ch.ppOffset =
                static_cast<std::uint32_t>(number(s->find(QStringLiteral("ppoffset") + si), s->name).value_or(0));
            od_.dynamicChannels.push_back(ch);
        }
    }

    void readComments() {
        const IniSection* s = doc_.section(QStringLiteral("comments"));
        if (!s) return;
        const int n = static_cast<int>(std::min<std::uint64_t>(number(s, "lines").value_or(0), 10000));
        for (int i = 1; i <= n; ++i) od_.comments << s->value(QStringLiteral("line") + QString::number(i));
    }

    // ---- objects ----
    std::set<std::uint16_t> objectSet() {
        std::map<std::uint16_t, int> listed;  // index -> line of its list entry
        bool anyList = false;
        for (const char* listName : {"mandatoryobjects", "optionalobjects", "manufacturerobjects"}) {
            const IniSection* s = doc_.section(QString::fromLatin1(listName));
            if (!s) continue;
            anyList = true;
            const auto count = number(s, "supportedobjects");
            int found = 0;
            for (const IniEntry& e : s->entries) {
                bool isIndexKey = false;
                e.key.toUInt(&isIndexKey, 10);
                if (!isIndexKey) continue;
                const auto idx = number(&e, s->name);
                if (!idx) continue;
                if (*idx > 0xFFFF) {
                    sink_.warning(e.line, QStringLiteral("object index %1 is above 0xFFFF; ignored").arg(e.value));
                    continue;
                }
                ++found;
                listed.emplace(static_cast<std::uint16_t>(*idx), e.line);
            }
            if (count && static_cast<int>(*count) != found)
                sink_.warning(s->find(QStringLiteral("supportedobjects"))->line,
                              QStringLiteral("[%1] SupportedObjects=%2 but %3 entries are listed")
                                  .arg(s->name)
                                  .arg(*count)
                                  .arg(found));
        }
        std::set<std::uint16_t> result;
        if (!anyList) {
            if (!objects_.empty())
                sink_.warning(0, QStringLiteral("no object lists ([MandatoryObjects], [OptionalObjects], "
                                                "[ManufacturerObjects]); every [XXXX] section is read as an object"));
            for (const auto& [i, s] : objects_) result.insert(i);
            return result;
        }
        for (const auto& [i, line] : listed) {
            if (objects_.count(i)) result.insert(i);
            else
                sink_.warning(
                    line,
                    QStringLiteral("object 0x%1 is listed but has no section [%2]; skipped").arg(hex4(i), hex4(i)));
        }
        for (const auto& [i, s] : objects_) {
            if (listed.count(i)) continue;
            // Data type definitions (index < 0x1000, e.g. dummies for [DummyUsage]) are not listed.
            if (i >= 0x1000)
                sink_.warning(s->line,
                              QStringLiteral("section [%1] is not in any object list; read anyway").arg(s->name));
            result.insert(i);
        }
        return result;
    }

    static QString hex4(std::uint16_t i) {
        return QString::number(i, 16).toUpper().rightJustified(4, QLatin1Char('0'));
    }

    // Validates value text of a key against the entry's type; drops an inline comment if that helps.
    void checkValue(SubObject& s, QString SubObject::*field, const IniEntry* e, const QString& section) {
        if (!e) return;
        QString& text = s.*field;
        text = e->value;
        if (text.isEmpty()) return;
        if (typeClass(s.dataType) == TypeClass::Domain) return;  // DOMAIN/custom: any text (file names, hex)
        QString why;
        if (s.interpret(text, 1, &why)) return;
        bool stripped = false;
        const QString shorter = stripInlineComment(text, &stripped);
        if (stripped && s.interpret(shorter, 1)) {
            sink_.warning(e->line, QStringLiteral("inline comment after %1 in [%2] ignored").arg(e->key, section));
            text = shorter;
            return;
        }
        sink_.warning(e->line, QStringLiteral("%1 in [%2]: %3; kept as text").arg(e->key, section, why));
    }

    void fillEntry(SubObject& s, const IniSection& sec, bool requireType) {
        s.name = sec.value(QStringLiteral("parametername"));
        if (s.name.isEmpty()) {
            sink_.warning(sec.line, QStringLiteral("[%1] has no ParameterName").arg(sec.name));
            s.name = sec.name;
        }
        if (const auto t = number(&sec, "datatype")) {
            if (*t > 0xFFFF)
                sink_.warning(sec.find(QStringLiteral("datatype"))->line,
                              QStringLiteral("DataType %1 is not a data type index").arg(*t));
            else s.dataType = static_cast<DataType>(*t);
            if (!isKnownBasicType(s.dataType) && !objects_.count(static_cast<std::uint16_t>(s.dataType)) && *t < 0x20)
                sink_.warning(sec.find(QStringLiteral("datatype"))->line,
                              QStringLiteral("DataType 0x%1 is not defined; handled as DOMAIN")
                                  .arg(hex4(static_cast<std::uint16_t>(*t))));
        } else if (requireType) {
            sink_.warning(sec.line, QStringLiteral("[%1] has no DataType; UNSIGNED8 assumed").arg(sec.name));
        }
        if (const IniEntry* a = sec.find(QStringLiteral("accesstype"))) {
            bool stripped = false;
            auto acc = accessFromString(a->value);
            if (!acc) {
                acc = accessFromString(stripInlineComment(a->value, &stripped));
                if (acc)
                    sink_.warning(a->line,
                                  QStringLiteral("inline comment after AccessType in [%1] ignored").arg(sec.name));
            }
            if (acc) s.access = *acc;
            else
                sink_.warning(a->line,
                              QStringLiteral("AccessType='%1' in [%2] is not ro, wo, rw, rwr, rww or const; ro assumed")
                                  .arg(a->value, sec.name));
        } else if (requireType) {
            sink_.warning(sec.line, QStringLiteral("[%1] has no AccessType; ro assumed").arg(sec.name));
        }
        s.pdoMappable = number(&sec, "pdomapping").value_or(0) != 0;
        s.objFlags = static_cast<std::uint32_t>(number(&sec, "objflags").value_or(0));
        checkValue(s, &SubObject::defaultValue, sec.find(QStringLiteral("defaultvalue")), sec.name);
        checkValue(s, &SubObject::parameterValue, sec.find(QStringLiteral("parametervalue")), sec.name);
        checkValue(s, &SubObject::lowLimit, sec.find(QStringLiteral("lowlimit")), sec.name);
        checkValue(s, &SubObject::highLimit, sec.find(QStringLiteral("highlimit")), sec.name);
        s.denotation = sec.value(QStringLiteral("denotation"));
        s.line = sec.line;
        keepExtra(sec, s.extraKeys,
                  {"parametername", "objecttype", "datatype", "accesstype", "pdomapping", "objflags", "defaultvalue",
                   "parametervalue", "lowlimit", "highlimit", "denotation", "subnumber", "compactsubobj"});
    }

    std::optional<std::uint64_t> number(const IniSection* s, const QString& lowerKey) {
        return number(s->find(lowerKey), s->name);
    }

    void readObjects() {
        for (std::uint16_t index : objectSet()) {
            const IniSection& sec = *objects_[index];
            Object o;
            o.index = index;
            o.line = sec.line;
            o.name = sec.value(QStringLiteral("parametername"));
            if (o.name.isEmpty()) {
                sink_.warning(sec.line, QStringLiteral("[%1] has no ParameterName").arg(sec.name));
                o.name = QStringLiteral("Object %1").arg(hex4(index));
            }
            const bool hasSubs = subs_.count(index) != 0;
            const auto compact = number(&sec, "compactsubobj");
            auto ot = number(&sec, "objecttype");
            ObjectType type = ObjectType::Var;
            if (ot) {
                switch (*ot) {
                case 0x0:
                case 0x2:
                case 0x5:
                case 0x6:
                case 0x7:
                case 0x8:
                case 0x9: type = static_cast<ObjectType>(*ot); break;
                default:
                    sink_.warning(
                        sec.find(QStringLiteral("objecttype"))->line,
                        QStringLiteral("ObjectType=%1 in [%2] is not a CiA 301 object code").arg(*ot).arg(sec.name));
                    type = hasSubs ? ObjectType::Record : ObjectType::Var;
                }
            } else if (hasSubs || (compact && *compact)) {
                type = ObjectType::Record;
                sink_.warning(sec.line,
                              QStringLiteral("[%1] has sub-objects but no ObjectType; RECORD assumed").arg(sec.name));
            }
            o.objectType = type;
            if (const auto t = number(&sec, "datatype"); t && *t <= 0xFFFF) o.dataType = static_cast<DataType>(*t);
            else if (type == ObjectType::Domain) o.dataType = DataType::Domain;
            o.objFlags = static_cast<std::uint32_t>(number(&sec, "objflags").value_or(0));
            keepExtra(
                sec, o.extraKeys,
                {"parametername", "objecttype", "datatype", "accesstype", "pdomapping", "objflags", "defaultvalue",
                 "parametervalue", "lowlimit", "highlimit", "denotation", "subnumber", "compactsubobj"});
            const bool composite =
                type == ObjectType::Array || type == ObjectType::Record || type == ObjectType::DefStruct;
            if (!composite) {
                SubObject s;
                s.index = index;
                s.sub = 0;
                if (type == ObjectType::Domain && !sec.find(QStringLiteral("datatype"))) s.dataType = DataType::Domain;
                fillEntry(s, sec, type == ObjectType::Var);
                if (type == ObjectType::Domain && !sec.find(QStringLiteral("accesstype"))) s.access = Access::ReadWrite;
                o.subs.push_back(std::move(s));
                o.extraKeys.clear();  // kept on the entry
                if (hasSubs)
                    sink_.warning(sec.line, QStringLiteral("[%1] is a %2 but has sub-object sections; they are ignored")
                                                .arg(sec.name, objectTypeName(type)));
            } else if (compact && *compact > 0) {
                readCompact(o, sec, static_cast<int>(std::min<std::uint64_t>(*compact, 254)));
            } else {
                for (const auto& [subIndex, subSec] : subs_[index]) {
                    SubObject s;
                    s.index = index;
                    s.sub = static_cast<std::uint8_t>(subIndex);
                    fillEntry(s, *subSec, true);
                    o.subs.push_back(std::move(s));
                }
                if (o.subs.empty())
                    sink_.warning(
                        sec.line,
                        QStringLiteral("[%1] is a %2 without sub-objects").arg(sec.name, objectTypeName(type)));
                if (const auto n = number(&sec, "subnumber"); n && static_cast<size_t>(*n) != o.subs.size())
                    sink_.warning(sec.find(QStringLiteral("subnumber"))->line,
                                  QStringLiteral("[%1] SubNumber=%2 but %3 sub-object sections were found")
                                      .arg(sec.name)
                                      .arg(*n)
                                      .arg(o.subs.size()));
            }
            if (const IniSection* l = links_.count(index) ? links_[index] : nullptr) {
                for (const IniEntry& e : l->entries) {
                    bool isIndexKey = false;
                    e.key.toUInt(&isIndexKey, 10);
                    if (!isIndexKey) continue;
                    if (const auto v = number(&e, l->name); v && *v <= 0xFFFF)
                        o.objectLinks.push_back(static_cast<std::uint16_t>(*v));
                }
            }
            od_.insert(std::move(o));
        }
        for (const auto& [index, m] : subs_) {
            if (od_.object(index) || m.empty()) continue;
            const IniSection* first = m.begin()->second;
            sink_.warning(first->line,
                          QStringLiteral("[%1] has no object section [%2]; ignored").arg(first->name, hex4(index)));
        }
    }

    // CompactSubObj (CiA 306 4.5.2.3): sub 0 holds the count; subs 1..N take type, access,
    // default and limits from the object's section; names from [XXXXName], DCF values from
    // [XXXXValue] and denotations from [XXXXDenotation]. Without a name, sub N is called
    // "<object name> N".
    void readCompact(Object& o, const IniSection& sec, int n) {
        SubObject s0;
        s0.index = o.index;
        s0.sub = 0;
        s0.name = QStringLiteral("Highest sub-index supported");
        s0.dataType = DataType::Unsigned8;
        s0.access = Access::ReadOnly;
        s0.defaultValue = QString::number(n);
        s0.line = sec.line;
        o.subs.push_back(s0);
        o.compactSubObj = n;
        SubObject proto;
        proto.index = o.index;
        fillEntry(proto, sec, true);
        proto.extraKeys.clear();
        const IniSection* names = names_.count(o.index) ? names_[o.index] : nullptr;
        const IniSection* values = values_.count(o.index) ? values_[o.index] : nullptr;
        const IniSection* denots = denotations_.count(o.index) ? denotations_[o.index] : nullptr;
        for (int i = 1; i <= n; ++i) {
            SubObject s = proto;
            s.sub = static_cast<std::uint8_t>(i);
            const QString key = QString::number(i);
            const QString nm = names ? names->value(key) : QString();
            s.name = nm.isEmpty() ? QStringLiteral("%1 %2").arg(o.name).arg(i) : nm;
            s.denotation = denots ? denots->value(key) : QString();
            if (values) {
                if (const IniEntry* e = values->find(key)) {
                    checkValue(s, &SubObject::parameterValue, e, values->name);
                }
            }
            o.subs.push_back(std::move(s));
        }
    }

    // CompactPDO (CiA 306 4.6.2): PDO objects up to NrOfRXPDO/NrOfTXPDO that the file omits are
    // implied with their CiA 301 default layout. Bits: 0 COB-ID, 1 transmission type,
    // 2 inhibit time, 4 event timer, 5 SYNC start value (7.5.2.35/36).
    void impliedPdos() {
        const int mask = od_.device.compactPdo;
        if (!mask) return;
        auto make = [&](std::uint16_t comm, std::uint16_t map, int n, bool tx) {
            if (!od_.object(comm)) {
                Object o;
                o.index = comm;
                o.objectType = ObjectType::Record;
                o.dataType = DataType::PdoCommunicationParameter;
                o.name = QStringLiteral("%1PDO %2 communication parameter").arg(tx ? "T" : "R").arg(n + 1);
                auto add = [&](std::uint8_t sub, const QString& name, DataType t, Access a, const QString& def) {
                    SubObject s;
                    s.index = comm;
                    s.sub = sub;
                    s.name = name;
                    s.dataType = t;
                    s.access = a;
                    s.defaultValue = def;
                    o.subs.push_back(s);
                };
                int highest = 0;
                const QString cob = n < 4 ? QStringLiteral("$NODEID+0x%1").arg((tx ? 0x180 : 0x200) + 0x100 * n, 0, 16)
                                          : QStringLiteral("0x80000000");
                if (mask & 0x01)
                    add(1, QStringLiteral("COB-ID"), DataType::Unsigned32, Access::ReadWrite, cob), highest = 1;
                if (mask & 0x02)
                    add(2, QStringLiteral("Transmission type"), DataType::Unsigned8, Access::ReadWrite,
                        QStringLiteral("0xFF")),
                        highest = 2;
                if (mask & 0x04)
                    add(3, QStringLiteral("Inhibit time"), DataType::Unsigned16, Access::ReadWrite,
                        QStringLiteral("0")),
                        highest = 3;
                if (mask & 0x10)
                    add(5, QStringLiteral("Event timer"), DataType::Unsigned16, Access::ReadWrite, QStringLiteral("0")),
                        highest = 5;
                if (tx && (mask & 0x20))
                    add(6, QStringLiteral("SYNC start value"), DataType::Unsigned8, Access::ReadWrite,
                        QStringLiteral("0")),
                        highest = 6;
                add(0, QStringLiteral("Highest sub-index supported"), DataType::Unsigned8, Access::Const,
                    QString::number(highest));
                od_.insert(std::move(o));
            }
            if (!od_.object(map)) {
                Object o;
                o.index = map;
                o.objectType = ObjectType::Record;
                o.dataType = DataType::PdoMapping;
                o.name = QStringLiteral("%1PDO %2 mapping parameter").arg(tx ? "T" : "R").arg(n + 1);
                SubObject s0;
                s0.name = QStringLiteral("Number of mapped objects");
                s0.dataType = DataType::Unsigned8;
                s0.access = Access::ReadWrite;
                s0.defaultValue = QStringLiteral("0");
                o.subs.push_back(s0);
                for (int i = 1; i <= 8; ++i) {
                    SubObject s;
                    s.sub = static_cast<std::uint8_t>(i);
                    s.name = QStringLiteral("Mapped object %1").arg(i);
                    s.dataType = DataType::Unsigned32;
                    s.access = Access::ReadWrite;
                    s.defaultValue = QStringLiteral("0");
                    o.subs.push_back(s);
                }
                od_.insert(std::move(o));
            }
        };
        for (int i = 0; i < od_.device.nrOfRxPdo; ++i)
            make(static_cast<std::uint16_t>(0x1400 + i), static_cast<std::uint16_t>(0x1600 + i), i, false);
        for (int i = 0; i < od_.device.nrOfTxPdo; ++i)
            make(static_cast<std::uint16_t>(0x1800 + i), static_cast<std::uint16_t>(0x1A00 + i), i, true);
    }

    const IniDocument& doc_;
    DiagnosticSink& sink_;
    ObjectDictionary& od_;
    std::map<std::uint16_t, const IniSection*> objects_;
    std::map<std::uint16_t, std::map<int, const IniSection*>> subs_;
    std::map<std::uint16_t, const IniSection*> names_, values_, denotations_, links_;
};

}  // namespace

ReadResult EdsReader::read(const QByteArray& bytes, const QString& fileName) {
    ReadResult r;
    DiagnosticSink sink(fileName);
    const QString text = decodeDictionaryText(bytes, &r.encoding);
    const IniDocument doc = IniDocument::parse(text, sink);
    Builder(doc, sink, r.dictionary).run();
    r.usable = r.dictionary.objectCount() > 0;
    if (!r.usable)
        sink.error(0, bytes.isEmpty() ? QStringLiteral("file is empty")
                                      : QStringLiteral("no object could be read; not a usable EDS/DCF"));
    r.diagnostics = sink.take();
    return r;
}

ReadResult EdsReader::readFile(const QString& path) {
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly)) {
        ReadResult r;
        r.diagnostics.push_back(
            {path, 0, Diagnostic::Severity::Error, QStringLiteral("cannot open: %1").arg(f.errorString())});
        return r;
    }
    return read(f.readAll(), path);
}

ReadResult readDictionary(const QByteArray& bytes, const QString& fileName) {
    qsizetype i = bytes.startsWith("\xEF\xBB\xBF") ? 3 : 0;
    while (i < bytes.size() && (bytes[i] == ' ' || bytes[i] == '\t' || bytes[i] == '\r' || bytes[i] == '\n')) ++i;
    if (i < bytes.size() && bytes[i] == '<')
        return XddReader::read(bytes.mid(i), fileName);  // an XML declaration must come first
    return EdsReader::read(bytes, fileName);
}

ReadResult readDictionaryFile(const QString& path) {
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly)) {
        ReadResult r;
        r.diagnostics.push_back(
            {path, 0, Diagnostic::Severity::Error, QStringLiteral("cannot open: %1").arg(f.errorString())});
        return r;
    }
    return readDictionary(f.readAll(), path);
}

}  // namespace coscope::eds
