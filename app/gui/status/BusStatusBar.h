// SPDX-License-Identifier: GPL-3.0-or-later
// Folder app/gui/status/ owns the status bar: source and bus state, frames/s, bus load, drops,
// errors and the progress of a running job.
#pragma once

#include <QObject>

#include <cstdint>

class QLabel;
class QProgressBar;
class QPushButton;
class QStatusBar;

namespace coscope::gui {

class Job;
class Workspace;

// The permanent part of the status bar: source and bus state, the controller's fault confinement
// state and error counters (with a Restart button after bus-off), frames/s, bus load, dropped
// frames, errors, and the progress of a running job with its Cancel button.
class BusStatusBar : public QObject {
    Q_OBJECT
public:
    BusStatusBar(QStatusBar* bar, Workspace* workspace);

    // Called by the window's refresh timer; `job` is the job to show (may be null).
    void refresh(Job* job);

    QString stateText() const;
    QString rateText() const;
    QString loadText() const;
    QString controllerText() const;
    // What CoScope sends on its own as the bus's master ("SYNC 10 ms (1,234) · heartbeat 127"); hidden when empty.
    void setMasterText(const QString& text);

private slots:
    void restartController();

private:
    Workspace* workspace_;
    QLabel* source_ = nullptr;
    QLabel* state_ = nullptr;
    QLabel* rate_ = nullptr;
    QLabel* load_ = nullptr;
    QLabel* dropped_ = nullptr;
    QLabel* errors_ = nullptr;
    QLabel* controller_ = nullptr;
    QLabel* master_ = nullptr;
    QPushButton* restart_ = nullptr;
    QProgressBar* progress_ = nullptr;
    QPushButton* cancel_ = nullptr;
    Job* job_ = nullptr;
    int64_t lastNs_ = 0;
    uint64_t lastFrames_ = 0;
    double lastBits_ = 0;
    double rate_fps_ = 0;
    double load_pct_ = 0;
};

// Bits a classic data frame of `len` bytes takes on the wire, with worst-case stuffing:
// 47 + 8·len framing bits (ISO 11898-1), plus up to one stuff bit per 4 of the 34 + 8·len
// stuffable bits (11-bit ids; 29-bit ids add 20 framing and 20 stuffable bits).
double frameBits(int len, bool extended);

}  // namespace coscope::gui
