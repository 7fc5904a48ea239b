// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "app/gui/session/Job.h"
#include "core/trace/TraceStore.h"
#include "dissectors/SignalRecorder.h"

#include <QString>

#include <map>
#include <memory>

namespace coscope::gui {

// Records a log's plot signals again with the dictionaries the user assigned after it was read
// (a node's PDO mapping and names come from its dictionary) and the raw signals defined since: a fresh SignalRecorder consumes
// the whole trace on a worker thread; the workspace then hands it to the Plot dock.
class SignalReplayJob : public Job {
public:
    SignalReplayJob(std::shared_ptr<const TraceStore> store, std::map<int, QString> dictionaries,
                    std::vector<dissect::RawSignal> raw = {});
    ~SignalReplayJob() override;

    const std::map<int, QString>& dictionaries() const { return names_; }
    // Valid once isDone() and not cancelled.
    const std::shared_ptr<dissect::SignalRecorder>& recorder() const { return recorder_; }

protected:
    void run() override;

private:
    std::shared_ptr<const TraceStore> store_;
    std::map<int, QString> names_;
    std::vector<dissect::RawSignal> raw_;
    std::shared_ptr<dissect::SignalRecorder> recorder_;
};

}  // namespace coscope::gui
