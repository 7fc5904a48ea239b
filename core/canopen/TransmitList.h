// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/can/CanFrame.h"
#include "core/canopen/PeriodicSender.h"

#include <QJsonArray>
#include <QString>
#include <QStringList>

#include <mutex>
#include <optional>
#include <vector>

namespace coscope::canopen {

class MasterContext;

// One row of the transmit list: a frame (standard/extended ID, RTR with its DLC, data, CAN FD
// with BRS), how often it goes out and what it is for.
struct TransmitEntry {
    CanFrame frame;
    uint32_t periodUs = 0;  // 0 = sent once only (no periodic sending)
    QString comment;

    friend bool operator==(const TransmitEntry& a, const TransmitEntry& b) {
        return a.frame == b.frame && a.periodUs == b.periodUs && a.comment == b.comment;
    }
};

// The transmit list of one bus (the Transmit panel's model; PCAN-View's and SavvyCAN's transmit
// lists): rows of frames, each sent once on demand or periodically on the bus's PeriodicSender,
// several at once, with a sent count per row. Kept between sessions and in the project file
// through toJson()/fromJson() or toStringList()/fromStringList().
//
// Thread-safety: every function may be called from any thread (the GUI calls it from its thread
// and polls the counts on its 30 Hz timer), except from a PeriodicSender callback (start() waits
// for the sender thread's first send while holding the list). Rows are indexes 0..size()-1.
class TransmitList {
public:
    // Sends with context.send() and context.periodic(); the context outlives the list.
    explicit TransmitList(MasterContext& context);
    ~TransmitList();  // stops every periodic row
    TransmitList(const TransmitList&) = delete;
    TransmitList& operator=(const TransmitList&) = delete;

    // --- rows
    int size() const;
    TransmitEntry entry(int row) const;  // a default entry for a row out of range
    std::vector<TransmitEntry> entries() const;
    // Appends a row; returns its index.
    int add(const TransmitEntry& entry);
    // Replaces a row. A periodically running row keeps running with the new frame and period
    // (stops when the new period is 0). False for a row out of range.
    bool update(int row, const TransmitEntry& entry);
    // Removes a row (stopping it first). False for a row out of range.
    bool remove(int row);
    // Moves a row to index `to` (rows between shift). False when either is out of range.
    bool move(int from, int to);
    // Stops and removes every row.
    void clear();
    // Changes whenever rows are added, removed, moved or replaced (not for counts): a poller
    // rebuilds its rows only when it changed.
    uint64_t revision() const;

    // --- sending
    // Sends a row's frame once, now, from the calling thread. False with *error when the bus
    // refused it (listen-only: with the reason) or the row is out of range.
    bool sendOnce(int row, QString* error = nullptr);
    // Starts sending a row every periodUs on the bus's PeriodicSender: first frame at once, then
    // `count` frames in all (0 = until stopped). False with *error when its period is 0, the row is
    // out of range or the first frame was refused. Restarts when running.
    bool start(int row, QString* error = nullptr, uint64_t count = 0);
    void stop(int row);
    void stopAll();
    bool isRunning(int row) const;
    // Rows running now.
    int runningCount() const;
    // Frames of this row that went out (once and periodic), since it was added or last reset.
    uint64_t sentCount(int row) const;
    void resetCounts();
    // Why the row's last periodic run stopped by itself (a send failed); empty otherwise.
    QString lastError(int row) const;

    // --- text: candump/cansend syntax (core/can/CanFrame.h parseCansend/formatCansend):
    // "601#4018100100000000", "123#R", "123#R4", "1F334455#11.22", "123##1AABB" (FD, flag 1 = BRS)
    static std::optional<CanFrame> parseFrame(QStringView text, QString* error = nullptr);
    static QString formatFrame(const CanFrame& frame);

    // --- persistence (QSettings and the project file)
    // One object per row: {"frame": "601#40...", "period_us": 100000, "comment": "..."}.
    QJsonArray toJson() const;
    // Replaces the rows (all stopped first). Rows that do not parse are skipped and named in
    // *error (the good ones load: a bad line never loses the rest); false when any was skipped.
    bool fromJson(const QJsonArray& rows, QString* error = nullptr);
    // One line per row: "FRAME<TAB>PERIOD_US<TAB>COMMENT" (tabs and line breaks in the comment
    // become spaces).
    QStringList toStringList() const;
    bool fromStringList(const QStringList& lines, QString* error = nullptr);

private:
    struct Row {
        TransmitEntry entry;
        uint64_t sentOnce = 0;      // sendOnce() frames
        uint64_t sentPeriodic = 0;  // frames of finished periodic runs
        PeriodicSender::JobId job = 0;
        QString error;  // of the last finished run
    };
    void stopRow(Row& row);                                   // mutex_ held
    bool startRow(Row& row, uint64_t count, QString* error);  // mutex_ held
    void replaceRows(std::vector<TransmitEntry> rows);

    MasterContext& context_;
    mutable std::mutex mutex_;
    std::vector<Row> rows_;
    uint64_t revision_ = 0;
};

}  // namespace coscope::canopen
