// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "app/gui/session/Job.h"
#include "core/logio/LogReader.h"
#include "core/trace/CaptureJournal.h"
#include "core/trace/CaptureSession.h"
#include "core/trace/TraceStore.h"

#include <QStringList>

#include <functional>

#include <memory>
#include <mutex>
#include <vector>

namespace coscope::gui {

// Reads a log file of any format the log layer knows into a trace store on a worker thread.
// Frames become visible batch by batch while the rest loads (the store is readable while it is
// appended to), and each batch goes to the consumers (node table, event log) like live traffic.
// A malformed line is a diagnostic (line number + message); the rest still loads.
// A gap of the capture recorded in the log (a pcapng journal) goes into the store
// (TraceStore::addGap) and to `onGap`, on the consumers' thread between their calls for the
// frames before and after it. The consumers run on one thread of the job (not the caller's).
class LogLoadJob : public Job {
public:
    using GapHandler = std::function<void(const TraceStore::Gap&)>;
    LogLoadJob(QString path, std::shared_ptr<TraceStore> store, std::vector<CaptureSession::Consumer> consumers,
               GapHandler onGap = {});
    ~LogLoadJob() override;

    const QString& path() const { return path_; }
    QString formatName() const;
    QStringList busNames() const;
    uint64_t diagnosticCount() const;
    // The first diagnostics as "line N: message".
    QStringList diagnostics(int max = 20) const;
    // The first skipped lines with their numbers and why (for the load report).
    std::vector<logio::LogDiagnostic> firstProblems(int max = 5) const;
    int64_t linesRead() const;  // text formats; 0 for binary ones

    // Bounded memory (issue 16), before start(): once the store holds half of `budget`, every
    // frame also goes to a spill journal in `folder` and the store keeps at most `budget` in
    // RAM, paging older chunks back from the spill. The spill is removed with the job.
    void setSpill(QString folder, size_t budget);
    QString spillPath() const;

protected:
    void run() override;

private:
    void startSpill();
    void noteReaderLocked(const logio::LogReader& reader, size_t& seenDiagnostics);  // mutex_ held
    QString path_;
    std::shared_ptr<TraceStore> store_;
    std::vector<CaptureSession::Consumer> consumers_;
    GapHandler onGap_;
    mutable std::mutex mutex_;
    std::unique_ptr<logio::LogReader> reader_;  // guarded for the accessors
    QString format_;
    QStringList busNames_;
    uint64_t diagnosticCount_ = 0;
    QStringList diagnostics_;
    std::vector<logio::LogDiagnostic> problems_;
    int64_t linesRead_ = 0;
    QString spillFolder_;
    size_t budget_ = 0;
    std::unique_ptr<CaptureJournal> spill_;  // loading thread, then the destructor
    QString spillPath_;                      // guarded
};

}  // namespace coscope::gui
