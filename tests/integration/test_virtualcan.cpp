// SPDX-License-Identifier: GPL-3.0-or-later
// Two QtCanBus endpoints on Qt's virtualcan plugin: the first device starts the plugin's local
// TCP server (port 35468), the second connects to it; frames written on one arrive on the other.
#include "core/can/CanBus.h"
#include "core/can/QtCanBus.h"
#include "integration/BusRead.h"

#include <QElapsedTimer>
#include <QLoggingCategory>
#include <QtTest>

#include <vector>

using namespace coscope;
using coscope::testing::openBus;
using coscope::testing::readFrames;

class TestVirtualCan : public QObject {
    Q_OBJECT
    std::unique_ptr<CanBus> a_, b_;

private slots:
    void initTestCase() {
        QLoggingCategory::setFilterRules(
            QStringLiteral("qt.canbus.plugins.*.debug=false\nqt.canbus.plugins.*.info=false"));
        if (!qtCanPlugins().contains(QStringLiteral("virtualcan"))) QSKIP("Qt's virtualcan plugin is not installed");
        QString err;
        a_ = createBus(QStringLiteral("virtualcan://can0?fd=1"), &err);
        QVERIFY2(a_, qPrintable(err));
        QVERIFY(dynamic_cast<QtCanBus*>(a_.get()));
        a_->open();
        QVERIFY2(a_->waitForOpen(5000), qPrintable(a_->errorString()));
        b_ = createBus(QStringLiteral("virtualcan://can0?fd=1"), &err);
        QVERIFY2(b_, qPrintable(err));
        b_->open();
        QVERIFY2(b_->waitForOpen(5000), qPrintable(b_->errorString()));
        QTest::qWait(200);  // both clients registered with the plugin's server
        CanFrame drain[64];
        while (a_->read(drain, 64) || b_->read(drain, 64)) {}
    }
    void cleanupTestCase() {
        if (b_) b_->close();
        if (a_) a_->close();
        if (a_) QVERIFY(a_->state() == CanBus::State::Closed);
    }

    void frameGoesAcross_data() {
        QTest::addColumn<QString>("text");
        QTest::newRow("classic") << "123#DEADBEEF";
        QTest::newRow("extended") << "1F334455#11.22.33";
        QTest::newRow("empty") << "7FF#";
        QTest::newRow("rtr") << "701#R1";
        QTest::newRow("fd") << "321##1000102030405060708090A0B";
    }
    void frameGoesAcross() {
        QFETCH(QString, text);
        QString err;
        const auto frame = parseCansend(text, &err);
        QVERIFY2(frame, qPrintable(err));
        QVERIFY2(a_->send(*frame, &err), qPrintable(err));

        // The sender sees its own frame, flagged Tx.
        auto echo = readFrames(*a_, 1);
        QCOMPARE(echo.size(), size_t(1));
        QVERIFY(echo[0].isTx());
        QCOMPARE(formatCansend(echo[0]), formatCansend(*frame));

        // The other endpoint receives it, not flagged Tx, with a live timestamp.
        auto got = readFrames(*b_, 1);
        QCOMPARE(got.size(), size_t(1));
        QVERIFY(!got[0].isTx());
        QCOMPARE(formatCansend(got[0]), formatCansend(*frame));
        QCOMPARE(got[0].flags & ~CanFrame::Tx, frame->flags);
        QVERIFY(got[0].timestampNs > 1'600'000'000'000'000'000LL);
    }
    void otherDirectionToo() {
        QString err;
        QVERIFY2(b_->send(CanFrame::classic(0x181, {1, 2, 3, 4}), &err), qPrintable(err));
        auto got = readFrames(*a_, 1);
        QCOMPARE(got.size(), size_t(1));
        QCOMPARE(got[0].id, 0x181u);
        QCOMPARE(got[0].len, 4);
        QCOMPARE(b_->counters().tx, uint64_t(1));
    }
    void conversionsKeepEveryFlag() {
        CanFrame f = CanFrame::classic(0x1ABCDE, {}, true);
        f.flags |= CanFrame::Fd | CanFrame::BitRateSwitch | CanFrame::ErrorState;
        f.len = 16;
        for (int i = 0; i < 16; ++i) f.data[i] = static_cast<uint8_t>(0xA0 + i);
        auto back = QtCanBus::fromQt(QtCanBus::toQt(f));
        QVERIFY(back);
        back->timestampNs = 0;
        QCOMPARE(*back, f);

        QCanBusFrame err(QCanBusFrame::ErrorFrame);
        err.setError(QCanBusFrame::BusOffError);  // CAN_ERR_BUSOFF = 0x40
        auto e = QtCanBus::fromQt(err);
        QVERIFY(e && e->isError());
        QCOMPARE(e->id, 0x40u);
        QVERIFY(!QtCanBus::fromQt(QCanBusFrame(QCanBusFrame::InvalidFrame)));
    }
};

QTEST_GUILESS_MAIN(TestVirtualCan)
#include "test_virtualcan.moc"
