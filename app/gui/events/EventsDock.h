// SPDX-License-Identifier: GPL-3.0-or-later
// Folder app/gui/events/ owns the event log (NMT, boot-up, heartbeat, EMCY, SDO aborts, bus state)
// as a model and its dock.
#pragma once

#include "core/trace/TraceStore.h"

#include <QDockWidget>

class QComboBox;
class QLabel;
class QPushButton;
class QTableView;

namespace coscope::gui {

class EventsFilterModel;
class EventsModel;
class Workspace;

// The Events dock: EMCY, SDO aborts, NMT, boot-ups, heartbeat timeouts, bus errors and drops.
// Narrowed to a node, a kind or a least severity, sorted by a click on a column's header,
// exported as CSV (the rows shown); double-clicking an event (or Enter) jumps to its frame in
// the trace.
class EventsDock : public QDockWidget {
    Q_OBJECT
public:
    explicit EventsDock(Workspace* workspace, QWidget* parent = nullptr);

    void rebind();
    void refresh();

    EventsModel* model() const { return model_; }
    EventsFilterModel* shown() const { return shown_; }
    QTableView* view() const { return view_; }
    // Export CSV…: the rows shown, to a file the user chooses.
    void exportCsv();

signals:
    void frameActivated(coscope::FrameNo frame);
    void message(const QString& text);  // for the status bar

private:
    Workspace* workspace_;
    void buildBar(QWidget* host);
    void updateNodeChoices();
    void updateCount();

    EventsModel* model_ = nullptr;
    EventsFilterModel* shown_ = nullptr;
    QTableView* view_ = nullptr;
    QComboBox* node_ = nullptr;
    QComboBox* kind_ = nullptr;
    QComboBox* severity_ = nullptr;
    QLabel* count_ = nullptr;
    QPushButton* export_ = nullptr;
    bool follow_ = true;
    // The store whose first frame's time is the origin: read once, not at every tick (with
    // bounded memory, issue 16, a read of frame 0 would keep its chunk in RAM or load it back).
    std::weak_ptr<const TraceStore> originStore_;
};

}  // namespace coscope::gui
