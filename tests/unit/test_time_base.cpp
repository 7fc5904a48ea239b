// SPDX-License-Identifier: GPL-3.0-or-later
// One time base (DESIGN.md "Time", issue 37 item 3): relative seconds since the first frame, or
// the wall clock where the trace's stamps are Unix time; a trace of bare relative stamps shows
// relative seconds in either mode.
#include "core/trace/TimeBase.h"

#include <QDateTime>
#include <QtTest>

using namespace coscope;

class TimeBaseTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { qputenv("TZ", "UTC"); }

    void relativeSeconds() {
        const TimeBase b{1'700'000'000'000'000'000LL, TimeBase::Mode::Relative};
        QVERIFY(b.hasWallClock());
        QCOMPARE(b.text(1'700'000'001'234'567'891LL), QStringLiteral("1.234568"));
        QCOMPARE(b.shortText(1'700'000'001'234'567'891LL), QStringLiteral("1.235 s"));
    }

    void wallClock() {
        // 1700000000 s = 2023-11-14 22:13:20 UTC.
        const TimeBase b{1'700'000'000'000'000'000LL, TimeBase::Mode::WallClock};
        QCOMPARE(b.shown(), TimeBase::Mode::WallClock);
        QCOMPARE(b.text(1'700'000'001'234'567'891LL), QStringLiteral("22:13:21.234567"));
        QCOMPARE(b.text(1'700'000'001'234'567'891LL, true), QStringLiteral("2023-11-14 22:13:21.234567"));
        QCOMPARE(b.shortText(1'700'000'001'234'567'891LL), QStringLiteral("22:13:21.234"));
    }

    void noWallClockWithoutUnixStamps() {
        // A log of relative stamps (a TRC without $STARTTIME, a bare CSV): seconds in either mode.
        const TimeBase b{2'000'000'000LL, TimeBase::Mode::WallClock};
        QVERIFY(!b.hasWallClock());
        QCOMPARE(b.shown(), TimeBase::Mode::Relative);
        QCOMPARE(b.text(3'500'000'000LL), QStringLiteral("1.500000"));
    }
};

QTEST_GUILESS_MAIN(TimeBaseTest)
#include "test_time_base.moc"
