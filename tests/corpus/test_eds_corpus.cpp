// SPDX-License-Identifier: GPL-3.0-or-later
// Every real-world EDS/DCF/XDD in ../shared/testdata/eds loads (see PROVENANCE.md for each
// file's quirks); known values from several of them. Skips when ../shared is absent.
#include "eds/DcfWriter.h"
#include "eds/EdsReader.h"

#include <QDir>
#include <QTest>

using namespace coscope;
using namespace coscope::od;

namespace {

QString corpus() { return QStringLiteral(COSCOPE_SHARED_DIR "/testdata/eds"); }

eds::ReadResult load(const QString& name) { return eds::readDictionaryFile(corpus() + u'/' + name); }

bool warnsAt(const eds::ReadResult& r, int line, const QString& fragment) {
    for (const auto& d : r.diagnostics)
        if (d.line == line && d.severity == eds::Diagnostic::Severity::Warning && d.message.contains(fragment))
            return true;
    return false;
}

int compositeEntries(const ObjectDictionary& od) {
    int n = 0;
    for (const auto& [i, o] : od.objects())
        if (o.isComposite()) n += static_cast<int>(o.subs.size());
    return n;
}

}  // namespace

class TestEdsCorpus : public QObject {
    Q_OBJECT
private slots:
    void init();
    void everyFileLoads();
    void brokenFilesWarnWithLines();
    void maxonEpos4();
    void knownValues();
    void xddMatchesEds();
    void dcfRoundTripOfEveryFile();
};

void TestEdsCorpus::init() {
    if (!QDir(corpus()).exists()) QSKIP("../shared/testdata/eds is absent");
}

void TestEdsCorpus::everyFileLoads() {
    const auto files = QDir(corpus()).entryList({"*.eds", "*.dcf", "*.xdd"}, QDir::Files);
    QVERIFY(files.size() >= 20);
    for (const QString& f : files) {
        const auto r = load(f);
        QVERIFY2(r.usable, qPrintable(f));
        QVERIFY2(r.errorCount() == 0, qPrintable(f));
        QVERIFY2(r.dictionary.objectCount() >= 4, qPrintable(f));
        for (const auto& d : r.diagnostics) QVERIFY2(d.file.endsWith(f), qPrintable(d.toString()));
    }
}

void TestEdsCorpus::brokenFilesWarnWithLines() {
    const auto dup = load("lely_test_sdo-server_dupkey.dcf");
    QVERIFY(dup.usable);
    QVERIFY(warnsAt(dup, 49, "duplicate key DefaultValue in [1018sub0] (first at line 48)"));
    QCOMPARE(dup.dictionary.entry(0x1018, 0)->resolvedDefault(1)->toUInt64(),
             std::optional<std::uint64_t>(4));           // first wins
    QCOMPARE(dup.dictionary.nodeId(), std::uint8_t(1));  // [DeviceComissioning]

    const auto hash = load("kacanopen_CiA301_hashcomments.eds");
    QVERIFY(hash.usable);
    QVERIFY(warnsAt(hash, 3, "inline comment after ObjectType in [1000]"));
    QVERIFY(warnsAt(hash, 7, "'Profile- or manufacturer-specific' is not a number for UNSIGNED32"));
    QVERIFY(warnsAt(hash, 16, "'No' is not a number for UNSIGNED8"));
    QCOMPARE(hash.dictionary.entry(0x1001, 0)->dataType, DataType::Unsigned8);
    QVERIFY(hash.dictionary.entry(0x1001, 0)->pdoMappable);
    QCOMPARE(hash.dictionary.object(0x1003)->objectType, ObjectType::Array);
}

void TestEdsCorpus::maxonEpos4() {
    const auto r = load("maxon_EPOS4_Module_50-5.eds");
    QVERIFY(r.usable);
    QCOMPARE(r.warningCount(), 0);
    // PROVENANCE: 164 objects / 489 subs. The 489 are the [XXXXsubN] sections (entries of
    // ARRAY/RECORD objects); with the 66 VAR objects the dictionary has 555 entries.
    QCOMPARE(r.dictionary.objectCount(), 164);
    QCOMPARE(compositeEntries(r.dictionary), 489);
    QCOMPARE(r.dictionary.subObjectCount(), 555);
    QCOMPARE(r.dictionary.vendorId(), std::optional<std::uint32_t>(0xFB));  // maxon motor
    const SubObject* cw = r.dictionary.entry(0x6040, 0);
    QVERIFY(cw);
    QCOMPARE(cw->dataType, DataType::Unsigned16);
    QVERIFY(cw->pdoMappable);
    const auto dcf = load("maxon_EPOS4_50-15_node1.dcf");
    QCOMPARE(dcf.dictionary.objectCount(), 164);
    QCOMPARE(dcf.dictionary.nodeId(), std::uint8_t(1));
}

void TestEdsCorpus::knownValues() {
    // CANopenNode: TPDO1 COB-ID $NODEID+0xC0000180 kept symbolic (invalid + no-RTR bits).
    const auto cn = load("canopennode_DS301_profile.eds");
    QVERIFY(cn.dictionary.entry(0x1800, 1)->defaultUsesNodeId());
    QCOMPARE(cn.dictionary.entry(0x1800, 1)->defaultValue, QString("$NODEID+0xC0000180"));
    QCOMPARE(cn.dictionary.entry(0x1800, 1)->resolvedDefault(10)->toUInt64(), std::optional<std::uint64_t>(0xC000018A));
    // OreSat: constant-first formula, Denotation and ParameterValue, [DeviceCommissioning].
    const auto ore = load("oresat_c3.dcf");
    QVERIFY(ore.dictionary.subObjectCount() > 1500);
    bool constantFirst = false;
    for (const auto& [i, o] : ore.dictionary.objects())
        for (const auto& s : o.subs)
            if (s.defaultValue.startsWith("0x") && s.defaultUsesNodeId()) constantFirst = true;
    QVERIFY(constantFirst);
    // Beckhoff: COB-ID with the invalid bit set.
    const auto bk = load("beckhoff_BK5120_bus_coupler.eds");
    bool invalidBit = false;
    for (const auto& [i, o] : bk.dictionary.objects())
        for (const auto& s : o.subs)
            if (s.defaultValue.contains("0x80000") && s.defaultUsesNodeId())
                invalidBit |= (s.resolvedDefault(1)->toUInt64().value_or(0) & 0x80000000u) != 0;
    QVERIFY(invalidBit);
    // python-canopen: CompactSubObj with names; lely: CompactSubObj=254/127.
    const auto py = load("python-canopen_test_sample.eds");
    QVERIFY(py.dictionary.object(0x3004));
    QVERIFY(py.dictionary.object(0x3004)->subs.size() >= 2);
    const auto lely = load("lely_coctl.dcf");
    bool big = false;
    for (const auto& [i, o] : lely.dictionary.objects()) big |= o.compactSubObj == 254 || o.compactSubObj == 127;
    QVERIFY(big);
    // Eyou: [DynamicChannels].
    QCOMPARE(int(load("eyou_YiyouServo_V1.4.eds").dictionary.dynamicChannels.size()), 1);
    // Elmo: 165 objects (PROVENANCE).
    QCOMPARE(load("elmo_Gold_Drive.eds").dictionary.objectCount(), 165);
    // Nanotec: 200 object sections (PROVENANCE).
    QCOMPARE(load("nanotec_CL3.eds").dictionary.objectCount(), 200);
}

void TestEdsCorpus::xddMatchesEds() {
    const auto xdd = load("canopendemo_demoDevice.xdd");
    const auto e = load("canopendemo_demoDevice.eds");
    QVERIFY(xdd.usable && e.usable);
    QCOMPARE(xdd.dictionary.device.productName, QString("Demo device"));
    QCOMPARE(xdd.dictionary.entry(0x1000, 0)->dataType, e.dictionary.entry(0x1000, 0)->dataType);
    QCOMPARE(xdd.dictionary.entry(0x1000, 0)->resolvedDefault(1), e.dictionary.entry(0x1000, 0)->resolvedDefault(1));
    QCOMPARE(xdd.dictionary.entry(0x1018, 2)->resolvedDefault(1)->toUInt64(), std::optional<std::uint64_t>(1));
    int same = 0, total = 0;
    for (const auto& [i, o] : e.dictionary.objects())
        for (const auto& s : o.subs) {
            ++total;
            const SubObject* x = xdd.dictionary.entry(i, s.sub);
            same += x && x->dataType == s.dataType && x->resolvedDefault(1) == s.resolvedDefault(1);
        }
    QVERIFY2(same * 10 >= total * 9, qPrintable(QString("%1 of %2 entries agree").arg(same).arg(total)));
}

void TestEdsCorpus::dcfRoundTripOfEveryFile() {
    const auto files = QDir(corpus()).entryList({"*.eds", "*.dcf"}, QDir::Files);
    for (const QString& f : files) {
        const auto a = load(f);
        const auto b = eds::EdsReader::read(eds::DcfWriter::write(a.dictionary), f + ".written.dcf");
        QVERIFY2(b.usable, qPrintable(f));
        QCOMPARE(b.dictionary.objectCount(), a.dictionary.objectCount());
        QCOMPARE(b.dictionary.subObjectCount(), a.dictionary.subObjectCount());
        for (const auto& [i, o] : a.dictionary.objects())
            for (const auto& s : o.subs) {
                const SubObject* t = b.dictionary.entry(i, s.sub);
                QVERIFY2(t && t->defaultValue == s.defaultValue && t->parameterValue == s.parameterValue &&
                             t->dataType == s.dataType,
                         qPrintable(QString("%1 %2:%3").arg(f).arg(i, 0, 16).arg(s.sub)));
            }
    }
}

QTEST_GUILESS_MAIN(TestEdsCorpus)
#include "test_eds_corpus.moc"
