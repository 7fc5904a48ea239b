// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Waits, processing events, until `pred` holds (true) or `timeoutMs` passed (false): for GUI
// tests that act and then look, as a user waits for the window to answer.
//
// The wait is an event loop, not QTest::qWait: qWait sleeps 10 ms between two passes over the
// events, so every answer posted from another thread (the ingest thread's frames, a simulated
// drive's SDO response) waited up to 10 ms, and a test doing 700 SDO reads took 7 s more than the
// app does (30 s under ASan). An event loop wakes as soon as something is posted, as the app's does.

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QEvent>
#include <QEventLoop>
#include <QTimer>

namespace coscope::testing {

template <typename Pred>
bool waitFor(Pred pred, int timeoutMs = 15000) {
    QElapsedTimer t;
    t.start();
    while (!pred()) {
        if (t.elapsed() > timeoutMs) return false;
        QEventLoop loop;
        QTimer::singleShot(5, &loop, &QEventLoop::quit);  // look at `pred` again at least every 5 ms
        loop.exec();
        QCoreApplication::sendPostedEvents(nullptr, QEvent::DeferredDelete);  // deleteLater(), as qWait does
    }
    return true;
}

}  // namespace coscope::testing
