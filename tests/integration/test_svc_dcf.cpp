// SPDX-License-Identifier: GPL-3.0-or-later
// DeviceConfiguration against the virtual drives: a node's values read into a DCF match the
// drive; a DCF written, changed and applied puts the change on the drive; a refused entry is
// reported with its object and abort text while the others are still written and reported;
// what a plan leaves out and why; the dcf export / dcf apply verbs (consent, --dry-run, --yes).
#include "SvcTestRig.h"

#include "core/canopen/DeviceConfiguration.h"
#include "core/canopen/SdoClient.h"
#include "core/canopen/ServiceWait.h"
#include "core/sim/VirtualDevice.h"
#include "eds/DcfWriter.h"
#include "eds/DictionaryLibrary.h"
#include "eds/EdsReader.h"

#include <QProcess>
#include <QTemporaryDir>
#include "tests/CliRun.h"

#include <QtTest>

using namespace coscope;
using namespace coscope::canopen;
using namespace svctest;

namespace {
od::ObjectDictionary dictionary(const QString& name) { return eds::DictionaryLibrary().load(name).dictionary; }

ConfigReadResult readAll(DeviceConfiguration& config, uint8_t node, const od::ObjectDictionary& dict,
                         int* progressCalls = nullptr) {
    std::optional<ConfigReadResult> out;
    config.read(
        node, dict,
        [progressCalls](const ConfigEntryResult&, int, int) {
            if (progressCalls) ++*progressCalls;
        },
        [&out](const ConfigReadResult& r) { out = r; });
    waitUntil([&] { return out.has_value(); }, 60000);
    return out.value_or(ConfigReadResult{});
}

std::vector<ConfigEntryResult> apply(DeviceConfiguration& config, const ApplyPlan& plan) {
    std::optional<std::vector<ConfigEntryResult>> out;
    config.apply(plan, {}, [&out](const std::vector<ConfigEntryResult>& r, bool) { out = r; });
    waitUntil([&] { return out.has_value(); }, 60000);
    return out.value_or(std::vector<ConfigEntryResult>{});
}

std::optional<od::Value> deviceValue(Rig& rig, uint8_t node, uint16_t index, uint8_t sub) {
    std::optional<od::Value> v;
    rig.onDevice(node, [&](sim::VirtualDevice& d) { v = d.value(index, sub); });
    return v;
}

// Sets ParameterValue of [IIII] (sub 0 VAR) or [IIIIsubS] in DCF text.
void setParameterValue(QByteArray& dcf, const QString& section, const QString& value) {
    QString text = QString::fromUtf8(dcf);
    const int at = text.indexOf(QStringLiteral("[%1]").arg(section));
    QVERIFY2(at >= 0, qPrintable(section));
    const int pv = text.indexOf(QStringLiteral("ParameterValue="), at);
    QVERIFY(pv >= 0);
    const int end = text.indexOf(u'\r', pv);
    text.replace(pv, end - pv, QStringLiteral("ParameterValue=") + value);
    dcf = text.toUtf8();
}
}  // namespace

class TestSvcDcf : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;

private slots:
    void initTestCase() { QVERIFY(dir_.isValid()); }

    void exportMatchesTheDrive() {
        Rig rig;
        QVERIFY(rig.useSpec(QStringLiteral("1:delta-asda-a2")));
        QVERIFY(rig.open());
        rig.onDevice(1, [](sim::VirtualDevice& d) { d.setValue(0x1017, 0, od::Value::unsignedInt(250)); });
        SdoClient sdo(*rig.context);
        DeviceConfiguration config(sdo);
        const od::ObjectDictionary dict = dictionary(QStringLiteral("delta-asda-a2"));
        int progress = 0;
        const ConfigReadResult r = readAll(config, 1, dict, &progress);
        QCOMPARE(r.node, uint8_t(1));
        QVERIFY(!r.cancelled);
        QCOMPARE(progress, static_cast<int>(r.entries.size()));
        // All readable entries but the empty error history (1003h:00 = 0: subs 1..n not asked).
        const auto readable = DeviceConfiguration::readableEntries(dict);
        const auto history = std::count_if(readable.begin(), readable.end(),
                                           [](const auto& p) { return p.first == 0x1003 && p.second > 0; });
        QVERIFY(history > 0);
        QCOMPARE(r.entries.size(), readable.size() - static_cast<size_t>(history));
        QVERIFY(r.entries.size() > 100);
        QCOMPARE(r.failed, 0);
        // Every value read equals the drive's (static objects: the drive is not enabled).
        int compared = 0;
        for (const ConfigEntryResult& e : r.entries) {
            if (!e.ok) {
                QVERIFY2(e.error.contains(objectRef(e.index, e.sub)), qPrintable(e.error));
                continue;
            }
            const od::SubObject* s = r.values.entry(e.index, e.sub);
            QVERIFY(s);
            QCOMPARE(s->parameterValue, e.valueText);
            if (s->pdoMappable && s->access == od::Access::ReadOnly) continue;  // process values
            const auto dev = deviceValue(rig, 1, e.index, e.sub);
            QVERIFY(dev);
            QVERIFY2(s->interpret(s->parameterValue, 1)->encode(s->dataType) == dev->encode(s->dataType),
                     qPrintable(QStringLiteral("%1 = %2").arg(objectRef(e.index, e.sub), s->parameterValue)));
            ++compared;
        }
        QVERIFY(compared > 100);
        QCOMPARE(r.values.entry(0x1017, 0)->parameterValue, QStringLiteral("0x00FA"));
        QCOMPARE(r.values.entry(0x1018, 1)->parameterValue, QStringLiteral("0x000001DD"));  // Delta's vendor-ID
        QCOMPARE(r.values.nodeId(), uint8_t(1));
        // Written as a DCF and read back: the same values and NodeID.
        const QString path = dir_.filePath(QStringLiteral("delta.dcf"));
        QString error;
        QVERIFY2(eds::DcfWriter::writeFile(r.values, path, &error), qPrintable(error));
        const eds::ReadResult back = eds::readDictionaryFile(path);
        QVERIFY(back.usable);
        QCOMPARE(back.dictionary.nodeId(), uint8_t(1));
        QCOMPARE(back.dictionary.entry(0x1017, 0)->parameterValue, QStringLiteral("0x00FA"));
        QCOMPARE(back.dictionary.entry(0x6083, 0)->parameterValue, r.values.entry(0x6083, 0)->parameterValue);
    }

    void modifiedDcfIsApplied() {
        Rig rig;
        QVERIFY(rig.useSpec(QStringLiteral("1:delta-asda-a2")));
        QVERIFY(rig.open());
        SdoClient sdo(*rig.context);
        DeviceConfiguration config(sdo);
        const ConfigReadResult exported = readAll(config, 1, dictionary(QStringLiteral("delta-asda-a2")));
        QByteArray text = eds::DcfWriter::write(exported.values);
        setParameterValue(text, QStringLiteral("1017"), QStringLiteral("400"));
        setParameterValue(text, QStringLiteral("6083"), QStringLiteral("12345"));
        const eds::ReadResult dcf = eds::EdsReader::read(text, QStringLiteral("changed.dcf"));
        QVERIFY(dcf.usable);

        // Against the node's current values only the two changes are written.
        const ConfigReadResult now = readAll(config, 1, dcf.dictionary);
        const ApplyPlan plan = DeviceConfiguration::plan(1, dcf.dictionary, &now.values, ApplyScope::OnlyDifferent);
        QCOMPARE(plan.writes.size(), size_t(2));
        QCOMPARE(plan.writes[0].index, uint16_t(0x1017));
        QCOMPARE(plan.writes[0].currentText, QStringLiteral("0x0000"));
        QCOMPARE(plan.writes[1].index, uint16_t(0x6083));
        QCOMPARE(plan.writes[1].data, QByteArray::fromHex("39300000"));
        // The rest is listed with a reason: unchanged, read-only, or a command object.
        auto reason = [&](uint16_t index, uint8_t sub) {
            for (const SkippedEntry& s : plan.skipped)
                if (s.index == index && s.sub == sub) return s.reason;
            return QString();
        };
        QVERIFY(reason(0x1005, 0).startsWith(QStringLiteral("unchanged")));
        QVERIFY(reason(0x1018, 1).contains(QStringLiteral("not writable")));
        QVERIFY(reason(0x6040, 0).contains(QStringLiteral("command")));  // controlword never from a file
        // Without current values every writable value is planned.
        const ApplyPlan all = DeviceConfiguration::plan(1, dcf.dictionary, nullptr, ApplyScope::AllValues);
        QVERIFY(all.writes.size() > 20);

        const auto results = apply(config, plan);
        QCOMPARE(results.size(), size_t(2));
        for (const auto& r : results) QVERIFY2(r.ok, qPrintable(r.error));
        QCOMPARE(deviceValue(rig, 1, 0x1017, 0)->toUInt64().value_or(0), uint64_t(400));
        QCOMPARE(deviceValue(rig, 1, 0x6083, 0)->toUInt64().value_or(0), uint64_t(12345));
    }

    void pdoChangesAreWrittenInTheCia301Order() {
        Rig rig;
        QVERIFY(rig.useSpec(QStringLiteral("3:generic-cia402")));
        QVERIFY(rig.open());
        SdoClient sdo(*rig.context);
        DeviceConfiguration config(sdo);
        const ConfigReadResult now = readAll(config, 3, dictionary(QStringLiteral("generic-cia402")));
        od::ObjectDictionary dcf = now.values;
        dcf.setParameterValue(0x1800, 2, QStringLiteral("1"));  // TPDO1 on every SYNC
        dcf.setParameterValue(0x1A00, 0, QStringLiteral("2"));
        dcf.setParameterValue(0x1A00, 1, QStringLiteral("0x60410010"));
        dcf.setParameterValue(0x1A00, 2, QStringLiteral("0x60640020"));
        const ApplyPlan plan = DeviceConfiguration::plan(3, dcf, &now.values, ApplyScope::OnlyDifferent);
        QVERIFY(plan.writes.size() >= 6);
        // COB-ID invalid first, the mapping count 0 before the entries and last, COB-ID valid at the end.
        QCOMPARE(plan.writes.front().index, uint16_t(0x1800));
        QCOMPARE(plan.writes.front().sub, uint8_t(1));
        QVERIFY(plan.writes.front().value.toUInt64().value_or(0) & 0x80000000u);
        QCOMPARE(plan.writes.back().index, uint16_t(0x1800));
        QCOMPARE(plan.writes.back().sub, uint8_t(1));
        QVERIFY(!(plan.writes.back().value.toUInt64().value_or(0) & 0x80000000u));
        int zeroAt = -1, countAt = -1, entryAt = -1;
        for (int i = 0; i < static_cast<int>(plan.writes.size()); ++i) {
            const PlannedWrite& w = plan.writes[static_cast<size_t>(i)];
            if (w.index == 0x1A00 && w.sub == 0) (w.value.toUInt64().value_or(9) == 0 ? zeroAt : countAt) = i;
            if (w.index == 0x1A00 && w.sub == 2) entryAt = i;
        }
        QVERIFY(zeroAt >= 0 && zeroAt < entryAt && entryAt < countAt);
        const auto results = apply(config, plan);
        for (const auto& r : results) QVERIFY2(r.ok, qPrintable(r.error));
        QCOMPARE(deviceValue(rig, 3, 0x1A00, 2)->toUInt64().value_or(0), uint64_t(0x60640020));
        QCOMPARE(deviceValue(rig, 3, 0x1A00, 0)->toUInt64().value_or(0), uint64_t(2));
        QCOMPARE(deviceValue(rig, 3, 0x1800, 2)->toUInt64().value_or(0), uint64_t(1));
        QVERIFY(!(deviceValue(rig, 3, 0x1800, 1)->toUInt64().value_or(0x80000000u) & 0x80000000u));
    }

    void refusedEntryIsReportedAndTheOthersWritten() {
        Rig rig;
        QVERIFY(rig.useSpec(QStringLiteral("3:generic-cia402")));
        QVERIFY(rig.open());
        SdoClient sdo(*rig.context);
        DeviceConfiguration config(sdo);
        od::ObjectDictionary dcf = dictionary(QStringLiteral("generic-cia402"));
        dcf.setParameterValue(0x1017, 0, QStringLiteral("100"));
        dcf.setParameterValue(0x6083, 0, QStringLiteral("2000"));
        dcf.setParameterValue(0x6084, 0, QStringLiteral("3000"));
        const ApplyPlan plan = DeviceConfiguration::plan(3, dcf, nullptr, ApplyScope::AllValues);
        QCOMPARE(plan.writes.size(), size_t(3));
        rig.onDevice(3, [](sim::VirtualDevice& d) {
            d.sdoFaults().abortOn = std::make_tuple(uint16_t(0x6083), uint8_t(0), uint32_t(0x06090031));
        });
        const auto results = apply(config, plan);
        QCOMPARE(results.size(), size_t(3));  // no retries, none left out
        QVERIFY(results[0].ok);
        QVERIFY(!results[1].ok);
        QCOMPARE(results[1].index, uint16_t(0x6083));
        QCOMPARE(results[1].abortCode, 0x06090031u);
        QVERIFY2(results[1].error.contains(QStringLiteral("6083:00")) &&
                     results[1].error.contains(QStringLiteral("too high")),
                 qPrintable(results[1].error));
        QVERIFY(results[2].ok);
        QCOMPARE(deviceValue(rig, 3, 0x1017, 0)->toUInt64().value_or(0), uint64_t(100));
        QCOMPARE(deviceValue(rig, 3, 0x6084, 0)->toUInt64().value_or(0), uint64_t(3000));
        QVERIFY(deviceValue(rig, 3, 0x6083, 0)->toUInt64().value_or(0) != 2000u);
    }

    void cancelStopsAfterTheCurrentTransfer() {
        Rig rig;
        QVERIFY(rig.useSpec(QStringLiteral("1:delta-asda-a2")));
        QVERIFY(rig.open());
        SdoClient sdo(*rig.context);
        DeviceConfiguration config(sdo);
        std::optional<ConfigReadResult> out;
        config.read(
            1, dictionary(QStringLiteral("delta-asda-a2")),
            [&config](const ConfigEntryResult&, int done, int) {
                if (done == 5) config.cancel();
            },
            [&out](const ConfigReadResult& r) { out = r; });
        QVERIFY(waitUntil([&] { return out.has_value(); }, 20000));
        QVERIFY(out->cancelled);
        QCOMPARE(out->entries.size(), size_t(5));
        QVERIFY(!config.isRunning());
    }

    void cliExportAndApply() {
        const QString bus = QStringLiteral("sim://?nodes=1:delta-asda-a2");
        const QString path = dir_.filePath(QStringLiteral("cli.dcf"));
        Run r = cli({QStringLiteral("dcf"), QStringLiteral("export"), bus, QStringLiteral("1"), path});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        QVERIFY(r.out.contains(QStringLiteral("values read")));
        const eds::ReadResult dcf = eds::readDictionaryFile(path);
        QVERIFY(dcf.usable);
        QCOMPARE(dcf.dictionary.nodeId(), uint8_t(1));
        QCOMPARE(dcf.dictionary.entry(0x1018, 1)->parameterValue, QStringLiteral("0x000001DD"));

        // Unchanged: nothing to write.
        r = cli({QStringLiteral("dcf"), QStringLiteral("apply"), bus, QStringLiteral("1"), path});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        QVERIFY2(r.out.contains(QStringLiteral("0 object(s) to write")), qPrintable(r.out));

        QFile f(path);
        QVERIFY(f.open(QIODevice::ReadOnly));
        QByteArray text = f.readAll();
        f.close();
        setParameterValue(text, QStringLiteral("1017"), QStringLiteral("300"));
        QVERIFY(f.open(QIODevice::WriteOnly | QIODevice::Truncate));
        f.write(text);
        f.close();

        // Without --yes: refused, nothing written, the count said.
        r = cli({QStringLiteral("dcf"), QStringLiteral("apply"), bus, QStringLiteral("1"), path});
        QCOMPARE(r.code, 1);
        QVERIFY2(r.err.contains(QStringLiteral("would write 1 object(s) to node 1")) &&
                     r.err.contains(QStringLiteral("--yes")),
                 qPrintable(r.err));
        QCOMPARE(r.err.count(u'\n'), 1);
        // --dry-run lists the write and exits 0.
        r = cli({QStringLiteral("dcf"), QStringLiteral("apply"), bus, QStringLiteral("1"), path,
                 QStringLiteral("--dry-run")});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        QVERIFY2(r.out.contains(QStringLiteral("write 1017:00")) && r.out.contains(QStringLiteral("0x012C")),
                 qPrintable(r.out));
        QVERIFY(r.out.contains(QStringLiteral("now 0x0000")));
        // --yes writes it.
        r = cli(
            {QStringLiteral("dcf"), QStringLiteral("apply"), bus, QStringLiteral("1"), path, QStringLiteral("--yes")});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        QVERIFY2(
            r.out.contains(QStringLiteral("ok     1017:00")) && r.out.contains(QStringLiteral("1 object(s) written")),
            qPrintable(r.out));
        // Usage errors.
        QCOMPARE(cli({QStringLiteral("dcf"), QStringLiteral("apply"), bus, QStringLiteral("1"), path,
                      QStringLiteral("--yes"), QStringLiteral("--dry-run")})
                     .code,
                 2);
        QCOMPARE(cli({QStringLiteral("dcf"), QStringLiteral("export"), bus, QStringLiteral("200"), path}).code, 2);
        r = cli({QStringLiteral("dcf"), QStringLiteral("apply"), bus, QStringLiteral("1"),
                 dir_.filePath(QStringLiteral("missing.dcf"))});
        QCOMPARE(r.code, 1);
        QVERIFY(r.err.contains(QStringLiteral("missing.dcf")));
    }
};

QTEST_GUILESS_MAIN(TestSvcDcf)
#include "test_svc_dcf.moc"
