// SPDX-License-Identifier: GPL-3.0-or-later
// GuardedDrives on the virtual drives (issue 35 "Safety edges"): a drive CoScope enabled asks
// once for consent; with it, CoScope's heartbeat starts (node 127, 100 ms) and the drive's
// 1016h/6007h watch it; the drive leaving the record (disabled) gets its old values back and the
// heartbeat it started stops. When the bus closes: putBackDirect() writes the old values straight
// on the bus for a drive whose Disable voltage was confirmed, and leaves them for one whose
// Disable was not (it then stops by itself when the heartbeat stops). Listen-only: no guard.
#include "SvcTestRig.h"

#include "core/canopen/DriveDisable.h"
#include "core/canopen/GuardedDrives.h"
#include "core/canopen/HeartbeatProducer.h"
#include "core/canopen/SdoClient.h"
#include "core/sim/VirtualDevice.h"

#include <QSignalSpy>
#include <QtTest>

using namespace coscope;
using namespace coscope::canopen;
using namespace svctest;

namespace {
constexpr uint32_t kArmed = 0x007F012C;  // node 127, 300 ms (CiA 301 §7.5.2.18)

uint64_t value(Rig& rig, uint8_t node, uint16_t index, uint8_t sub) {
    uint64_t v = ~uint64_t(0);
    rig.onDevice(node, [&](sim::VirtualDevice& d) {
        if (auto x = d.value(index, sub)) v = x->toUInt64().value_or(~uint64_t(0));
    });
    return v;
}

struct Bench {
    Rig rig;
    std::unique_ptr<SdoClient> sdo;
    std::unique_ptr<HeartbeatProducer> heartbeat;
    std::unique_ptr<GuardedDrives> guards;
    bool open(const QString& url = QStringLiteral("sim://")) {
        if (!rig.useSpec(QStringLiteral("3:generic-cia402")) || !rig.open(url)) return false;
        sdo = std::make_unique<SdoClient>(*rig.context);
        heartbeat = std::make_unique<HeartbeatProducer>(*rig.context);
        guards = std::make_unique<GuardedDrives>(*rig.context, *sdo, *heartbeat);
        return true;
    }
    bool armed() { return value(rig, 3, 0x1016, 1) == kArmed && value(rig, 3, 0x6007, 0) == 3; }
};
}  // namespace

class TestSvcGuardedDrives : public QObject {
    Q_OBJECT
private slots:
    void consentArmsAndDisablePutsBack() {
        Bench b;
        QVERIFY(b.open());
        QSignalSpy asked(b.guards.get(), &GuardedDrives::consentNeeded);
        b.rig.context->enabledDrives().noteControlword(3, 0, 0x0006);  // Shutdown went to node 3
        b.guards->poll();
        QCOMPARE(asked.count(), 1);
        b.guards->poll();
        QCOMPARE(asked.count(), 1);  // once
        QVERIFY(!b.heartbeat->isRunning());
        b.guards->consent(3, true);
        QVERIFY(b.heartbeat->isRunning());
        QCOMPARE(b.heartbeat->nodeId(), uint8_t(127));
        QCOMPARE(b.heartbeat->periodMs(), uint16_t(100));
        QTRY_VERIFY_WITH_TIMEOUT(b.armed(), 5000);
        QCOMPARE(b.guards->guardedNodes(), std::vector<uint8_t>{3});
        QVERIFY(b.guards->holdsHeartbeat());
        // Disabled: off the record; the old values back, the heartbeat stops.
        b.rig.context->enabledDrives().noteControlword(3, 0, 0x0000);
        b.guards->poll();
        QTRY_VERIFY_WITH_TIMEOUT(value(b.rig, 3, 0x1016, 1) == 0 && value(b.rig, 3, 0x6007, 0) == 1, 5000);
        QTRY_VERIFY_WITH_TIMEOUT(!b.heartbeat->isRunning(), 2000);
        QVERIFY(b.guards->guardedNodes().empty());
        // Enabled again: the node's answer holds, no question.
        b.rig.context->enabledDrives().noteControlword(3, 0, 0x0006);
        b.guards->poll();
        QCOMPARE(asked.count(), 1);
        QTRY_VERIFY_WITH_TIMEOUT(b.armed(), 5000);
    }

    void closingPutsBackOnlyWhenDisableWasConfirmed() {
        for (bool confirmed : {true, false}) {
            Bench b;
            QVERIFY(b.open());
            b.rig.context->enabledDrives().noteControlword(3, 0, 0x000F);
            b.guards->poll();
            b.guards->consent(3, true);
            QTRY_VERIFY_WITH_TIMEOUT(b.armed(), 5000);
            auto putBack = b.guards->takePutBack();
            QCOMPARE(putBack.size(), size_t(1));
            QCOMPARE(putBack[0].writes.size(), size_t(2));  // 1016h:01, then 6007h
            b.guards.reset();
            b.sdo.reset();
            DriveDisableOutcome disabled;
            disabled.drives.push_back({EnabledDrives::Drive{3, 0, 0x000F}, true, true, confirmed,
                                       confirmed ? QString() : QStringLiteral("no answer")});
            const auto out = putBackDirect(*b.rig.context, std::move(putBack), disabled, 500);
            QCOMPARE(out.size(), size_t(1));
            QCOMPARE(out[0].putBack, confirmed);
            QCOMPARE(out[0].keptArmed, !confirmed);
            if (confirmed) {
                QVERIFY2(value(b.rig, 3, 0x1016, 1) == 0 && value(b.rig, 3, 0x6007, 0) == 1, qPrintable(out[0].text));
            } else {
                QVERIFY2(out[0].text.contains(QStringLiteral("stops by itself")), qPrintable(out[0].text));
                QVERIFY(b.armed());
            }
        }
    }

    void listenOnlyGuardsNothing() {
        Bench b;
        QVERIFY(b.open(QStringLiteral("sim://?listen-only=1")));
        QSignalSpy asked(b.guards.get(), &GuardedDrives::consentNeeded);
        QSignalSpy changed(b.guards.get(), &GuardedDrives::changed);
        b.rig.context->enabledDrives().noteControlword(3, 0, 0x0006);
        b.guards->poll();
        QCOMPARE(asked.count(), 0);
        QCOMPARE(changed.count(), 1);
        QVERIFY(changed[0][3].toString().contains(QStringLiteral("listen-only")));
        QVERIFY(!b.heartbeat->isRunning());
    }
};

QTEST_GUILESS_MAIN(TestSvcGuardedDrives)
#include "test_svc_guarded_drives.moc"
