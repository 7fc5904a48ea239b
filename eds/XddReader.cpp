// SPDX-License-Identifier: GPL-3.0-or-later
#include "eds/XddReader.h"

#include "core/od/NumberText.h"

#include <QHash>
#include <QXmlStreamReader>

#include <map>

namespace coscope::eds {

using namespace coscope::od;

namespace {

struct Parameter {
    std::optional<DataType> type;
    QString access;
    QString defaultValue, actualValue, lowLimit, highLimit;
};

struct XObject {
    QXmlStreamAttributes attrs;
    int line = 0;
    std::vector<std::pair<QXmlStreamAttributes, int>> subs;
};

// IEC 61131-3 elementary types used by CiA 311 (7.3) and their CiA 301 equivalents.
std::optional<DataType> iecType(QStringView n) {
    static const QHash<QString, DataType> map{
        {QStringLiteral("BOOL"), DataType::Boolean},          {QStringLiteral("SINT"), DataType::Integer8},
        {QStringLiteral("INT"), DataType::Integer16},         {QStringLiteral("DINT"), DataType::Integer32},
        {QStringLiteral("LINT"), DataType::Integer64},        {QStringLiteral("USINT"), DataType::Unsigned8},
        {QStringLiteral("UINT"), DataType::Unsigned16},       {QStringLiteral("UDINT"), DataType::Unsigned32},
        {QStringLiteral("ULINT"), DataType::Unsigned64},      {QStringLiteral("REAL"), DataType::Real32},
        {QStringLiteral("LREAL"), DataType::Real64},          {QStringLiteral("STRING"), DataType::VisibleString},
        {QStringLiteral("WSTRING"), DataType::UnicodeString}, {QStringLiteral("BITSTRING"), DataType::OctetString},
        {QStringLiteral("BYTE"), DataType::Unsigned8},        {QStringLiteral("WORD"), DataType::Unsigned16},
        {QStringLiteral("DWORD"), DataType::Unsigned32},      {QStringLiteral("LWORD"), DataType::Unsigned64},
        {QStringLiteral("CHAR"), DataType::Unsigned8},        {QStringLiteral("WCHAR"), DataType::Unsigned16},
    };
    auto it = map.constFind(n.toString());
    if (it == map.constEnd()) return std::nullopt;
    return *it;
}

// CiA 311 parameter access -> CiA 306 access.
std::optional<Access> parameterAccess(const QString& a) {
    if (a == u"const") return Access::Const;
    if (a == u"read" || a == u"noAccess") return Access::ReadOnly;
    if (a == u"write") return Access::WriteOnly;
    if (a == u"readWrite") return Access::ReadWrite;
    if (a == u"readWriteInput") return Access::ReadWriteWrite;
    if (a == u"readWriteOutput") return Access::ReadWriteRead;
    return std::nullopt;
}

std::optional<std::uint64_t> num(QStringView v, TextStyle style = TextStyle::Eds) {
    if (v.isEmpty()) return std::nullopt;
    // CiA 311 writes index/dataType as bare hex ("1000", "0007").
    const auto n = parseIntegerText(v.toString(), style);
    if (!n || n->negative) return std::nullopt;
    return n->magnitude;
}

std::optional<std::uint64_t> hexNum(QStringView v) {
    bool ok = false;
    const qulonglong x = v.toString().trimmed().toULongLong(&ok, 16);
    if (!ok) return std::nullopt;
    return x;
}

}  // namespace

ReadResult XddReader::read(const QByteArray& bytes, const QString& fileName) {
    ReadResult r;
    r.encoding = QStringLiteral("XML");
    DiagnosticSink sink(fileName);
    QXmlStreamReader xml(bytes);
    QHash<QString, Parameter> params;
    std::vector<XObject> objects;
    ObjectDictionary& od = r.dictionary;
    QString currentParam;
    QString identityField;
    bool inDeviceIdentity = false;

    while (!xml.atEnd()) {
        const auto token = xml.readNext();
        if (token == QXmlStreamReader::EndElement) {
            if (xml.name() == u"parameter") currentParam.clear();
            if (xml.name() == u"DeviceIdentity") inDeviceIdentity = false;
            continue;
        }
        if (token != QXmlStreamReader::StartElement) continue;
        const QString name = xml.name().toString();  // a copy: readElementText() moves the reader on
        const QXmlStreamAttributes a = xml.attributes();
        const int line = static_cast<int>(xml.lineNumber());
        if (name == u"DeviceIdentity") {
            inDeviceIdentity = true;
        } else if (inDeviceIdentity &&
                   (name == u"vendorName" || name == u"vendorID" || name == u"productName" || name == u"productID")) {
            const QString text = xml.readElementText(QXmlStreamReader::IncludeChildElements).trimmed();
            auto number = [&]() -> std::optional<std::uint32_t> {
                // vendorID/productID are hex in CiA 311 (xsd:hexBinary), "0x" tolerated.
                QString t = text;
                if (t.startsWith(QLatin1String("0x"), Qt::CaseInsensitive)) t = t.mid(2);
                const auto v = hexNum(t);
                if (!v || *v > 0xFFFFFFFFu) {
                    if (!text.isEmpty())
                        sink.warning(line, QStringLiteral("%1 '%2' is not a hex number").arg(name, text));
                    return std::nullopt;
                }
                return static_cast<std::uint32_t>(*v);
            };
            if (name == u"vendorName") od.device.vendorName = text;
            else if (name == u"productName") od.device.productName = text;
            else if (name == u"vendorID") od.device.vendorNumber = number();
            else od.device.productNumber = number();
        } else if (name == u"ProfileBody") {
            if (od.fileInfo.fileName.isEmpty()) od.fileInfo.fileName = a.value(QLatin1String("fileName")).toString();
            if (od.fileInfo.createdBy.isEmpty())
                od.fileInfo.createdBy = a.value(QLatin1String("fileCreator")).toString();
            if (od.fileInfo.fileVersion.isEmpty())
                od.fileInfo.fileVersion = a.value(QLatin1String("fileVersion")).toString();
        } else if (name == u"parameter") {
            currentParam = a.value(QLatin1String("uniqueID")).toString();
            Parameter& p = params[currentParam];
            p.access = a.hasAttribute(QLatin1String("access")) ? a.value(QLatin1String("access")).toString()
                                                               : QStringLiteral("read");
        } else if (!currentParam.isEmpty() && (name == u"defaultValue" || name == u"actualValue")) {
            Parameter& p = params[currentParam];
            (name == u"defaultValue" ? p.defaultValue : p.actualValue) = a.value(QLatin1String("value")).toString();
        } else if (!currentParam.isEmpty() && name == u"dataTypeIDRef") {
            params[currentParam].type = DataType::Domain;
        } else if (!currentParam.isEmpty() && iecType(name)) {
            params[currentParam].type = iecType(name);
        } else if (name == u"CANopenObject") {
            objects.push_back({a, line, {}});
        } else if (name == u"CANopenSubObject") {
            if (objects.empty())
                sink.warning(line, QStringLiteral("CANopenSubObject outside a CANopenObject; ignored"));
            else objects.back().subs.push_back({a, line});
        } else if (name == u"supportedBaudRate") {
            const QString v = a.value(QLatin1String("value")).toString();
            bool ok = false;
            const int kbit = v.section(u' ', 0, 0).toInt(&ok);
            if (ok) od.device.baudRates << kbit;
            else sink.warning(line, QStringLiteral("supportedBaudRate '%1' is not 'N Kbps'").arg(v));
        } else if (name == u"CANopenGeneralFeatures") {
            od.device.nrOfRxPdo = a.value(QLatin1String("nrOfRxPDO")).toInt();
            od.device.nrOfTxPdo = a.value(QLatin1String("nrOfTxPDO")).toInt();
            od.device.lssSupported = a.value(QLatin1String("layerSettingServiceSlave")) == u"true";
            if (a.hasAttribute(QLatin1String("granularity")))
                od.device.granularity = a.value(QLatin1String("granularity")).toInt();
            od.device.groupMessaging = a.value(QLatin1String("groupMessaging")) == u"true";
            od.device.dynamicChannelsSupported = a.value(QLatin1String("dynamicChannels")).toInt() > 0;
        } else if (name == u"dummy") {
            const QString e = a.value(QLatin1String("entry")).toString();  // "Dummy0002=1"
            const int i = e.mid(5, 4).toInt();
            if (i >= 1 && i <= 7) od.dummyUsage[static_cast<size_t>(i)] = e.section(u'=', 1) == u"1";
        } else if (name == u"deviceCommissioning") {
            if (const auto id = num(a.value(QLatin1String("nodeID")), TextStyle::Person); id && *id >= 1 && *id <= 127)
                od.commissioning.nodeId = static_cast<std::uint8_t>(*id);
            od.commissioning.nodeName = a.value(QLatin1String("nodeName")).toString();
            od.commissioning.baudRate = a.value(QLatin1String("actualBaudRate")).toString().section(u' ', 0, 0).toInt();
            od.commissioning.networkName = a.value(QLatin1String("networkName")).toString();
            od.commissioning.netNumber = a.value(QLatin1String("networkNumber")).toUInt();
            od.commissioning.canopenManager = a.value(QLatin1String("CANopenManager")) == u"true";
        }
    }
    if (xml.hasError())
        sink.error(static_cast<int>(xml.lineNumber()),
                   QStringLiteral("XML: %1 (what was read before is kept)").arg(xml.errorString()));

    auto fill = [&](SubObject& s, const QXmlStreamAttributes& a, int line) {
        const Parameter p = params.value(a.value(QLatin1String("uniqueIDRef")).toString());
        s.name = a.value(QLatin1String("name")).toString();
        s.line = line;
        if (const auto t = hexNum(a.value(QLatin1String("dataType"))); t && *t <= 0xFFFF)
            s.dataType = static_cast<DataType>(*t);
        else if (p.type) s.dataType = *p.type;
        if (a.hasAttribute(QLatin1String("accessType"))) {
            const auto acc = accessFromString(a.value(QLatin1String("accessType")).toString());
            if (acc) s.access = *acc;
            else
                sink.warning(line, QStringLiteral("accessType '%1' is not ro, wo, rw, rwr, rww or const")
                                       .arg(a.value(QLatin1String("accessType"))));
        } else if (const auto acc = parameterAccess(p.access)) {
            s.access = *acc;
        }
        const QString pdo = a.value(QLatin1String("PDOmapping")).toString();
        s.pdoMappable = !pdo.isEmpty() && pdo != u"no";
        auto pick = [&](const char* attr, const QString& fallback) {
            return a.hasAttribute(QLatin1String(attr)) ? a.value(QLatin1String(attr)).toString() : fallback;
        };
        s.defaultValue = pick("defaultValue", p.defaultValue);
        s.parameterValue = pick("actualValue", p.actualValue);
        s.lowLimit = pick("lowLimit", p.lowLimit);
        s.highLimit = pick("highLimit", p.highLimit);
        s.denotation = a.value(QLatin1String("denotation")).toString();
        if (!s.defaultValue.isEmpty() && typeClass(s.dataType) != TypeClass::Domain) {
            QString why;
            if (!s.interpret(s.defaultValue, 1, &why))
                sink.warning(line, QStringLiteral("defaultValue of %1: %2; kept as text").arg(s.name, why));
        }
    };

    for (const XObject& xo : objects) {
        Object o;
        const auto index = hexNum(xo.attrs.value(QLatin1String("index")));
        if (!index || *index > 0xFFFF) {
            sink.warning(xo.line, QStringLiteral("CANopenObject index '%1' is not a hex index; skipped")
                                      .arg(xo.attrs.value(QLatin1String("index"))));
            continue;
        }
        o.index = static_cast<std::uint16_t>(*index);
        o.line = xo.line;
        o.name = xo.attrs.value(QLatin1String("name")).toString();
        const auto ot = num(xo.attrs.value(QLatin1String("objectType")), TextStyle::Person).value_or(7);
        o.objectType = (ot == 0 || ot == 2 || ot == 5 || ot == 6 || ot == 7 || ot == 8 || ot == 9)
                           ? static_cast<ObjectType>(ot)
                           : ObjectType::Var;
        if (!o.isComposite()) {
            SubObject s;
            s.index = o.index;
            fill(s, xo.attrs, xo.line);
            o.dataType = s.dataType;
            o.subs.push_back(s);
        } else {
            for (const auto& [sa, sl] : xo.subs) {
                const auto sub = hexNum(sa.value(QLatin1String("subIndex")));
                if (!sub || *sub > 0xFF) {
                    sink.warning(sl, QStringLiteral("subIndex '%1' is not a hex sub-index; skipped")
                                         .arg(sa.value(QLatin1String("subIndex"))));
                    continue;
                }
                SubObject s;
                s.index = o.index;
                s.sub = static_cast<std::uint8_t>(*sub);
                fill(s, sa, sl);
                o.subs.push_back(s);
            }
        }
        if (od.object(o.index))
            sink.warning(xo.line, QStringLiteral("object %1 appears again; the first is kept")
                                      .arg(xo.attrs.value(QLatin1String("index"))));
        else od.insert(std::move(o));
    }
    r.usable = od.objectCount() > 0;
    if (!r.usable) sink.error(0, QStringLiteral("no CANopenObject could be read; not a usable XDD"));
    r.diagnostics = sink.take();
    return r;
}

}  // namespace coscope::eds
