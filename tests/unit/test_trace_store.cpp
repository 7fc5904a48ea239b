// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/trace/TraceStore.h"

#include <QtTest>

#include <atomic>
#include <thread>

using namespace coscope;

namespace {
CanFrame makeFrame(uint32_t i) {
    CanFrame f;
    f.timestampNs = 1000 + static_cast<int64_t>(i);
    f.id = 0x180 + (i % 4);
    f.len = 8;
    for (int b = 0; b < 8; ++b) f.data[b] = static_cast<uint8_t>(i >> (b % 4 * 8));
    return f;
}
}  // namespace

class TestTraceStore : public QObject {
    Q_OBJECT
private slots:
    void recordIs24Bytes() { QCOMPARE(sizeof(TraceRecord), size_t(24)); }

    void appendsAndReadsBack() {
        TraceStore store;
        QVERIFY(store.empty());
        for (uint32_t i = 0; i < 200000; ++i) QCOMPARE(store.append(makeFrame(i)), FrameNo(i));
        QCOMPARE(store.size(), size_t(200000));
        // Across chunk boundaries (65536 records per chunk) frames keep their numbers.
        for (uint32_t i : {0u, 65535u, 65536u, 131071u, 199999u}) {
            const CanFrame f = store.frame(i);
            QCOMPARE(f, makeFrame(i));
        }
    }

    void keepsEveryKindOfFrame() {
        TraceStore store;
        auto ext = parseCansend(u"1ABCDEF0#0102", nullptr);
        auto rtr = parseCansend(u"701#R1", nullptr);
        auto fd = parseCansend(QStringLiteral("123##3") + QString(128, u'5'), nullptr);
        QVERIFY(ext && rtr && fd);
        CanFrame err;
        err.flags = CanFrame::Error;
        err.id = 0x4;
        err.len = 8;
        err.data[1] = 0x10;
        CanFrame tx = CanFrame::classic(0x601, {0x40, 0x00, 0x10, 0x00});
        tx.flags |= CanFrame::Tx;
        tx.bus = 3;
        for (const CanFrame& f : {*ext, *rtr, *fd, err, tx}) store.append(f);
        QCOMPARE(store.frame(0), *ext);
        QCOMPARE(store.frame(1), *rtr);
        QCOMPARE(store.payload(1).size(), size_t(0));
        QCOMPARE(store.frame(2), *fd);
        QCOMPARE(store.payload(2).size(), size_t(64));
        QCOMPARE(store.payload(2)[63], uint8_t(0x55));
        QCOMPARE(store.frame(3), err);
        QCOMPARE(store.frame(4), tx);
        QCOMPARE(store.frame(4).bus, 3);
    }

    void fdPayloadsSpanArenaChunks() {
        TraceStore store;
        // 1 MiB FD chunks: 20000 frames of 64 bytes cross at least one boundary.
        for (int i = 0; i < 20000; ++i) {
            CanFrame f;
            f.id = 0x100;
            f.flags = CanFrame::Fd;
            f.len = 64;
            for (int b = 0; b < 64; ++b) f.data[b] = static_cast<uint8_t>(i + b);
            store.append(f);
        }
        for (int i : {0, 16383, 16384, 19999}) {
            const auto p = store.payload(static_cast<FrameNo>(i));
            QCOMPARE(p.size(), size_t(64));
            QCOMPARE(p[0], static_cast<uint8_t>(i));
            QCOMPARE(p[63], static_cast<uint8_t>(i + 63));
        }
    }

    void indexesByCobId() {
        TraceStore store;
        for (uint32_t i = 0; i < 10000; ++i) store.append(makeFrame(i));
        store.append(*parseCansend(u"00000181#01", nullptr));  // extended 181 is another key
        QCOMPARE(store.countFor(TraceStore::keyOf(0x181, false)), size_t(2500));
        QCOMPARE(store.frameFor(TraceStore::keyOf(0x181, false), 0), FrameNo(1));
        QCOMPARE(store.frameFor(TraceStore::keyOf(0x181, false), 2499), FrameNo(9997));
        QCOMPARE(store.countFor(TraceStore::keyOf(0x181, true)), size_t(1));
        QCOMPARE(store.frameFor(TraceStore::keyOf(0x181, true), 0), FrameNo(10000));
        QCOMPARE(store.countFor(TraceStore::keyOf(0x700, false)), size_t(0));
        const auto keys = store.keys();
        QCOMPARE(keys.size(), size_t(5));
        QCOMPARE(keys.front(), 0x180u);
        const auto frames = store.framesFor(TraceStore::keyOf(0x183, false));
        QCOMPARE(frames.size(), size_t(2500));
        for (FrameNo n : frames) QCOMPARE(store.record(n).id, 0x183u);
    }

    void staysWithinMemoryBudget() {
        TraceStore store;
        const uint32_t n = 1u << 20;
        for (uint32_t i = 0; i < n; ++i) store.append(makeFrame(i));
        const double perFrame = static_cast<double>(store.memoryBytes()) / n;
        QVERIFY2(perFrame <= 32.0, qPrintable(QString::number(perFrame)));
    }

    // One writer appends while readers read: every frame a reader can see is complete and in
    // order, and the per-COB-ID index never points past size().
    void concurrentAppendAndRead() {
        TraceStore store;
        const uint32_t total = 600000;
        std::atomic<bool> done{false};
        std::atomic<int> bad{0};
        std::thread writer([&] {
            for (uint32_t i = 0; i < total; ++i) store.append(makeFrame(i));
            done = true;
        });
        auto reader = [&] {
            while (!done.load()) {
                const size_t n = store.size();
                if (n == 0) continue;
                const auto i = static_cast<FrameNo>(n - 1);
                if (!(store.frame(i) == makeFrame(i))) ++bad;
                const uint32_t key = TraceStore::keyOf(0x180 + (i % 4), false);
                const size_t c = store.countFor(key);
                if (c && store.frameFor(key, c - 1) >= store.size()) ++bad;
            }
        };
        std::thread r1(reader), r2(reader);
        writer.join();
        r1.join();
        r2.join();
        QCOMPARE(bad.load(), 0);
        QCOMPARE(store.size(), size_t(total));
    }
};

QTEST_GUILESS_MAIN(TestTraceStore)
#include "test_trace_store.moc"
