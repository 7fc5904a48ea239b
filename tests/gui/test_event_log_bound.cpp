// SPDX-License-Identifier: GPL-3.0-or-later
// Issue 38 (a day-long capture in bounded memory): the event log keeps its newest events in RAM
// and the older ones in its spill file, and the Events view holds only the rows it shows: after
// many times the bound, every event is still there, counted and readable, in order, with its
// kind, time, frame, node and text.
#include "app/gui/events/EventLog.h"
#include "app/gui/events/EventsModel.h"

#include <QtTest>

using namespace coscope;
using namespace coscope::gui;

class TestEventLogBound : public QObject {
    Q_OBJECT
private slots:
    void oldEventsSpilledAndReadBack() {
        EventLog log;
        const size_t n = 5 * EventLog::kInRam + 123;
        EventsModel model;
        model.setLog(&log);
        for (size_t i = 0; i < n; ++i) {
            TraceEvent e;
            e.kind = i % 2 ? TraceEvent::Kind::SdoAbort : TraceEvent::Kind::Emcy;
            e.timeNs = 1'000'000'000LL + int64_t(i) * 1000;
            e.frame = FrameNo(i * 3);
            e.node = int(i % 127) + 1;
            e.text = QStringLiteral("event %1 \u00b0C").arg(i);
            log.add(std::move(e));
            if (i % 1000 == 0) model.refresh();
        }
        model.refresh();
        QCOMPARE(log.size(), n);
        QVERIFY2(log.eventsInRam() <= EventLog::kInRam + EventLog::kInRam / 4,
                 qPrintable(QString::number(log.eventsInRam())));
        const auto all = log.since(0);
        QCOMPARE(all.size(), n);
        for (size_t i : {size_t(0), size_t(1), size_t(63), size_t(64), size_t(4097), n / 2, n - 1}) {
            QCOMPARE(all[i].text, QStringLiteral("event %1 \u00b0C").arg(i));
            QCOMPARE(all[i].frame, FrameNo(i * 3));
            QCOMPARE(all[i].node, int(i % 127) + 1);
            QCOMPARE(all[i].timeNs, 1'000'000'000LL + int64_t(i) * 1000);
            QCOMPARE(all[i].kind, i % 2 ? TraceEvent::Kind::SdoAbort : TraceEvent::Kind::Emcy);
        }
        const auto some = log.events(100, 103);
        QCOMPARE(some.size(), size_t(3));
        QCOMPARE(some[2].text, QStringLiteral("event 102 \u00b0C"));

        // The view: every row, the old ones read back as shown, few held.
        QCOMPARE(model.rowCount(), int(n));
        auto text = [&](int row) {
            return model.data(model.index(row, EventsModel::Text), Qt::DisplayRole).toString();
        };
        QCOMPARE(text(0), QStringLiteral("event 0 \u00b0C"));
        QCOMPARE(text(int(n) - 1), QStringLiteral("event %1 \u00b0C").arg(n - 1));
        for (int row = 0; row < int(n); row += 97) QCOMPARE(text(row), QStringLiteral("event %1 \u00b0C").arg(row));
        QCOMPARE(model.eventAt(5).frame, FrameNo(15));
        QCOMPARE(model.data(model.index(0, EventsModel::Time), Qt::DisplayRole).toString(), QStringLiteral("0.000000"));
        QVERIFY2(model.rowsInRam() <= EventLog::kInRam + EventsModel::kBlock * EventsModel::kBlocksKept,
                 qPrintable(QString::number(model.rowsInRam())));

        log.clear();
        QCOMPARE(log.size(), size_t(0));
        model.refresh();
        QCOMPARE(model.rowCount(), 0);
    }
};

QTEST_GUILESS_MAIN(TestEventLogBound)
#include "test_event_log_bound.moc"
