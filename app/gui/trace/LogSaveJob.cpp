// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/trace/LogSaveJob.h"

#include "core/logio/LogFormats.h"

#include <QFile>
#include <QFileInfo>

#include <algorithm>

#include <spdlog/spdlog.h>

#include <QCoreApplication>

namespace coscope::gui {

LogSaveJob::LogSaveJob(QString path, QString format, std::shared_ptr<const TraceStore> store,
                       std::optional<std::vector<FrameNo>> frames, QStringList busNames,
                       std::shared_ptr<const FrameDecoder> decoder)
    : Job(QCoreApplication::translate("LogSaveJob", "Saving %1").arg(QFileInfo(path).fileName())),
      path_(std::move(path)), format_(std::move(format)), store_(std::move(store)), frames_(std::move(frames)),
      busNames_(std::move(busNames)), decoder_(std::move(decoder)) {}

LogSaveJob::~LogSaveJob() { stopAndJoin(); }

void LogSaveJob::run() {
    QString error;
    const QString format = logio::LogFormats::writerFormatFor(path_, format_, &error);
    if (format.isEmpty()) {
        fail(error.isEmpty() ? QCoreApplication::translate("LogSaveJob", "%1: unknown log format").arg(path_) : error);
        return;
    }
    auto writer = logio::LogFormats::createWriter(format);
    if (!writer) {
        fail(QCoreApplication::translate("LogSaveJob", "%1: cannot write format '%2'").arg(path_, format));
        return;
    }
    writer->setBusNames(busNames_);
    // The writer asks for the summary of the frame being written, from inside write(): decode
    // it as frame `current` of the store, in the context of the frames before it.
    auto decoder = decoder_;
    auto store = store_;
    auto current = std::make_shared<FrameNo>(0);
    writer->setSummaryProvider([decoder, store, current](const CanFrame&) {
        dissect::Dissection d;
        d.reset(dissect::Dissection::Level::Flat);
        decoder->decodeAt(*store, *current, d);
        return d.summary;
    });
    if (!writer->open(path_)) {
        fail(writer->errorString());
        return;
    }
    const size_t total = frames_ ? frames_->size() : store_->size();
    // Gaps of the capture go with the first frame saved after them (pcapng, ASC, TRC and CSV
    // keep them; MainWindow asks before saving to a format that cannot).
    std::vector<TraceStore::Gap> gaps = store_->gaps();
    // Stable: two gaps before the same frame keep their order (the earlier loss first).
    std::stable_sort(gaps.begin(), gaps.end(),
                     [](const TraceStore::Gap& a, const TraceStore::Gap& b) { return a.firstFrame < b.firstFrame; });
    size_t nextGap = 0;
    for (size_t i = 0; i < total; ++i) {
        if ((i & 0xFFFF) == 0) {
            setProgress(total ? double(i) / double(total) : 1.0);
            if (isCancelled()) break;
        }
        const FrameNo n = frames_ ? (*frames_)[i] : static_cast<FrameNo>(i);
        *current = n;
        for (; nextGap < gaps.size() && gaps[nextGap].firstFrame <= n; ++nextGap)
            writer->markGap(gaps[nextGap].lostNs, gaps[nextGap].backNs);
        if (!writer->write(store_->frame(n))) break;
        written_.store(i + 1, std::memory_order_relaxed);
    }
    writer->close();
    if (writer->hasError()) {
        fail(QStringLiteral("%1: %2").arg(path_, writer->errorString()));
        return;
    }
    if (isCancelled()) {
        QFile::remove(path_);
        return;
    }
    spdlog::info("saved {} frames to {} ({})", written_.load(), path_.toStdString(), format.toStdString());
}

}  // namespace coscope::gui
