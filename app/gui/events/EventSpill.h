// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "app/gui/events/EventLog.h"

#include <QTemporaryFile>

#include <memory>
#include <vector>

namespace coscope::gui {

// The older part of an event log on disk (issue 38: a day-long capture in bounded memory):
// events appended in order as records (kind, time, frame, node, text in UTF-8), read back by
// number. In RAM only the file offset of every kIndexStep-th event (8 bytes per 64 events). The
// text is kept as it was written (the UI language of then); `render` is not kept. Not
// thread-safe: EventLog's mutex guards it.
class EventSpill {
public:
    static constexpr size_t kIndexStep = 64;

    // Appends; false when the file cannot be written (then nothing more is spilled).
    bool append(const TraceEvent& e);
    size_t size() const { return count_; }
    // Events [from, to), to <= size().
    std::vector<TraceEvent> read(size_t from, size_t to) const;
    void clear();

private:
    bool open();

    std::unique_ptr<QTemporaryFile> file_;
    std::vector<qint64> index_;  // offset of event k * kIndexStep
    qint64 end_ = 0;
    size_t count_ = 0;
    bool failed_ = false;
};

}  // namespace coscope::gui
