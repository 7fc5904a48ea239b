// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "app/gui/session/Job.h"
#include "app/gui/trace/FrameDecoder.h"
#include "core/trace/TraceStore.h"

#include <QStringList>

#include <memory>
#include <optional>
#include <vector>

namespace coscope::gui {

// Writes frames of a trace store to a log file in any format the log layer writes (by name, or
// from the file's extension), on a worker thread with progress and cancel. `frames` selects the
// frames (e.g. the filtered rows); nullopt = all frames present when the job starts.
// A cancelled save removes the partial file.
class LogSaveJob : public Job {
public:
    LogSaveJob(QString path, QString format, std::shared_ptr<const TraceStore> store,
               std::optional<std::vector<FrameNo>> frames, QStringList busNames,
               std::shared_ptr<const FrameDecoder> decoder = defaultFrameDecoder());
    ~LogSaveJob() override;

    const QString& path() const { return path_; }
    uint64_t framesWritten() const { return written_.load(); }

protected:
    void run() override;

private:
    QString path_;
    QString format_;
    std::shared_ptr<const TraceStore> store_;
    std::optional<std::vector<FrameNo>> frames_;
    QStringList busNames_;
    std::shared_ptr<const FrameDecoder> decoder_;
    std::atomic<uint64_t> written_{0};
};

}  // namespace coscope::gui
