// SPDX-License-Identifier: GPL-3.0-or-later
// PeriodicSender, the one scheduler of a bus's periodic frames, against a recording sink: due
// times on an absolute grid (never early, no drift), a count that ends the job, skipping instead
// of bursting after a stall, period changes, a failed send stopping its job, the first send's
// failure refusing add(), and remove() waiting for a running callback.
#include "core/canopen/PeriodicSender.h"

#include <QtTest>

#include <atomic>
#include <chrono>
#include <mutex>
#include <thread>

using namespace coscope;
using namespace coscope::canopen;

namespace {

int64_t monoNs() {
    return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now().time_since_epoch())
        .count();
}

// Records when each frame was "sent"; optionally stalls or fails on a given frame.
struct Sink {
    std::mutex mutex;
    std::vector<std::pair<uint32_t, int64_t>> sent;  // id, CLOCK_MONOTONIC ns
    std::atomic<int> failOn{-1};                     // index of the frame that fails
    std::atomic<int> stallOn{-1};                    // index of the frame that takes stallMs
    int stallMs = 0;

    PeriodicSender::SendFunction function() {
        return [this](const CanFrame& f, QString* error) {
            std::lock_guard lock(mutex);
            const int index = static_cast<int>(sent.size());
            if (index == failOn) {
                if (error) *error = QStringLiteral("bus test is listen-only: sending is refused");
                return false;
            }
            if (index == stallOn) std::this_thread::sleep_for(std::chrono::milliseconds(stallMs));
            sent.emplace_back(f.id, monoNs());
            return true;
        };
    }
    std::vector<int64_t> times(uint32_t id) {
        std::lock_guard lock(mutex);
        std::vector<int64_t> out;
        for (auto& [i, t] : sent)
            if (i == id) out.push_back(t);
        return out;
    }
};

PeriodicSender::Job job(uint32_t id, int64_t periodNs, uint64_t count = 0) {
    PeriodicSender::Job j;
    j.frame = CanFrame::classic(id, {0x11, 0x22});
    j.periodNs = periodNs;
    j.count = count;
    return j;
}

constexpr int64_t kMs = 1'000'000;

}  // namespace

class TestPeriodicSender : public QObject {
    Q_OBJECT
private slots:
    void countEndsTheJobOnTheGrid() {
        Sink sink;
        PeriodicSender sender(sink.function());
        std::atomic<int> stopped{0};
        QString stopError = QStringLiteral("not called");
        auto j = job(0x181, 5 * kMs, 20);
        j.onStopped = [&](const QString& e) {
            stopError = e;
            ++stopped;
        };
        const int64_t before = monoNs();
        QString error;
        const auto id = sender.add(j, &error);
        QVERIFY2(id != 0, qPrintable(error));
        QVERIFY(!sink.times(0x181).empty());  // add() returns after the first send
        QTRY_VERIFY_WITH_TIMEOUT(!sender.status(id).running, 5000);
        const auto s = sender.status(id);
        QVERIFY(s.exists);
        QCOMPARE(s.sent, uint64_t(20));
        QVERIFY(s.error.isEmpty());
        QCOMPARE(stopped.load(), 1);
        QVERIFY(stopError.isEmpty());
        // Every frame k goes out at or after the grid's origin + k x period (absolute due times:
        // never early, never a burst); a late one skips due times, counted. The origin is at or
        // after `before`; the first frame's own time may be late (a loaded machine), so frame 1
        // less than a period after frame 0 is right when frame 0 was late.
        const auto t = sink.times(0x181);
        QCOMPARE(t.size(), size_t(20));
        QVERIFY(t[0] >= before);
        for (size_t k = 1; k < t.size(); ++k)
            QVERIFY2(
                t[k] - before >= static_cast<int64_t>(k) * 5 * kMs,
                qPrintable(QStringLiteral("frame %1 early: %2 us after the start").arg(k).arg((t[k] - before) / 1000)));
        // No drift: on an idle machine the 20th frame is due at 95 ms; late only by skips.
        const auto st = sender.status(id);
        QVERIFY2(t.back() - t[0] < static_cast<int64_t>(19 + st.skipped + 1) * 5 * kMs,
                 qPrintable(QString::number((t.back() - t[0]) / 1000)));
        QCOMPARE(sender.runningCount(), 0);
        QVERIFY(sender.remove(id));
        QVERIFY(!sender.status(id).exists);
        QVERIFY(!sender.remove(id));
    }

    void stallSkipsInsteadOfBursting() {
        Sink sink;
        sink.stallOn = 3;
        sink.stallMs = 37;  // more than three periods
        PeriodicSender sender(sink.function());
        const auto id = sender.add(job(0x200, 10 * kMs, 8));
        QVERIFY(id);
        QTRY_VERIFY_WITH_TIMEOUT(!sender.status(id).running, 5000);
        const auto t = sink.times(0x200);
        QCOMPARE(t.size(), size_t(8));
        for (size_t k = 1; k < t.size(); ++k)
            QVERIFY2(t[k] - t[k - 1] >= 5 * kMs, qPrintable(QStringLiteral("frames %1 and %2 only %3 us apart")
                                                                .arg(k - 1)
                                                                .arg(k)
                                                                .arg((t[k] - t[k - 1]) / 1000)));
        QVERIFY2(sender.status(id).skipped >= 2, qPrintable(QString::number(sender.status(id).skipped)));
    }

    void failedSendStopsTheJobWithItsError() {
        Sink sink;
        sink.failOn = 3;
        PeriodicSender sender(sink.function());
        QString stopError;
        auto j = job(0x300, 2 * kMs);
        j.onStopped = [&](const QString& e) { stopError = e; };
        const auto id = sender.add(j);
        QVERIFY(id);
        QTRY_VERIFY_WITH_TIMEOUT(!sender.status(id).running, 5000);
        QCOMPARE(sender.status(id).sent, uint64_t(3));
        QVERIFY(sender.status(id).error.contains(QStringLiteral("listen-only")));
        QCOMPARE(stopError, sender.status(id).error);
    }

    void firstSendRefusedMeansNoJob() {
        Sink sink;
        sink.failOn = 0;
        PeriodicSender sender(sink.function());
        QString error;
        QCOMPARE(sender.add(job(0x80, 10 * kMs), &error), PeriodicSender::JobId(0));
        QVERIFY2(error.contains(QStringLiteral("listen-only")), qPrintable(error));
        QVERIFY(sender.jobs().empty());
        QCOMPARE(sender.add(job(0x80, 0), &error), PeriodicSender::JobId(0));
        QVERIFY(error.contains(QStringLiteral("period")));
    }

    void periodChangesAndRounding() {
        Sink sink;
        PeriodicSender sender(sink.function());
        auto id = sender.add(job(0x400, 1'499));  // rounds to whole µs
        QVERIFY(id);
        QCOMPARE(sender.status(id).periodNs, int64_t(1000));
        QVERIFY(sender.setPeriod(id, 20 * kMs));
        QCOMPARE(sender.status(id).periodNs, 20 * kMs);
        const size_t before = sink.times(0x400).size();
        const int64_t start = monoNs();
        QTest::qWait(110);
        const size_t during = sink.times(0x400).size() - before;
        // About 5 in 110 ms; a loaded machine may wait longer, never more than one per 20 ms
        // (at 1 µs it would be thousands).
        const auto most = static_cast<size_t>((monoNs() - start) / (20 * kMs) + 1);
        QVERIFY2(during >= 1 && during <= most, qPrintable(QStringLiteral("%1, at most %2").arg(during).arg(most)));
        QVERIFY(!sender.setPeriod(id, 0));
        QVERIFY(!sender.setPeriod(9999, kMs));
        sender.removeAll();
        QVERIFY(sender.jobs().empty());
        // Ids are never reused.
        const auto next = sender.add(job(0x401, kMs, 1));
        QVERIFY(next > id);
    }

    void removeWaitsForARunningCallback() {
        Sink sink;
        PeriodicSender sender(sink.function());
        std::atomic<int> inside{0};
        std::atomic<int> calls{0};
        auto j = job(0x500, 2 * kMs);
        j.afterSend = [&](const CanFrame&, uint64_t) {
            ++inside;
            ++calls;
            std::this_thread::sleep_for(std::chrono::milliseconds(15));
            --inside;
        };
        const auto id = sender.add(j);
        QVERIFY(id);
        QTRY_VERIFY_WITH_TIMEOUT(inside.load() == 1, 5000);
        QVERIFY(sender.remove(id));
        QCOMPARE(inside.load(), 0);  // remove() returned after the callback ended
        const int n = calls;
        QTest::qWait(30);
        QCOMPARE(calls.load(), n);  // and none ran after it
    }

    void aJobMayRemoveItselfFromItsHook() {
        Sink sink;
        PeriodicSender sender(sink.function());
        std::atomic<PeriodicSender::JobId> self{0};
        auto j = job(0x600, 2 * kMs);
        j.afterSend = [&](const CanFrame&, uint64_t sent) {
            if (sent == 3) sender.remove(self);
        };
        // The hook needs the id: the job starts with a first send before add() returns, so
        // removing from the 3rd send is safe.
        self = sender.add(j);
        QVERIFY(self.load());
        QTRY_VERIFY_WITH_TIMEOUT(!sender.status(self).exists, 5000);
        QTest::qWait(20);
        QCOMPARE(sink.times(0x600).size(), size_t(3));
    }

    void makerRunsOnTheSenderThread() {
        Sink sink;
        PeriodicSender sender(sink.function());
        std::atomic<bool> elsewhere{false};
        const auto main = std::this_thread::get_id();
        std::atomic<uint8_t> n{0};
        auto j = job(0x700, kMs, 4);
        j.maker = [&] {
            if (std::this_thread::get_id() != main) elsewhere = true;
            return CanFrame::classic(0x700, {++n});
        };
        QVERIFY(sender.add(j));
        QTRY_COMPARE_WITH_TIMEOUT(sink.times(0x700).size(), size_t(4), 5000);
        QVERIFY(elsewhere.load());
        QCOMPARE(n.load(), uint8_t(4));
    }
};

QTEST_GUILESS_MAIN(TestPeriodicSender)
#include "test_periodic_sender.moc"
