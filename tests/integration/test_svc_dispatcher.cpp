// SPDX-License-Identifier: GPL-3.0-or-later
// FrameDispatcher: only the COB-IDs a service waits for leave the ingest thread, batched, on the
// subscriber's thread; own Tx echoes, extended and error frames never; nothing after unsubscribe.
#include "core/canopen/FrameDispatcher.h"
#include "core/canopen/ServiceWait.h"

#include <QThread>
#include <QtTest>

#include <thread>

using namespace coscope;
using namespace coscope::canopen;

class TestSvcDispatcher : public QObject {
    Q_OBJECT
private slots:
    void filtersAndBatchesOnSubscriberThread() {
        FrameDispatcher d;
        QObject ctx;
        std::vector<CanFrame> got;
        int calls = 0;
        QThread* seenOn = nullptr;
        const int id = d.subscribe(&ctx, {0x585, 0x7E4}, [&](const std::vector<CanFrame>& f) {
            ++calls;
            seenOn = QThread::currentThread();
            got.insert(got.end(), f.begin(), f.end());
        });
        QVERIFY(id > 0);
        std::vector<CanFrame> batch;
        for (uint32_t i = 0; i < 1000; ++i) batch.push_back(CanFrame::classic(0x181 + (i % 5), {1, 2}));
        batch.push_back(CanFrame::classic(0x585, {0x43}));
        CanFrame tx = CanFrame::classic(0x585, {0x99});
        tx.flags |= CanFrame::Tx;
        batch.push_back(tx);
        batch.push_back(CanFrame::classic(0x585, {0x44}, true));  // extended 585h: not ours
        batch.push_back(CanFrame::classic(0x7E4, {0x5E, 3}));
        std::thread ingest([&] { d.dispatch(batch.data(), batch.size()); });
        ingest.join();
        QVERIFY(waitUntil([&] { return calls > 0; }, 2000));
        QCOMPARE(calls, 1);  // one hand-over for the batch
        QCOMPARE(seenOn, QThread::currentThread());
        QCOMPARE(got.size(), size_t(2));
        QCOMPARE(got[0].data[0], uint8_t(0x43));
        QCOMPARE(got[1].id, 0x7E4u);

        // A batch with nothing wanted posts nothing.
        std::vector<CanFrame> noise(100, CanFrame::classic(0x181, {}));
        d.dispatch(noise.data(), noise.size());
        QTest::qWait(20);
        QCOMPARE(calls, 1);

        // Posted but not yet delivered, then unsubscribed: dropped.
        CanFrame late = CanFrame::classic(0x585, {0x60});
        d.dispatch(&late, 1);
        d.unsubscribe(id);
        QTest::qWait(20);
        QCOMPARE(calls, 1);
    }

    void changingIds() {
        FrameDispatcher d;
        QObject ctx;
        int n = 0;
        const int id = d.subscribe(&ctx, {}, [&](const std::vector<CanFrame>& f) { n += int(f.size()); });
        CanFrame f = CanFrame::classic(0x581, {0});
        d.dispatch(&f, 1);
        QTest::qWait(10);
        QCOMPARE(n, 0);
        d.setCobIds(id, {0x581});
        d.dispatch(&f, 1);
        QVERIFY(waitUntil([&] { return n == 1; }, 1000));
    }
};

QTEST_GUILESS_MAIN(TestSvcDispatcher)
#include "test_svc_dispatcher.moc"
