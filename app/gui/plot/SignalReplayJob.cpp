// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/plot/SignalReplayJob.h"

#include <QObject>

#include <algorithm>

namespace coscope::gui {

SignalReplayJob::SignalReplayJob(std::shared_ptr<const TraceStore> store, std::map<int, QString> dictionaries,
                                 std::vector<dissect::RawSignal> raw)
    : Job(QObject::tr("Decoding the PDOs with the assigned dictionaries")), store_(std::move(store)),
      names_(std::move(dictionaries)), raw_(std::move(raw)), recorder_(std::make_shared<dissect::SignalRecorder>()) {}

SignalReplayJob::~SignalReplayJob() { stopAndJoin(); }

void SignalReplayJob::run() {
    recorder_->setDictionaries(names_);
    recorder_->setRawSignals(raw_);
    const size_t total = store_->size();
    constexpr size_t kBatch = 8192;  // as the ingest thread would hand them over
    for (size_t first = 0; first < total; first += kBatch) {
        if (isCancelled()) return;
        recorder_->consume(*store_, static_cast<FrameNo>(first), std::min(kBatch, total - first));
        setProgress(double(first) / double(total));
    }
}

}  // namespace coscope::gui
