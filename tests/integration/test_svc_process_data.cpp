// SPDX-License-Identifier: GPL-3.0-or-later
// Process data (issue 35): the AIMOTOR's RPDOs as its dictionary maps them by default
// (extract-aimotor §2 object table: RPDO1 = 6040h/16, 6060h/8, 607Ah/32 at 200h + node; RPDO2 =
// 60FFh/32, 6071h/16 at 300h + node, transmission type 1 = applied at the next SYNC) composed
// LSB first at their bit offsets (CiA 301 §7.2.2, §7.5.2.36); motion sent only while hold to run
// is fed, the stopped values (halt, velocity 0) after it; with each SYNC right after the SYNC
// frame; and the virtual drive turning on RPDO2's target velocity and stopping after release.
#include "SvcTestRig.h"

#include "core/canopen/Ds402Controller.h"
#include "core/canopen/ProcessData.h"
#include "core/canopen/ServiceWait.h"
#include "core/canopen/SyncProducer.h"
#include "core/sim/Ds402Drive.h"
#include "eds/DictionaryLibrary.h"

#include <QtTest>

using namespace coscope;
using namespace coscope::canopen;
using namespace svctest;

namespace {
constexpr uint8_t kAimotor = 2;
constexpr uint8_t kObserver = 100;

QByteArray payload(const CanFrame& f) { return bytesOf(f); }

struct ProcessRig {
    Rig rig;
    ScriptedNode* observer = nullptr;
    eds::DictionaryPtr dictionary;
    std::unique_ptr<SyncProducer> sync;
    std::unique_ptr<ProcessData> data;

    bool open() {
        QString error;
        if (!rig.useSpec(QStringLiteral("2:aimotor"), &error)) return false;
        observer = rig.addNode(kObserver);
        if (!rig.open()) return false;
        dictionary = eds::DictionaryLibrary::shared().loadShared(QStringLiteral("aimotor"), nullptr, &error);
        if (!dictionary) return false;
        sync = std::make_unique<SyncProducer>(*rig.context);
        data = std::make_unique<ProcessData>(*rig.context, *sync);
        return data->setNode(kAimotor, *dictionary, &error);
    }
    // Frames on the bus with this id, as the observer node saw them.
    std::vector<CanFrame> seen(uint32_t id) { return observer->seen(id); }
    double velocity() {
        double v = 0;
        rig.onDevice(kAimotor, [&](sim::VirtualDevice& d) { v = d.drive(0)->velocity(); });
        return v;
    }
    ds402::State state() {
        ds402::State s = ds402::State::Unknown;
        rig.onDevice(kAimotor, [&](sim::VirtualDevice& d) { s = d.drive(0)->state(); });
        return s;
    }
};
}  // namespace

class TestSvcProcessData : public QObject {
    Q_OBJECT
private slots:
    void aimotorDefaultLayout() {
        ProcessRig r;
        QVERIFY(r.open());
        const ProcessDataPdo* rpdo1 = r.data->pdo(1);
        QVERIFY(rpdo1);
        QCOMPARE(rpdo1->layout.canId(), 0x202u);
        QCOMPARE(int(rpdo1->objects.size()), 3);
        QCOMPARE(rpdo1->objects[0].entry.index, uint16_t(0x6040));
        QCOMPARE(rpdo1->objects[1].bitOffset, 16);
        QCOMPARE(rpdo1->objects[2].bitOffset, 24);
        QVERIFY(rpdo1->objects[2].isSigned);  // 607Ah INTEGER32
        QVERIFY(rpdo1->carriesMotion());
        const ProcessDataPdo* rpdo2 = r.data->pdo(2);
        QVERIFY(rpdo2);
        QCOMPARE(rpdo2->layout.canId(), 0x302u);
        QCOMPARE(rpdo2->bytes(), 6);
        QVERIFY(!r.data->pdo(3));  // unmapped by default
    }

    void composesRpdo1Bytes() {
        ProcessRig r;
        QVERIFY(r.open());
        QVERIFY(r.rig.context->enabledDrives().isEmpty());
        QVERIFY(r.data->setValue(0x6040, 0, 0x000F));
        // A controlword that enables voltage is in the bus's record before it can be sent: the
        // bus does not close with the drive left enabled.
        QCOMPARE(r.rig.context->enabledDrives().drives().size(), size_t(1));
        QCOMPARE(int(r.rig.context->enabledDrives().drives()[0].node), 2);
        QVERIFY(r.data->setValue(0x6060, 0, 3));
        QVERIFY(r.data->setValue(0x607A, 0, 1000));
        CanFrame f = r.data->frame(1);
        QCOMPARE(f.id, 0x202u);
        QCOMPARE(payload(f), hex("0f0003e8030000"));
        QVERIFY(r.data->setValue(0x607A, 0, -2));
        QCOMPARE(payload(r.data->frame(1)), hex("0f0003feffffff"));
        // Not held: the controlword gets halt (bit 8), the position is kept.
        QCOMPARE(payload(r.data->frame(1, false)), hex("0f0103feffffff"));
        QVERIFY(r.data->setValue(0x60FF, 0, -1500));
        QVERIFY(r.data->setValue(0x6071, 0, 100));
        QCOMPARE(payload(r.data->frame(2)), hex("24faffff6400"));
        QCOMPARE(payload(r.data->frame(2, false)), hex("000000000000"));  // velocity and torque 0
        QString error;
        QVERIFY(!r.data->setValue(0x6060, 0, 200, &error));  // INTEGER8
        QVERIFY(error.contains(QStringLiteral("8 mapped bits")));
        QVERIFY(!r.data->setValue(0x6041, 0, 1, &error));
        QVERIFY(error.contains(QStringLiteral("not mapped")));
    }

    // The drive's present values fill the RPDO objects (readValues), but a value the user set
    // while that read was still running stays as the user set it.
    void readValuesKeepsWhatTheUserSetMeanwhile() {
        ProcessRig r;
        QVERIFY(r.open());
        r.rig.onDevice(kAimotor, [](sim::VirtualDevice& d) {
            QVERIFY(d.setValue(0x6060, 0, od::Value::signedInt(1)));  // profile position
            QVERIFY(d.setValue(0x607A, 0, od::Value::signedInt(1234)));
        });
        SdoClient sdo(*r.rig.context);
        bool done = false;
        QStringList failed;
        r.data->readValues(sdo, [&](const QStringList& f) {
            failed = f;
            done = true;
        });
        QVERIFY(r.data->setValue(0x607A, 0, -7));  // typed before the read's answers came
        QTRY_VERIFY_WITH_TIMEOUT(done, 5000);
        QVERIFY2(failed.isEmpty(), qPrintable(failed.join(u'\n')));
        QCOMPARE(r.data->value(0x6060, 0).value_or(0), int64_t(1));   // read from the drive
        QCOMPARE(r.data->value(0x607A, 0).value_or(0), int64_t(-7));  // the user's, not 1234
    }

    void motionOnlyWhileHeld() {
        ProcessRig r;
        QVERIFY(r.open());
        QVERIFY(r.data->setValue(0x60FF, 0, 1000));
        r.data->setMode(ProcessData::Mode::Once);
        QString error;
        QVERIFY(!r.data->start(&error));  // both RPDOs carry motion objects
        QTest::qWait(50);
        QVERIFY(r.seen(0x302).empty());
        r.data->feedHold();
        QVERIFY(QTest::qWaitFor([&] { return r.seen(0x302).size() == 1; }, 2000));
        QCOMPARE(payload(r.seen(0x302)[0]), hex("e80300000000"));
        r.data->releaseHold();
        QVERIFY(QTest::qWaitFor([&] { return r.seen(0x302).size() == 2; }, 2000));
        QCOMPARE(payload(r.seen(0x302)[1]), hex("000000000000"));
        QCOMPARE(payload(r.seen(0x202)[1]), hex("00010000000000"));  // halt
    }

    void periodicStopsWhenNotFed() {
        ProcessRig r;
        QVERIFY(r.open());
        r.data->setEnabled(1, false);
        QVERIFY(r.data->setValue(0x60FF, 0, 77));
        r.data->setMode(ProcessData::Mode::Every, 20);
        QVERIFY(r.data->start());
        QTest::qWait(100);
        QVERIFY(r.seen(0x302).empty());  // not held: nothing
        bool expired = false;
        connect(r.data.get(), &ProcessData::holdExpired, this, [&] { expired = true; });
        QElapsedTimer t;
        t.start();
        while (t.elapsed() < 300) {
            r.data->feedHold();
            QTest::qWait(50);
        }
        const size_t whileHeld = r.seen(0x302).size();
        QVERIFY2(whileHeld >= 10 && whileHeld <= 18, qPrintable(QString::number(whileHeld)));
        QVERIFY(QTest::qWaitFor([&] { return expired; }, 1000));
        QTest::qWait(100);
        const auto frames = r.seen(0x302);
        QCOMPARE(payload(frames.back()), hex("000000000000"));
        QCOMPARE(payload(frames[frames.size() - 2]), hex("4d0000000000"));
        QTest::qWait(200);
        QCOMPARE(r.seen(0x302).size(), frames.size());  // the periodic send stopped
        QVERIFY(r.seen(0x202).empty());                 // RPDO1 was not chosen
        r.data->stop();
    }

    void withEachSync() {
        ProcessRig r;
        QVERIFY(r.open());
        r.sync->setPeriodUs(10000);
        QVERIFY(r.sync->start());
        r.data->setMode(ProcessData::Mode::WithSync);
        QVERIFY(r.data->start());
        r.data->feedHold();
        QTest::qWait(120);
        r.data->feedHold();
        QTest::qWait(120);
        r.data->stop();
        r.sync->stop();
        const size_t pdos = r.seen(0x302).size();
        const size_t syncs = r.seen(0x80).size();
        QVERIFY2(syncs >= 15 && pdos + 2 >= syncs && pdos <= syncs + 1,
                 qPrintable(QStringLiteral("%1 %2").arg(syncs).arg(pdos)));
    }

    void driveTurnsOnRpdo2() {
        ProcessRig r;
        QVERIFY(r.open());
        QString error;
        QVERIFY(
            r.rig.context->send(CanFrame::classic(0x000, {0x01, kAimotor}), &error));  // NMT start (CiA 301 §7.2.8.3.1)
        SdoClient sdo(*r.rig.context);
        Ds402Controller ctl(sdo, kAimotor);
        auto mode =
            waitForResult<Ds402Result>([&](Ds402Callback cb) { ctl.setMode(3, cb); }, 5000);  // profile velocity
        QVERIFY(mode && mode->ok);
        auto en = waitForResult<Ds402Result>([&](Ds402Callback cb) { ctl.enable(cb); }, 5000);
        QVERIFY2(en && en->ok, en ? qPrintable(en->error) : "no result");
        QVERIFY(r.data->setValue(0x6040, 0, 0x000F));
        QVERIFY(r.data->setValue(0x6060, 0, 3));
        QVERIFY(r.data->setValue(0x60FF, 0, 20000));
        r.sync->setPeriodUs(10000);
        QVERIFY(r.sync->start());
        r.data->setMode(ProcessData::Mode::WithSync);
        QVERIFY(r.data->start());
        QElapsedTimer t;
        t.start();
        bool moved = false;
        while (t.elapsed() < 1500 && !moved) {
            r.data->feedHold();
            QTest::qWait(50);
            moved = r.velocity() > 1000;
        }
        QVERIFY2(moved, qPrintable(QString::number(r.velocity())));
        r.data->releaseHold();
        QVERIFY2(QTest::qWaitFor([&] { return std::abs(r.velocity()) < 1; }, 3000),
                 qPrintable(QString::number(r.velocity())));
        QCOMPARE(r.state(), ds402::State::OperationEnabled);  // halted, not disabled
        r.data->stop();
        r.sync->stop();
    }
};

QTEST_GUILESS_MAIN(TestSvcProcessData)
#include "test_svc_process_data.moc"
