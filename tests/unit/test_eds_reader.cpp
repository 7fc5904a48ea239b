// SPDX-License-Identifier: GPL-3.0-or-later
// EdsReader on CoScope's own fixtures: one quirk per check (tests/data/eds/quirks.eds and
// small inline snippets).
#include "eds/EdsReader.h"

#include <QFile>
#include <QTest>

using namespace coscope;
using namespace coscope::od;

namespace {

bool hasDiagnostic(const eds::ReadResult& r, int line, const QString& fragment) {
    for (const auto& d : r.diagnostics)
        if (d.line == line && d.message.contains(fragment, Qt::CaseInsensitive)) return true;
    return false;
}

QString dump(const eds::ReadResult& r) {
    QString s;
    for (const auto& d : r.diagnostics) s += d.toString() + u'\n';
    return s;
}

eds::ReadResult readSnippet(const char* text) {
    return eds::EdsReader::read(QByteArray(text), QStringLiteral("snippet.eds"));
}

}  // namespace

class TestEdsReader : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void objectSetFromListsAndScan();
    void caseInsensitiveAndOrder();
    void duplicateKeyFirstWins();
    void nodeIdFormulas();
    void numbersOctalHexReal();
    void compactSubObj();
    void compactPdo();
    void dummyDynamicLinksCommissioning();
    void dcfValues();
    void encodingWindows1252AndCrlf();
    void utf8WithBom();
    void noListsFallback();
    void inlineHashComments();
    void duplicateSection();
    void unknownKeysKept();
    void customDataType();
    void nothingUsable();
    void diagnosticFormat();
    void lookupIsFast();

private:
    eds::ReadResult quirks_;
};

void TestEdsReader::initTestCase() {
    quirks_ = eds::EdsReader::readFile(QStringLiteral(COSCOPE_SOURCE_DIR "/tests/data/eds/quirks.eds"));
    QVERIFY2(quirks_.usable, qPrintable(dump(quirks_)));
}

void TestEdsReader::objectSetFromListsAndScan() {
    const auto& od = quirks_.dictionary;
    // Listed: 1000 1018 1016 1800 1A00 1017 2000 2001 2002; 1800/1A00 have no section (implied
    // by CompactPDO), 2003 is unlisted but read; CompactPDO also implies 1400/1600.
    QList<int> indices;
    for (const auto& [i, o] : od.objects()) indices << i;
    QCOMPARE(indices, (QList<int>{0x1000, 0x1016, 0x1017, 0x1018, 0x1400, 0x1600, 0x1800, 0x1A00, 0x2000, 0x2001,
                                  0x2002, 0x2003}));
    QVERIFY2(hasDiagnostic(quirks_, 81, "0x1800 is listed but has no section"), qPrintable(dump(quirks_)));
    QVERIFY(hasDiagnostic(quirks_, 137, "[2003] is not in any object list"));
}

void TestEdsReader::caseInsensitiveAndOrder() {
    const auto& od = quirks_.dictionary;
    QCOMPARE(od.fileInfo.fileName, QString("quirks.eds"));        // [fileinfo]
    QCOMPARE(od.device.productName, QString("Quirk Drive"));      // [DEVICEINFO]
    QCOMPARE(od.device.baudRates, (QList<int>{250, 500}));        // Baudrate_250 and BaudRate_500
    QCOMPARE(od.entry(0x2000, 0)->access, Access::ReadWrite);     // AccessType=RW
    QCOMPARE(od.entry(0x2000, 0)->name, QString("Late object"));  // object before the lists
}

void TestEdsReader::duplicateKeyFirstWins() {
    const SubObject* s = quirks_.dictionary.entry(0x1018, 0);
    QVERIFY(s);
    QCOMPARE(s->defaultValue, QString("1"));
    QVERIFY2(hasDiagnostic(quirks_, 70, "duplicate key DefaultValue in [1018sub0] (first at line 69)"),
             qPrintable(dump(quirks_)));
}

void TestEdsReader::nodeIdFormulas() {
    const SubObject* s = quirks_.dictionary.entry(0x2000, 0);
    QCOMPARE(s->defaultValue, QString("$NODEID+0x180"));  // kept symbolic
    QVERIFY(s->defaultUsesNodeId());
    QCOMPARE(s->resolvedDefault(5)->toUInt64(), std::optional<std::uint64_t>(0x185));
    QCOMPARE(s->resolvedDefault(0x7F)->toUInt64(), std::optional<std::uint64_t>(0x1FF));
    // Constant first, spaces, lower case.
    const auto r =
        readSnippet("[1014]\nParameterName=COB-ID EMCY\nDataType=0x0007\nAccessType=rw\nDefaultValue=0x80 + $nodeid\n");
    QCOMPARE(r.dictionary.entry(0x1014, 0)->resolvedDefault(3)->toUInt64(), std::optional<std::uint64_t>(0x83));
}

void TestEdsReader::numbersOctalHexReal() {
    const auto& od = quirks_.dictionary;
    QCOMPARE(od.entry(0x1017, 0)->resolvedDefault(1)->toUInt64(), std::optional<std::uint64_t>(8));  // "010" octal
    QCOMPARE(od.device.productNumber, std::optional<std::uint32_t>(0456));                           // octal too
    QCOMPARE(od.device.vendorNumber, std::optional<std::uint32_t>(0x123));
    QCOMPARE(od.entry(0x2001, 0)->resolvedDefault(1)->toDouble(), std::optional<double>(1.5));  // REAL bit pattern
    QCOMPARE(od.entry(0x2002, 0)->resolvedDefault(1)->toInt64(), std::optional<std::int64_t>(-5));
    const Limits l = od.entry(0x2002, 0)->limits();
    QVERIFY(!Value::parse(DataType::Integer16, "200", l).ok());
    QVERIFY(Value::parse(DataType::Integer16, "99", l).ok());
}

void TestEdsReader::compactSubObj() {
    const Object* o = quirks_.dictionary.object(0x1016);
    QVERIFY(o);
    QCOMPARE(o->objectType, ObjectType::Array);
    QCOMPARE(int(o->subs.size()), 4);
    QCOMPARE(o->sub(0)->resolvedDefault(1)->toUInt64(), std::optional<std::uint64_t>(3));
    QCOMPARE(o->sub(1)->name, QString("Heartbeat of node 1"));
    QCOMPARE(o->sub(2)->name, QString("Consumer heartbeat time 2"));
    QCOMPARE(o->sub(3)->name, QString("Heartbeat of node 3"));
    QCOMPARE(o->sub(2)->dataType, DataType::Unsigned32);
    QCOMPARE(o->sub(2)->access, Access::ReadWrite);
    QCOMPARE(o->sub(2)->parameterValue, QString("0x000203E8"));  // [1016Value]
    QCOMPARE(o->sub(1)->parameterValue, QString());
    QCOMPARE(quirks_.dictionary.displayName(0x1016, 1), QString("Consumer heartbeat time: Heartbeat of node 1"));
}

void TestEdsReader::compactPdo() {
    const auto& od = quirks_.dictionary;
    // CompactPDO=0x13: COB-ID, transmission type and event timer implied.
    const Object* tx = od.object(0x1800);
    QVERIFY(tx);
    QVERIFY(tx->sub(1) && tx->sub(2) && tx->sub(5));
    QVERIFY(!tx->sub(3));
    QCOMPARE(tx->sub(1)->resolvedDefault(5)->toUInt64(), std::optional<std::uint64_t>(0x185));
    QCOMPARE(od.entry(0x1400, 1)->resolvedDefault(5)->toUInt64(), std::optional<std::uint64_t>(0x205));
    QCOMPARE(int(od.object(0x1A00)->subs.size()), 9);
}

void TestEdsReader::dummyDynamicLinksCommissioning() {
    const auto& od = quirks_.dictionary;
    QVERIFY(od.dummyUsage[5] && od.dummyUsage[7]);
    QVERIFY(!od.dummyUsage[2]);
    QCOMPARE(int(od.dynamicChannels.size()), 1);
    QCOMPARE(od.dynamicChannels[0].rangeFirst, std::uint16_t(0xA000));
    QCOMPARE(od.dynamicChannels[0].rangeLast, std::uint16_t(0xA0FF));
    QCOMPARE(od.dynamicChannels[0].dir, QString("rww"));
    QCOMPARE(od.object(0x1016)->objectLinks, (std::vector<std::uint16_t>{0x1017}));
    QCOMPARE(od.nodeId(), std::uint8_t(5));  // [DeviceComissioning]
    QCOMPARE(od.commissioning.baudRate, 500);
    QVERIFY(od.device.lssSupported);
    QCOMPARE(od.device.nrOfRxPdo, 1);
    // The correct spelling wins when both exist.
    const auto r = readSnippet(
        "[DeviceComissioning]\nNodeID=3\n[DeviceCommissioning]\nNodeID=4\n[1000]\nParameterName=x\nDataType="
        "7\nAccessType=ro\n");
    QCOMPARE(r.dictionary.nodeId(), std::uint8_t(4));
    QVERIFY(hasDiagnostic(r, 1, "both [DeviceCommissioning] and [DeviceComissioning]"));
}

void TestEdsReader::dcfValues() {
    const SubObject* s = quirks_.dictionary.entry(0x1017, 0);
    QCOMPARE(s->parameterValue, QString("1000"));
    QCOMPARE(s->denotation, QString("fast heartbeat"));
    QCOMPARE(s->resolvedValue(1)->toUInt64(), std::optional<std::uint64_t>(1000));
}

void TestEdsReader::encodingWindows1252AndCrlf() {
    QCOMPARE(quirks_.encoding, QString("Windows-1252"));
    QCOMPARE(quirks_.dictionary.device.vendorName, QString::fromUtf8("Test Vendor Müller €"));  // no '\r' left
    QCOMPARE(quirks_.dictionary.entry(0x2003, 0)->resolvedDefault(1)->toText(), QString::fromUtf8("Café"));
}

void TestEdsReader::utf8WithBom() {
    const auto r = eds::EdsReader::read(QByteArray("\xEF\xBB\xBF[1008]\r\nParameterName=Ger\xC3\xA4tename\r\nDataType="
                                                   "0x0009\r\nAccessType=const\r\nDefaultValue=\xC2\xB5"
                                                   "Drive\r\n"),
                                        QStringLiteral("bom.eds"));
    QVERIFY(r.usable);
    QCOMPARE(r.encoding, QString("UTF-8"));
    QCOMPARE(r.dictionary.object(0x1008)->name, QString::fromUtf8("Gerätename"));
    QCOMPARE(r.dictionary.entry(0x1008, 0)->resolvedDefault(0)->toText(), QString::fromUtf8("µDrive"));
}

void TestEdsReader::noListsFallback() {
    const auto r = readSnippet(
        "; no object lists\n[1000]\nParameterName=Device "
        "type\nDataType=0x0007\nAccessType=ro\n\n[1001]\nParameterName=Error "
        "register\nDataType=0x0005\nAccessType=ro\n");
    QCOMPARE(r.dictionary.objectCount(), 2);
    QVERIFY(hasDiagnostic(r, 0, "no object lists"));
}

void TestEdsReader::inlineHashComments() {
    const auto r = readSnippet(
        "[1001]\nParameterName=Error register #1\nObjectType=0x07 # VAR\nDataType=0x0005 # UNSIGNED8\n# Category: "
        "Mandatory\nAccessType=ro # read\nDefaultValue=No\nPDOMapping=1 # Optional\n");
    QVERIFY(r.usable);
    const SubObject* s = r.dictionary.entry(0x1001, 0);
    QCOMPARE(s->name, QString("Error register #1"));  // names keep '#'
    QCOMPARE(s->dataType, DataType::Unsigned8);
    QCOMPARE(s->access, Access::ReadOnly);
    QVERIFY(s->pdoMappable);
    QVERIFY(hasDiagnostic(r, 3, "inline comment after ObjectType"));
    QVERIFY(hasDiagnostic(r, 8, "inline comment after PDOMapping"));
    QVERIFY2(hasDiagnostic(r, 7, "DefaultValue in [1001]: 'No' is not a number for UNSIGNED8"), qPrintable(dump(r)));
    QCOMPARE(s->defaultValue, QString("No"));  // kept as text
    QVERIFY(!s->resolvedDefault(1));
}

void TestEdsReader::duplicateSection() {
    const auto r =
        readSnippet("[1000]\nParameterName=First\nDataType=0x0007\n[1000]\nParameterName=Second\nAccessType=rw\n");
    const SubObject* s = r.dictionary.entry(0x1000, 0);
    QCOMPARE(s->name, QString("First"));
    QCOMPARE(s->access, Access::ReadWrite);  // merged
    QVERIFY(hasDiagnostic(r, 4, "section [1000] appears again (first at line 1)"));
    QVERIFY(hasDiagnostic(r, 5, "duplicate key ParameterName"));
}

void TestEdsReader::unknownKeysKept() {
    const SubObject* s = quirks_.dictionary.entry(0x2000, 0);
    QCOMPARE(s->extraKeys.size(), 1);
    QCOMPARE(s->extraKeys.front().first, QString("VendorKey"));
    QCOMPARE(s->extraKeys.front().second, QString("kept"));
    bool tool = false;
    for (const auto& x : quirks_.dictionary.extraSections) tool |= x.name == u"ToolInfos" && x.keys.size() == 1;
    QVERIFY(tool);
    QCOMPARE(quirks_.dictionary.comments, QStringList{"Quirks fixture"});
}

void TestEdsReader::customDataType() {
    const auto r = readSnippet(
        "[0040]\nParameterName=My "
        "struct\nObjectType=0x6\nSubNumber=2\n[0040sub0]\nParameterName=Count\nDataType=0x0005\nAccessType="
        "ro\nDefaultValue=1\n"
        "[0040sub1]\nParameterName=Field\nDataType=0x0007\nAccessType=ro\nDefaultValue=0x0007\n"
        "[2100]\nParameterName=Custom typed\nObjectType=0x7\nDataType=0x0040\nAccessType=rw\nDefaultValue=0102\n");
    QVERIFY(r.usable);
    QCOMPARE(r.dictionary.object(0x0040)->objectType, ObjectType::DefStruct);
    const SubObject* s = r.dictionary.entry(0x2100, 0);
    QCOMPARE(s->dataType, static_cast<DataType>(0x0040));
    QCOMPARE(typeClass(s->dataType), TypeClass::Domain);
    QCOMPARE(s->resolvedDefault(1)->toBytes(), QByteArray::fromHex("0102"));
}

void TestEdsReader::nothingUsable() {
    auto r = readSnippet("");
    QVERIFY(!r.usable);
    QCOMPARE(r.errorCount(), 1);
    r = eds::EdsReader::read(QByteArray("\x00\x01\x02garbage\xff\xfe", 12), "bin.eds");
    QVERIFY(!r.usable);
    r = eds::EdsReader::readFile("/nonexistent/file.eds");
    QVERIFY(!r.usable);
    QVERIFY(r.diagnostics.front().message.contains("cannot open"));
}

void TestEdsReader::diagnosticFormat() {
    const auto r = readSnippet("[1000]\nParameterName=x\nDataType=0x0007\nAccessType=bogus\n");
    QVERIFY(r.usable);
    QStringList lines;
    for (const auto& d : r.diagnostics) lines << d.toString();
    QVERIFY2(
        lines.contains(
            "snippet.eds:4: warning: AccessType='bogus' in [1000] is not ro, wo, rw, rwr, rww or const; ro assumed"),
        qPrintable(lines.join('\n')));
    QVERIFY(lines.contains("snippet.eds: warning: no [DeviceInfo] section"));
}

void TestEdsReader::lookupIsFast() {
    // Copies keep working lookups (the index is rebuilt, not shared).
    ObjectDictionary copy = quirks_.dictionary;
    quirks_.dictionary.setParameterValue(0x2002, 0, "7");
    QCOMPARE(copy.entry(0x2002, 0)->parameterValue, QString());
    QCOMPARE(quirks_.dictionary.entry(0x2002, 0)->parameterValue, QString("7"));
    QCOMPARE(copy.subObjectCount(), quirks_.dictionary.subObjectCount());
    QVERIFY(!copy.entry(0x2002, 1));
    QVERIFY(!copy.entry(0x3000, 0));
}

QTEST_GUILESS_MAIN(TestEdsReader)
#include "test_eds_reader.moc"
