// SPDX-License-Identifier: GPL-3.0-or-later
// XddReader (CiA 311) on a small hand-written XDD, and the content sniffing of readDictionary.
#include "eds/XddReader.h"

#include <QFile>
#include <QTest>

using namespace coscope;
using namespace coscope::od;

static QByteArray miniXdd() {
    QFile f(QStringLiteral(COSCOPE_SOURCE_DIR "/tests/data/eds/mini.xdd"));
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

class TestEdsXdd : public QObject {
    Q_OBJECT
private slots:
    void readsModel();
    void sniffedByReadDictionary();
    void brokenXmlKeepsWhatWasRead();
};

void TestEdsXdd::readsModel() {
    QVERIFY(!miniXdd().isEmpty());
    const auto r = eds::XddReader::read(miniXdd(), "mini.xdd");
    QString all;
    for (const auto& d : r.diagnostics) all += d.toString() + u'\n';
    QVERIFY2(r.usable, qPrintable(all));
    QVERIFY2(r.diagnostics.empty(), qPrintable(all));
    const auto& od = r.dictionary;
    QCOMPARE(od.objectCount(), 4);
    QCOMPARE(od.device.vendorNumber, std::optional<std::uint32_t>(0x1A2));
    QCOMPARE(od.device.productNumber, std::optional<std::uint32_t>(0x10));
    QCOMPARE(od.device.productName, QString::fromUtf8("Mini µDrive"));
    QCOMPARE(od.device.baudRates, (QList<int>{250, 1000}));
    QCOMPARE(od.device.nrOfTxPdo, 3);
    QVERIFY(od.device.lssSupported);
    QCOMPARE(od.nodeId(), std::uint8_t(9));
    QCOMPARE(od.commissioning.baudRate, 500);
    const SubObject* hb = od.entry(0x1017, 0);
    QCOMPARE(hb->dataType, DataType::Unsigned16);
    QCOMPARE(hb->access, Access::ReadWrite);
    QVERIFY(!hb->pdoMappable);
    QCOMPARE(hb->resolvedDefault(1)->toUInt64(), std::optional<std::uint64_t>(500));
    QCOMPARE(od.entry(0x1800, 1)->resolvedDefault(9)->toUInt64(), std::optional<std::uint64_t>(0x189));
    QCOMPARE(od.entry(0x1800, 0)->access, Access::ReadOnly);  // CiA 311 default access is read
    QCOMPARE(od.displayName(0x1800, 1), QString("TPDO1 communication: COB-ID"));
    const SubObject* pos = od.entry(0x6064, 0);
    QCOMPARE(pos->dataType, DataType::Integer32);
    QCOMPARE(pos->access, Access::ReadWriteRead);
    QVERIFY(pos->pdoMappable);
    QCOMPARE(pos->resolvedValue(1)->toInt64(), std::optional<std::int64_t>(-7));
    const SubObject* in = od.entry(0x2000, 0);
    QCOMPARE(in->dataType, DataType::Unsigned16);
    QCOMPARE(in->access, Access::Const);
    QCOMPARE(in->highLimit, QString("0x20"));
}

void TestEdsXdd::sniffedByReadDictionary() {
    const auto r = eds::readDictionary(QByteArray("\xEF\xBB\xBF  \n") + miniXdd(), "mini.xdd");
    QVERIFY(r.usable);
    QCOMPARE(r.encoding, QString("XML"));
}

void TestEdsXdd::brokenXmlKeepsWhatWasRead() {
    QByteArray cut = miniXdd();
    cut.truncate(cut.indexOf("<CANopenObject index=\"6064\"") + 10);
    const auto r = eds::XddReader::read(cut, "cut.xdd");
    QVERIFY(r.usable);
    QCOMPARE(r.dictionary.objectCount(), 2);
    QCOMPARE(r.errorCount(), 1);
    QVERIFY(r.diagnostics.back().line > 0);
}

QTEST_GUILESS_MAIN(TestEdsXdd)
#include "test_eds_xdd.moc"
