// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/can/FrameRing.h"

#include <QtTest>

#include <thread>

using namespace coscope;

class TestFrameRing : public QObject {
    Q_OBJECT
private slots:
    void fullRingCountsDrops() {
        FrameRing ring(8);
        QCOMPARE(ring.capacity(), size_t(8));
        for (int i = 0; i < 10; ++i) ring.push(CanFrame::classic(static_cast<uint32_t>(i), {}));
        QCOMPARE(ring.size(), size_t(8));
        QCOMPARE(ring.dropped(), uint64_t(2));
        CanFrame out[16];
        QCOMPARE(ring.pop(out, 16), size_t(8));
        QCOMPARE(out[0].id, 0u);
        QCOMPARE(out[7].id, 7u);  // the oldest are kept, the newest beyond capacity are the drops
        QCOMPARE(ring.pop(out, 16), size_t(0));
    }
    void producerAndConsumerThreads() {
        FrameRing ring(1024);
        const uint32_t total = 500000;
        uint64_t received = 0;
        uint32_t expect = 0;
        bool ordered = true;
        std::thread producer([&] {
            for (uint32_t i = 0; i < total; ++i)
                while (!ring.push(CanFrame::classic(i & 0x7FF, {static_cast<uint8_t>(i), static_cast<uint8_t>(i >> 8),
                                                                static_cast<uint8_t>(i >> 16)}))) {}
        });
        CanFrame buf[256];
        while (received < total) {
            const size_t n = ring.pop(buf, 256);
            for (size_t k = 0; k < n; ++k) {
                const uint32_t v = buf[k].data[0] | (buf[k].data[1] << 8) | (buf[k].data[2] << 16);
                if (v != (expect & 0xFFFFFF)) ordered = false;
                ++expect;
            }
            received += n;
        }
        producer.join();
        QVERIFY(ordered);
        QCOMPARE(received, uint64_t(total));
    }
};

QTEST_GUILESS_MAIN(TestFrameRing)
#include "test_frame_ring.moc"
