// SPDX-License-Identifier: GPL-3.0-or-later
// Program download (CiA 302-3) through ProgramDownload against the virtual drives: a 1 MiB image
// by block SDO completes and the node comes back with the new 100Ah and 1F56h; a drive that
// aborts half-way gives a clear error naming 1F50h and the abort code, and nothing is claimed;
// an image with a bad CRC is downloaded but its start is refused and 1F57h says why; segmented
// transfer (chosen, or when the node declines block); cancel sends an abort and a retry from
// the start then succeeds; a drive CoScope enabled is disabled first.
#include "SvcTestRig.h"

#include "core/canopen/ProgramDownload.h"
#include "core/canopen/SdoAbort.h"
#include "core/canopen/SdoClient.h"
#include "core/canopen/ServiceWait.h"
#include "core/sim/ProgramFlash.h"
#include "core/sim/ProgramImage.h"
#include "core/sim/VirtualDevice.h"

#include <QElapsedTimer>
#include <QRandomGenerator>
#include <QtTest>

using namespace coscope;
using namespace coscope::canopen;
using namespace svctest;

namespace {
QByteArray payload(int size, quint32 seed) {
    QByteArray p(size, Qt::Uninitialized);
    QRandomGenerator g(seed);
    for (auto& c : p) c = static_cast<char>(g.generate() & 0xFF);
    return p;
}

ProgramDownloadOutcome download(ProgramDownload& pd, const ProgramDownloadRequest& req, int* progressCalls = nullptr,
                                qint64* lastDone = nullptr) {
    std::optional<ProgramDownloadOutcome> out;
    pd.run(
        req, {},
        [&](qint64 done, qint64, double) {
            if (progressCalls) ++*progressCalls;
            if (lastDone) *lastDone = done;
        },
        [&](const ProgramDownloadOutcome& o) { out = o; });
    waitUntil([&] { return out.has_value(); }, 60000);
    return out.value_or(ProgramDownloadOutcome{});
}

struct FlashSeen {
    QString version;
    uint32_t softwareId = 0;
    uint32_t status = 0;
    bool running = false;
};
FlashSeen flashOf(Rig& rig, uint8_t node) {
    FlashSeen f;
    rig.onDevice(node, [&](sim::VirtualDevice& d) {
        f.version = d.programFlash().version();
        f.softwareId = d.programFlash().softwareId();
        f.status = d.programFlash().flashStatus();
        f.running = d.programFlash().running();
    });
    return f;
}
}  // namespace

class TestSvcProgram : public QObject {
    Q_OBJECT
private slots:
    void oneMebibyteByBlockStartsTheNewProgram() {
        Rig rig;
        QVERIFY(rig.useSpec(QStringLiteral("1:delta-asda-a2")));
        QVERIFY(rig.open());
        SdoClient sdo(*rig.context);
        ProgramDownload pd(*rig.context, sdo);
        const QByteArray body = payload(1024 * 1024, 1);
        ProgramDownloadRequest req;
        req.node = 1;
        req.image = sim::makeProgramImage(body, QStringLiteral("2.1.0"));
        int progress = 0;
        qint64 last = 0;
        QElapsedTimer t;
        t.start();
        const ProgramDownloadOutcome o = download(pd, req, &progress, &last);
        qInfo("1 MiB by block SDO over sim: %lld ms (transfer %.2f s), %d progress reports", t.elapsed(), o.seconds,
              progress);
        QVERIFY2(o.ok, qPrintable(o.summary()));
        QVERIFY(o.started);
        QVERIFY(!o.fellBackToSegmented);
        QCOMPARE(o.bytes, qint64(req.image.size()));
        QCOMPARE(last, qint64(req.image.size()));
        QVERIFY(progress >= 2);
        QVERIFY(o.before.version.has_value());
        QCOMPARE(o.after.version.value_or(QString()), QStringLiteral("2.1.0"));
        QCOMPARE(o.after.softwareId.value_or(0), sim::crc32(body));
        QVERIFY(o.before.softwareId.value_or(0) != o.after.softwareId.value_or(0));
        QCOMPARE(o.after.flashStatus.value_or(99), 0u);
        const FlashSeen f = flashOf(rig, 1);
        QCOMPARE(f.version, QStringLiteral("2.1.0"));
        QVERIFY(f.running);
        QVERIFY2(o.summary().contains(QStringLiteral("-> 2.1.0")), qPrintable(o.summary()));
    }

    void everyPersonalityTakesAProgram() {
        for (const QString& dict :
             {QStringLiteral("aimotor"), QStringLiteral("dexmart-dev"), QStringLiteral("generic-cia402")}) {
            Rig rig;
            QVERIFY(rig.useSpec(QStringLiteral("4:") + dict));
            QVERIFY(rig.open());
            SdoClient sdo(*rig.context);
            ProgramDownload pd(*rig.context, sdo);
            ProgramDownloadRequest req;
            req.node = 4;
            req.image = sim::makeProgramImage(payload(4096, 2), QStringLiteral("9.9"));
            const ProgramDownloadOutcome o = download(pd, req);
            QVERIFY2(o.ok, qPrintable(dict + QStringLiteral(": ") + o.summary()));
            QCOMPARE(o.after.version.value_or(QString()), QStringLiteral("9.9"));
        }
    }

    void driveAbortingHalfWayClaimsNothing() {
        Rig rig;
        QVERIFY(rig.useSpec(QStringLiteral("1:aimotor")));
        QVERIFY(rig.open());
        const FlashSeen old = flashOf(rig, 1);
        rig.onDevice(1, [](sim::VirtualDevice& d) {
            d.sdoFaults().abortDownloadAfter = std::pair{512 * 1024, sdoabort::HardwareError};
        });
        SdoClient sdo(*rig.context);
        ProgramDownload pd(*rig.context, sdo);
        ProgramDownloadRequest req;
        req.node = 1;
        req.image = sim::makeProgramImage(payload(1024 * 1024, 3), QStringLiteral("3.0"));
        const ProgramDownloadOutcome o = download(pd, req);
        QVERIFY(!o.ok);
        QVERIFY(!o.cancelled);
        QVERIFY(!o.started);
        QCOMPARE(o.step, ProgramStep::Download);
        QCOMPARE(o.abortCode, sdoabort::HardwareError);
        QVERIFY2(o.error.contains(QStringLiteral("1F50:01")), qPrintable(o.error));
        QVERIFY2(o.error.contains(QStringLiteral("06060000")), qPrintable(o.error));
        QVERIFY2(o.summary().contains(QStringLiteral("nothing claimed")), qPrintable(o.summary()));
        QVERIFY(!o.after.version.has_value());
        const FlashSeen f = flashOf(rig, 1);
        QCOMPARE(f.version, old.version);
        QCOMPARE(f.softwareId, old.softwareId);
        QVERIFY(!f.running);  // stopped for the download, and nothing started
    }

    void badCrcIsRefusedAtStart() {
        Rig rig;
        QVERIFY(rig.useSpec(QStringLiteral("2:dexmart-dev")));
        QVERIFY(rig.open());
        const FlashSeen old = flashOf(rig, 2);
        SdoClient sdo(*rig.context);
        ProgramDownload pd(*rig.context, sdo);
        ProgramDownloadRequest req;
        req.node = 2;
        req.image = sim::makeProgramImage(payload(20000, 4), QStringLiteral("4.0"));
        req.image[100] = static_cast<char>(req.image[100] ^ 0x01);  // one bit flipped in the payload
        const ProgramDownloadOutcome o = download(pd, req);
        QVERIFY(!o.ok);
        QCOMPARE(o.step, ProgramStep::Start);
        QCOMPARE(o.abortCode, sdoabort::CannotStore);
        QVERIFY2(o.error.contains(QStringLiteral("1F51:01")), qPrintable(o.error));
        QCOMPARE(o.bytes, qint64(req.image.size()));  // the data went in; the start did not
        QVERIFY(!o.started);
        const FlashSeen f = flashOf(rig, 2);
        QCOMPARE(f.status, 3u << 1);  // 1F57h: data format error (CiA 302-3)
        QCOMPARE(f.version, old.version);
        QVERIFY(!f.running);
        QCOMPARE(flashStatusText(f.status), QStringLiteral("data format error"));
    }

    void segmentedWhenChosenOrWhenBlockIsDeclined() {
        Rig rig;
        QVERIFY(rig.useSpec(QStringLiteral("1:delta-asda-a2")));
        QVERIFY(rig.open());
        SdoClient sdo(*rig.context);
        ProgramDownload pd(*rig.context, sdo);
        ProgramDownloadRequest req;
        req.node = 1;
        req.block = false;
        req.image = sim::makeProgramImage(payload(8 * 1024, 5), QStringLiteral("5.0"));
        QElapsedTimer t;
        t.start();
        ProgramDownloadOutcome o = download(pd, req);
        qInfo("8 KiB segmented over sim: transfer %.2f s (%.1f KiB/s)", o.seconds, 8.0 / std::max(o.seconds, 1e-6));
        QVERIFY2(o.ok, qPrintable(o.summary()));
        QCOMPARE(o.after.version.value_or(QString()), QStringLiteral("5.0"));

        rig.onDevice(1, [](sim::VirtualDevice& d) { d.sdoFaults().declineBlock = true; });
        req.block = true;
        req.image = sim::makeProgramImage(payload(4 * 1024, 6), QStringLiteral("6.0"));
        o = download(pd, req);
        QVERIFY2(o.ok, qPrintable(o.summary()));
        QVERIFY(o.fellBackToSegmented);
        QCOMPARE(o.after.version.value_or(QString()), QStringLiteral("6.0"));
    }

    void cancelAbortsAndRetryStartsAgain() {
        Rig rig;
        QVERIFY(rig.useSpec(QStringLiteral("1:delta-asda-a2")));
        QVERIFY(rig.open());
        SdoClient sdo(*rig.context);
        ProgramDownload pd(*rig.context, sdo);
        ProgramDownloadRequest req;
        req.node = 1;
        req.image = sim::makeProgramImage(payload(1024 * 1024, 7), QStringLiteral("7.0"));
        std::optional<ProgramDownloadOutcome> out;
        bool cancelled = false;
        pd.run(
            req, {},
            [&](qint64 done, qint64, double) {
                if (done > 0 && !cancelled) {
                    cancelled = true;
                    QMetaObject::invokeMethod(
                        &pd, [&pd] { pd.cancel(); }, Qt::QueuedConnection);  // as a click would
                }
            },
            [&](const ProgramDownloadOutcome& o) { out = o; });
        QVERIFY(waitUntil([&] { return out.has_value(); }, 30000));
        QVERIFY(!out->ok);
        QVERIFY(out->cancelled);
        QCOMPARE(out->step, ProgramStep::Download);
        QCOMPARE(out->abortCode, sdoabort::GeneralError);  // what the client sent the node
        QVERIFY(!flashOf(rig, 1).running);

        out.reset();
        pd.retry();
        QVERIFY(waitUntil([&] { return out.has_value(); }, 30000));
        QVERIFY2(out->ok, qPrintable(out->summary()));
        QCOMPARE(out->after.version.value_or(QString()), QStringLiteral("7.0"));
    }

    void driveEnabledByCoScopeIsDisabledFirst() {
        Rig rig;
        QVERIFY(rig.useSpec(QStringLiteral("1:delta-asda-a2")));
        QVERIFY(rig.open());
        rig.context->enabledDrives().noteControlword(1, 0, 0x000F);
        SdoClient sdo(*rig.context);
        ProgramDownload pd(*rig.context, sdo);
        std::vector<ProgramStep> steps;
        ProgramDownloadRequest req;
        req.node = 1;
        req.image = sim::makeProgramImage(payload(1000, 8), QStringLiteral("8.0"));
        std::optional<ProgramDownloadOutcome> out;
        pd.run(
            req, [&](ProgramStep s) { steps.push_back(s); }, {}, [&](const ProgramDownloadOutcome& o) { out = o; });
        QVERIFY(waitUntil([&] { return out.has_value(); }, 30000));
        QVERIFY2(out->ok, qPrintable(out->summary()));
        QVERIFY(rig.context->enabledDrives().isEmpty());
        QVERIFY2(out->notes.contains(QStringLiteral("node 1 disabled")), qPrintable(out->notes));
        const std::vector<ProgramStep> expected{ProgramStep::ReadBefore, ProgramStep::DisableDrive, ProgramStep::Stop,
                                                ProgramStep::Clear,      ProgramStep::Download,     ProgramStep::Start,
                                                ProgramStep::BootUp,     ProgramStep::ReadAfter,    ProgramStep::Done};
        QCOMPARE(steps, expected);
    }
};

QTEST_GUILESS_MAIN(TestSvcProgram)
#include "test_svc_program.moc"
