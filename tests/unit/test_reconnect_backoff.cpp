// SPDX-License-Identifier: GPL-3.0-or-later
// The lost-adapter state machine (issue 16) without a device: ReconnectBackoff's schedule and
// ThreadedCanBus's Open -> Lost -> (failed attempts) -> Open, and close() ending the retries.
#include "core/can/ReconnectBackoff.h"
#include "core/can/ThreadedCanBus.h"

#include <QtTest>

#include <atomic>

using namespace coscope;

namespace {
// A backend whose device is "there" or not: startOnThread() opens when present, else fails.
class FakeAdapterBus : public ThreadedCanBus {
public:
    std::atomic<bool> present{true};
    std::atomic<int> starts{0};

    FakeAdapterBus() : ThreadedCanBus(*BusUrl::parse(QStringLiteral("socketcand://127.0.0.1:1/can0"), nullptr)) {}
    ~FakeAdapterBus() override { close(); }

    void unplug() {
        present = false;
        runOnBusThread([this] { connectionLost(QStringLiteral("adapter unplugged")); });
    }

protected:
    bool sendFrame(const CanFrame&, QString*) override { return true; }

private:
    QString threadName() const override { return QStringLiteral("fake"); }
    void startOnThread() override {
        ++starts;
        if (present) reachedOpen();
        else failedToOpen(QStringLiteral("no adapter"));
    }
    void stopOnThread() override {}
};
}  // namespace

class TestReconnectBackoff : public QObject {
    Q_OBJECT
private slots:
    void scheduleDoublesFromHalfASecondToEight() {
        ReconnectBackoff b;
        QList<int> waits;
        for (int i = 0; i < 7; ++i) waits << b.next();
        QCOMPARE(waits, (QList<int>{500, 1000, 2000, 4000, 8000, 8000, 8000}));
        QCOMPARE(b.attempts(), 7);
        b.reset();
        QCOMPARE(b.next(), 500);
    }

    void lostThenBackAfterFailedAttempts() {
        QList<CanBus::State> states;  // outlives the bus, whose close() still reports Closed
        FakeAdapterBus bus;
        connect(&bus, &CanBus::stateChanged, &bus, [&](CanBus::State s) { states << s; });
        bus.open();
        QVERIFY(bus.waitForOpen(2000));
        QCOMPARE(bus.starts.load(), 1);

        bus.unplug();
        QTRY_VERIFY(bus.state() == CanBus::State::Lost);
        QCOMPARE(bus.errorString(), QStringLiteral("adapter unplugged"));
        QVERIFY(bus.lostSinceNs() > 0);
        QVERIFY(bus.nextRetryInMs() > 0 && bus.nextRetryInMs() <= 500);
        // Attempts at 0.5 s and 1.5 s fail and keep it Lost (not Error); the next wait is 2 s.
        QTRY_COMPARE_WITH_TIMEOUT(bus.starts.load(), 3, 3000);
        QVERIFY(bus.state() == CanBus::State::Lost);
        QVERIFY2(bus.nextRetryInMs() > 1000 && bus.nextRetryInMs() <= 2000,
                 qPrintable(QString::number(bus.nextRetryInMs())));

        bus.present = true;
        QTRY_VERIFY_WITH_TIMEOUT(bus.state() == CanBus::State::Open, 3000);
        QCOMPARE(bus.starts.load(), 4);
        QCOMPARE(bus.lostSinceNs(), int64_t(0));
        QCOMPARE(bus.nextRetryInMs(), -1);
        QTRY_VERIFY(states == (QList<CanBus::State>{CanBus::State::Opening, CanBus::State::Open, CanBus::State::Lost,
                                                    CanBus::State::Open}));

        // Lost again: the schedule starts over at 0.5 s.
        bus.unplug();
        QTRY_VERIFY(bus.state() == CanBus::State::Lost);
        QVERIFY(bus.nextRetryInMs() <= 500);
    }

    void closeWhileLostStopsRetrying() {
        FakeAdapterBus bus;
        bus.open();
        QVERIFY(bus.waitForOpen(2000));
        bus.unplug();
        QTRY_VERIFY(bus.state() == CanBus::State::Lost);
        bus.close();
        QVERIFY(bus.state() == CanBus::State::Closed);
        const int starts = bus.starts.load();
        bus.present = true;
        QTest::qWait(1200);
        QCOMPARE(bus.starts.load(), starts);
        QVERIFY(bus.state() == CanBus::State::Closed);
    }

    void firstOpenFailureIsAnErrorNotALoss() {
        FakeAdapterBus bus;
        bus.present = false;
        bus.open();
        QVERIFY(!bus.waitForOpen(2000));
        QVERIFY(bus.state() == CanBus::State::Error);
        QTest::qWait(700);
        QCOMPARE(bus.starts.load(), 1);
    }
};

QTEST_GUILESS_MAIN(TestReconnectBackoff)
#include "test_reconnect_backoff.moc"
