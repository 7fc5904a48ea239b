// SPDX-License-Identifier: GPL-3.0-or-later
#include "eds/DcfWriter.h"

#include <QFile>
#include <QSaveFile>

namespace coscope::eds {

using namespace coscope::od;

namespace {

class Out {
public:
    void section(const QString& name) {
        if (!text_.isEmpty()) text_ += QLatin1String("\r\n");
        text_ += u'[' + name + QLatin1String("]\r\n");
    }
    void key(const QString& k, const QString& v) { text_ += k + u'=' + v + QLatin1String("\r\n"); }
    void keyIf(const QString& k, const QString& v) {
        if (!v.isEmpty()) key(k, v);
    }
    void extra(const ExtraKeys& keys) {
        for (const auto& [k, v] : keys) key(k, v);
    }
    QByteArray bytes() const { return text_.toUtf8(); }

private:
    QString text_;
};

QString hex(std::uint64_t v, int width) {
    return QStringLiteral("0x") + QString::number(v, 16).toUpper().rightJustified(width, QLatin1Char('0'));
}
QString hex4(std::uint16_t v) { return QString::number(v, 16).toUpper().rightJustified(4, QLatin1Char('0')); }

void entryKeys(Out& o, const SubObject& s, ObjectType type = ObjectType::Var) {
    o.key(QStringLiteral("ParameterName"), s.name);
    o.key(QStringLiteral("ObjectType"), hex(static_cast<int>(type), 1));
    o.key(QStringLiteral("DataType"), hex(static_cast<std::uint16_t>(s.dataType), 4));
    o.key(QStringLiteral("AccessType"), accessName(s.access));
    o.keyIf(QStringLiteral("DefaultValue"), s.defaultValue);
    o.key(QStringLiteral("PDOMapping"), s.pdoMappable ? QStringLiteral("1") : QStringLiteral("0"));
    o.keyIf(QStringLiteral("LowLimit"), s.lowLimit);
    o.keyIf(QStringLiteral("HighLimit"), s.highLimit);
    if (s.objFlags) o.key(QStringLiteral("ObjFlags"), hex(s.objFlags, 1));
    o.keyIf(QStringLiteral("ParameterValue"), s.parameterValue);
    o.keyIf(QStringLiteral("Denotation"), s.denotation);
    o.extra(s.extraKeys);
}

}  // namespace

QByteArray DcfWriter::write(const ObjectDictionary& od) { return write(od, 0, 0); }

QByteArray DcfWriter::write(const ObjectDictionary& od, std::uint8_t nodeId, int bitrateKbit) {
    Out o;
    const FileInfo& f = od.fileInfo;
    o.section(QStringLiteral("FileInfo"));
    o.keyIf(QStringLiteral("FileName"), f.fileName);
    o.keyIf(QStringLiteral("FileVersion"), f.fileVersion);
    o.keyIf(QStringLiteral("FileRevision"), f.fileRevision);
    o.key(QStringLiteral("EDSVersion"), f.edsVersion.isEmpty() ? QStringLiteral("4.0") : f.edsVersion);
    o.keyIf(QStringLiteral("Description"), f.description);
    o.keyIf(QStringLiteral("CreationTime"), f.creationTime);
    o.keyIf(QStringLiteral("CreationDate"), f.creationDate);
    o.keyIf(QStringLiteral("CreatedBy"), f.createdBy);
    o.keyIf(QStringLiteral("ModificationTime"), f.modificationTime);
    o.keyIf(QStringLiteral("ModificationDate"), f.modificationDate);
    o.keyIf(QStringLiteral("ModifiedBy"), f.modifiedBy);
    o.extra(f.extraKeys);

    const DeviceInfo& d = od.device;
    o.section(QStringLiteral("DeviceInfo"));
    o.keyIf(QStringLiteral("VendorName"), d.vendorName);
    if (d.vendorNumber) o.key(QStringLiteral("VendorNumber"), hex(*d.vendorNumber, 8));
    o.keyIf(QStringLiteral("ProductName"), d.productName);
    if (d.productNumber) o.key(QStringLiteral("ProductNumber"), hex(*d.productNumber, 8));
    if (d.revisionNumber) o.key(QStringLiteral("RevisionNumber"), hex(*d.revisionNumber, 8));
    o.keyIf(QStringLiteral("OrderCode"), d.orderCode);
    for (int rate : {10, 20, 50, 125, 250, 500, 800, 1000})
        o.key(QStringLiteral("BaudRate_%1").arg(rate),
              d.baudRates.contains(rate) ? QStringLiteral("1") : QStringLiteral("0"));
    o.key(QStringLiteral("SimpleBootUpMaster"), QString::number(d.simpleBootUpMaster));
    o.key(QStringLiteral("SimpleBootUpSlave"), QString::number(d.simpleBootUpSlave));
    o.key(QStringLiteral("Granularity"), QString::number(d.granularity));
    o.key(QStringLiteral("DynamicChannelsSupported"), QString::number(d.dynamicChannelsSupported));
    o.key(QStringLiteral("GroupMessaging"), QString::number(d.groupMessaging));
    o.key(QStringLiteral("NrOfRXPDO"), QString::number(d.nrOfRxPdo));
    o.key(QStringLiteral("NrOfTXPDO"), QString::number(d.nrOfTxPdo));
    o.key(QStringLiteral("LSS_Supported"), QString::number(d.lssSupported));
    // Implied PDO objects are written out, so CompactPDO is not repeated.
    o.extra(d.extraKeys);

    const Commissioning& c = od.commissioning;
    o.section(QStringLiteral("DeviceCommissioning"));
    const int node = nodeId ? nodeId : c.nodeId;
    if (node) o.key(QStringLiteral("NodeID"), QString::number(node));
    o.keyIf(QStringLiteral("NodeName"), c.nodeName);
    const int baud = bitrateKbit ? bitrateKbit : c.baudRate;
    if (baud) o.key(QStringLiteral("Baudrate"), QString::number(baud));
    o.key(QStringLiteral("NetNumber"), QString::number(c.netNumber));
    o.keyIf(QStringLiteral("NetworkName"), c.networkName);
    o.key(QStringLiteral("CANopenManager"), QString::number(c.canopenManager));
    if (c.lssSerialNumber) o.key(QStringLiteral("LSS_SerialNumber"), hex(*c.lssSerialNumber, 8));
    o.extra(c.extraKeys);

    o.section(QStringLiteral("DummyUsage"));
    for (int i = 1; i <= 7; ++i)
        o.key(QStringLiteral("Dummy000%1").arg(i),
              od.dummyUsage[static_cast<size_t>(i)] ? QStringLiteral("1") : QStringLiteral("0"));

    if (!od.dynamicChannels.empty()) {
        o.section(QStringLiteral("DynamicChannels"));
        o.key(QStringLiteral("NrOfSeg"), QString::number(od.dynamicChannels.size()));
        int i = 1;
        for (const DynamicChannel& ch : od.dynamicChannels) {
            o.key(QStringLiteral("Type%1").arg(i), hex(static_cast<std::uint16_t>(ch.type), 4));
            o.key(QStringLiteral("Dir%1").arg(i), ch.dir);
            o.key(QStringLiteral("Range%1").arg(i), hex(ch.rangeFirst, 4) + u'-' + hex(ch.rangeLast, 4));
            o.key(QStringLiteral("PPOffset%1").arg(i), QString::number(ch.ppOffset));
            ++i;
        }
    }
    if (!od.comments.isEmpty()) {
        o.section(QStringLiteral("Comments"));
        o.key(QStringLiteral("Lines"), QString::number(od.comments.size()));
        for (int i = 0; i < od.comments.size(); ++i) o.key(QStringLiteral("Line%1").arg(i + 1), od.comments[i]);
    }

    // Object lists (CiA 306 4.6.3): mandatory 1000h, 1001h, 1018h; optional: other
    // communication/profile objects; manufacturer: 2000h..5FFFh. Data types < 1000h are not listed.
    std::vector<std::uint16_t> mandatory, optional, manufacturer;
    for (const auto& [index, obj] : od.objects()) {
        if (index < 0x1000) continue;
        if (index == 0x1000 || index == 0x1001 || index == 0x1018) mandatory.push_back(index);
        else if (index >= 0x2000 && index <= 0x5FFF) manufacturer.push_back(index);
        else optional.push_back(index);
    }
    auto list = [&](const char* name, const std::vector<std::uint16_t>& v) {
        o.section(QString::fromLatin1(name));
        o.key(QStringLiteral("SupportedObjects"), QString::number(v.size()));
        for (size_t i = 0; i < v.size(); ++i) o.key(QString::number(i + 1), hex(v[i], 4));
    };
    list("MandatoryObjects", mandatory);
    list("OptionalObjects", optional);
    list("ManufacturerObjects", manufacturer);

    for (const auto& [index, obj] : od.objects()) {
        o.section(hex4(index));
        if (!obj.isComposite()) {
            if (obj.subs.empty()) {
                o.key(QStringLiteral("ParameterName"), obj.name);
                o.key(QStringLiteral("ObjectType"), hex(static_cast<int>(obj.objectType), 1));
                continue;
            }
            SubObject s = obj.subs.front();
            s.name = obj.name;
            entryKeys(o, s, obj.objectType);
        } else {
            o.key(QStringLiteral("ParameterName"), obj.name);
            o.key(QStringLiteral("ObjectType"), hex(static_cast<int>(obj.objectType), 1));
            o.key(QStringLiteral("SubNumber"), QString::number(obj.subs.size()));
            if (obj.objFlags) o.key(QStringLiteral("ObjFlags"), hex(obj.objFlags, 1));
            o.extra(obj.extraKeys);
            for (const SubObject& s : obj.subs) {
                o.section(hex4(index) + QStringLiteral("sub") + QString::number(s.sub, 16).toUpper());
                entryKeys(o, s);
            }
        }
        if (!obj.objectLinks.empty()) {
            o.section(hex4(index) + QStringLiteral("ObjectLinks"));
            o.key(QStringLiteral("ObjectLinks"), QString::number(obj.objectLinks.size()));
            for (size_t i = 0; i < obj.objectLinks.size(); ++i)
                o.key(QString::number(i + 1), hex(obj.objectLinks[i], 4));
        }
    }
    for (const ExtraSection& x : od.extraSections) {
        o.section(x.name);
        o.extra(x.keys);
    }
    return o.bytes();
}

bool DcfWriter::writeFile(const ObjectDictionary& od, const QString& path, QString* error) {
    QSaveFile f(path);
    if (!f.open(QIODevice::WriteOnly)) {
        if (error) *error = f.errorString();
        return false;
    }
    f.write(write(od));
    if (!f.commit()) {
        if (error) *error = f.errorString();
        return false;
    }
    return true;
}

}  // namespace coscope::eds
