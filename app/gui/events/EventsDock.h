// SPDX-License-Identifier: GPL-3.0-or-later
// Folder app/gui/events/ owns the event log (NMT, boot-up, heartbeat, EMCY, SDO aborts, bus state)
// as a model and its dock.
#pragma once

#include "core/trace/TraceStore.h"

#include <QDockWidget>

class QTableView;

namespace coscope::gui {

class EventsModel;
class Workspace;

// The Events dock: EMCY, SDO aborts, NMT, boot-ups, heartbeat timeouts, bus errors and drops.
// Double-clicking an event jumps to its frame in the trace.
class EventsDock : public QDockWidget {
    Q_OBJECT
public:
    explicit EventsDock(Workspace* workspace, QWidget* parent = nullptr);

    void rebind();
    void refresh();

    EventsModel* model() const { return model_; }
    QTableView* view() const { return view_; }

signals:
    void frameActivated(coscope::FrameNo frame);

private:
    Workspace* workspace_;
    EventsModel* model_ = nullptr;
    QTableView* view_ = nullptr;
    bool follow_ = true;
    // The store whose first frame's time is the origin: read once, not at every tick (with
    // bounded memory, issue 16, a read of frame 0 would keep its chunk in RAM or load it back).
    std::weak_ptr<const TraceStore> originStore_;
};

}  // namespace coscope::gui
