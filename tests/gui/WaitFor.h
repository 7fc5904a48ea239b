// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Waits, processing events, until `pred` holds (true) or `timeoutMs` passed (false): for GUI
// tests that act and then look, as a user waits for the window to answer.

#include <QElapsedTimer>
#include <QTest>

namespace coscope::testing {

template <typename Pred>
bool waitFor(Pred pred, int timeoutMs = 15000) {
    QElapsedTimer t;
    t.start();
    while (!pred()) {
        if (t.elapsed() > timeoutMs) return false;
        QTest::qWait(20);
    }
    return true;
}

}  // namespace coscope::testing
