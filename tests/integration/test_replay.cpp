// SPDX-License-Identifier: GPL-3.0-or-later
// replay:// bus: original timing scaled by speed, loop, end state, read-only, bad lines.
#include "core/can/CanBus.h"
#include "integration/BusRead.h"

#include <QElapsedTimer>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QtTest>

using namespace coscope;

class TestReplay : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;
    QString log_;

    // Plays the URL until the bus leaves Open; returns the frames and the elapsed ms.
    std::vector<CanFrame> play(const QString& url, qint64* elapsedMs, CanBus::State* endState,
                               QString* endMessage = nullptr, size_t stopAfter = 0) {
        QString error;
        auto bus = createBus(url, &error);
        if (!bus) qFatal("%s", qPrintable(error));
        QElapsedTimer t;
        t.start();
        bus->open();
        std::vector<CanFrame> got;
        CanFrame batch[64];
        while (t.elapsed() < 5000) {
            const size_t n = bus->read(batch, 64);
            got.insert(got.end(), batch, batch + n);
            if (stopAfter && got.size() >= stopAfter) break;
            if (n == 0 && bus->state() != CanBus::State::Open && bus->state() != CanBus::State::Opening &&
                bus->pending() == 0)
                break;
            if (n == 0) bus->waitForFrames(5);
        }
        *elapsedMs = t.elapsed();
        *endState = bus->state();
        if (endMessage) *endMessage = bus->errorString();
        bus->close();
        return got;
    }

private slots:
    void initTestCase() {
        QVERIFY(dir_.isValid());
        log_ = dir_.filePath(QStringLiteral("three.log"));
        QFile f(log_);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("(1000.000000) can0 181#01\n(1000.200000) can0 181#02\n(1000.400000) can0 181#03\n");
    }

    void originalTiming() {
        qint64 ms = 0;
        CanBus::State state;
        QString message;
        const auto got = play(QStringLiteral("replay://%1?speed=1").arg(log_), &ms, &state, &message);
        QCOMPARE(got.size(), size_t(3));
        QCOMPARE(got[2].data[0], uint8_t(3));
        QVERIFY2(ms >= 390 && ms < 1000, qPrintable(QString::number(ms)));
        QVERIFY(state == CanBus::State::Closed);
        QCOMPARE(message, QStringLiteral("replay finished"));
        // Timestamps keep the spacing and are shifted to now.
        QCOMPARE(got[1].timestampNs - got[0].timestampNs, 200000000LL);
        QVERIFY(std::llabs(got[0].timestampNs - nowNs()) < 5000000000LL);
    }

    void doubleSpeed() {
        qint64 ms = 0;
        CanBus::State state;
        const auto got = play(QStringLiteral("replay://%1?speed=2").arg(log_), &ms, &state);
        QCOMPARE(got.size(), size_t(3));
        QVERIFY2(ms >= 190 && ms < 390, qPrintable(QString::number(ms)));
    }

    void asFastAsPossible() {
        qint64 ms = 0;
        CanBus::State state;
        const auto got = play(QStringLiteral("replay://%1?speed=0").arg(log_), &ms, &state);
        QCOMPARE(got.size(), size_t(3));
        QVERIFY2(ms < 150, qPrintable(QString::number(ms)));
    }

    void loopRepeats() {
        qint64 ms = 0;
        CanBus::State state;
        const auto got = play(QStringLiteral("replay://%1?speed=0&loop=1").arg(log_), &ms, &state, nullptr, 9);
        QVERIFY(got.size() >= 9);
        QCOMPARE(got[3].data[0], uint8_t(1));
        QCOMPARE(got[8].data[0], uint8_t(3));
        QVERIFY(state == CanBus::State::Open);  // still playing
    }

    void readOnly() {
        auto bus = createBus(QStringLiteral("replay://%1?speed=1").arg(log_), nullptr);
        bus->open();
        QVERIFY(bus->waitForOpen(2000));
        QString error;
        QVERIFY(!bus->send(CanFrame::classic(0x123, {1}), &error));
        QCOMPARE(error, QStringLiteral("replay bus is read-only"));
        bus->close();
        QVERIFY(bus->state() == CanBus::State::Closed);
    }

    void missingFileIsError() {
        auto bus =
            createBus(QStringLiteral("replay://%1?speed=0").arg(dir_.filePath(QStringLiteral("none.log"))), nullptr);
        bus->open();
        QVERIFY(bus->state() == CanBus::State::Error);
        QVERIFY(bus->errorString().contains(QStringLiteral("none.log")));
    }

    void badLinesReportedRestPlays() {
        const QString path = dir_.filePath(QStringLiteral("bad.log"));
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("(1.000000) can0 181#01\n(1.000001) can0 XYZ#01\n(1.000002) can0 181#03\n");
        f.close();
        auto bus = createBus(QStringLiteral("replay://%1?speed=0").arg(path), nullptr);
        QSignalSpy errors(bus.get(), &CanBus::errorOccurred);
        bus->open();
        const std::vector<CanFrame> got = testing::readFrames(*bus, 2);
        QCOMPARE(got.size(), size_t(2));
        QTRY_VERIFY_WITH_TIMEOUT(!errors.isEmpty(), 2000);
        QVERIFY(errors.first().first().toString().contains(path + QStringLiteral(":2:")));
    }
};

QTEST_GUILESS_MAIN(TestReplay)
#include "test_replay.moc"
