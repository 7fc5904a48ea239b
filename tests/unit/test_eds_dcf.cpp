// SPDX-License-Identifier: GPL-3.0-or-later
// DcfWriter: what it writes reads back into the same dictionary.
#include "eds/DcfWriter.h"
#include "eds/EdsReader.h"

#include <QTemporaryDir>
#include <QTest>

using namespace coscope;
using namespace coscope::od;

namespace {

// Compares every field the model holds; returns the first difference.
QString difference(const ObjectDictionary& a, const ObjectDictionary& b) {
    if (a.objectCount() != b.objectCount())
        return QStringLiteral("object count %1 vs %2").arg(a.objectCount()).arg(b.objectCount());
    for (const auto& [index, oa] : a.objects()) {
        const Object* ob = b.object(index);
        if (!ob) return QStringLiteral("missing %1").arg(index, 0, 16);
        if (oa.name != ob->name || oa.objectType != ob->objectType || oa.subs.size() != ob->subs.size() ||
            oa.objectLinks != ob->objectLinks)
            return QStringLiteral("object %1 differs").arg(index, 0, 16);
        for (size_t i = 0; i < oa.subs.size(); ++i) {
            const SubObject &x = oa.subs[i], &y = ob->subs[i];
            if (x.sub != y.sub || x.name != y.name || x.dataType != y.dataType || x.access != y.access ||
                x.pdoMappable != y.pdoMappable || x.defaultValue != y.defaultValue ||
                x.parameterValue != y.parameterValue || x.lowLimit != y.lowLimit || x.highLimit != y.highLimit ||
                x.denotation != y.denotation || x.objFlags != y.objFlags || x.extraKeys != y.extraKeys)
                return QStringLiteral("entry %1:%2 differs (%3 / %4)").arg(index, 0, 16).arg(x.sub).arg(x.name, y.name);
        }
    }
    if (a.device.vendorName != b.device.vendorName || a.device.vendorNumber != b.device.vendorNumber ||
        a.device.productNumber != b.device.productNumber || a.device.revisionNumber != b.device.revisionNumber ||
        a.device.baudRates != b.device.baudRates || a.device.nrOfRxPdo != b.device.nrOfRxPdo ||
        a.device.lssSupported != b.device.lssSupported)
        return QStringLiteral("device info differs");
    if (a.commissioning.nodeId != b.commissioning.nodeId || a.commissioning.baudRate != b.commissioning.baudRate)
        return QStringLiteral("commissioning differs");
    if (a.dummyUsage != b.dummyUsage) return QStringLiteral("dummy usage differs");
    if (a.dynamicChannels.size() != b.dynamicChannels.size()) return QStringLiteral("dynamic channels differ");
    if (a.comments != b.comments) return QStringLiteral("comments differ");
    return {};
}

}  // namespace

class TestEdsDcf : public QObject {
    Q_OBJECT
private slots:
    void roundTripFixture();
    void actualValuesAndCommissioning();
    void writeFile();
};

void TestEdsDcf::roundTripFixture() {
    const auto first = eds::EdsReader::readFile(QStringLiteral(COSCOPE_SOURCE_DIR "/tests/data/eds/quirks.eds"));
    QVERIFY(first.usable);
    const QByteArray dcf = eds::DcfWriter::write(first.dictionary);
    const auto second = eds::EdsReader::read(dcf, "written.dcf");
    QVERIFY(second.usable);
    QString all;
    for (const auto& d : second.diagnostics) all += d.toString() + u'\n';
    QCOMPARE(second.warningCount(), 0);  // the writer produces a clean file
    QVERIFY2(all.isEmpty(), qPrintable(all));
    const QString diff = difference(first.dictionary, second.dictionary);
    QVERIFY2(diff.isEmpty(), qPrintable(diff));
    // Writing again gives the same bytes.
    QCOMPARE(eds::DcfWriter::write(second.dictionary), dcf);
}

void TestEdsDcf::actualValuesAndCommissioning() {
    auto r = eds::EdsReader::readFile(QStringLiteral(COSCOPE_SOURCE_DIR "/tests/data/eds/quirks.eds"));
    ObjectDictionary od = r.dictionary;
    QVERIFY(od.setParameterValue(0x2002, 0, QStringLiteral("42")));
    QVERIFY(!od.setParameterValue(0x2002, 9, QStringLiteral("42")));
    const QByteArray dcf = eds::DcfWriter::write(od, 12, 250);
    QVERIFY(dcf.contains("[DeviceCommissioning]\r\nNodeID=12\r\n"));
    QVERIFY(dcf.contains("Baudrate=250\r\n"));
    const auto back = eds::EdsReader::read(dcf, "x.dcf");
    QCOMPARE(back.dictionary.nodeId(), std::uint8_t(12));
    QCOMPARE(back.dictionary.commissioning.baudRate, 250);
    QCOMPARE(back.dictionary.entry(0x2002, 0)->resolvedValue(12)->toInt64(), std::optional<std::int64_t>(42));
    QCOMPARE(back.dictionary.entry(0x2000, 0)->resolvedDefault(12)->toUInt64(), std::optional<std::uint64_t>(0x18C));
}

void TestEdsDcf::writeFile() {
    QTemporaryDir dir;
    const auto r = eds::EdsReader::readFile(QStringLiteral(COSCOPE_SOURCE_DIR "/tests/data/eds/quirks.eds"));
    const QString path = dir.filePath("out.dcf");
    QString err;
    QVERIFY2(eds::DcfWriter::writeFile(r.dictionary, path, &err), qPrintable(err));
    const auto back = eds::EdsReader::readFile(path);
    QVERIFY(back.usable);
    QCOMPARE(back.dictionary.objectCount(), r.dictionary.objectCount());
    QVERIFY(!eds::DcfWriter::writeFile(r.dictionary, "/nonexistent-dir/x.dcf", &err));
    QVERIFY(!err.isEmpty());
}

QTEST_GUILESS_MAIN(TestEdsDcf)
#include "test_eds_dcf.moc"
