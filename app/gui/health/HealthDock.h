// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/trace/TraceStore.h"

#include <QDockWidget>
#include <QElapsedTimer>

class QCustomPlot;
class QAction;
class QLabel;
class QPushButton;
class QToolButton;
class QTableView;
class QTabWidget;

namespace coscope::gui {

class HealthModel;
class Workspace;

// The Health dock (issue 15): findings worst first, per-node and PDO tables, the bus load over
// time as a plot. Live and offline: the report comes from the workspace's HealthMonitor, which
// runs the same dissectors/ code as `coscope-cli stats`. Recomputed at most twice a second.
// Issue 37: the verdict on top; the current finding's what / why / what to check in a pane under
// the list; clicking a finding shows its first frame in the trace, Next / Previous occurrence
// (F8 / Shift+F8) step through its frames.
class HealthDock : public QDockWidget {
    Q_OBJECT
public:
    explicit HealthDock(Workspace* workspace, QWidget* parent = nullptr);

    void rebind();
    void refresh();

    HealthModel* findingsModel() const { return findings_; }
    HealthModel* nodesModel() const { return nodes_; }
    HealthModel* pdosModel() const { return pdos_; }
    QTableView* findingsView() const { return findingsView_; }
    QTableView* nodesView() const { return nodesView_; }
    QCustomPlot* loadPlot() const { return plot_; }
    QLabel* verdictLabel() const { return verdict_; }
    QLabel* detailLabel() const { return detail_; }
    QToolButton* nextButton() const { return nextButton_; }
    QToolButton* previousButton() const { return previousButton_; }
    // Export report…: the report as an HTML page or a PDF, to a file the user chooses.
    void exportReport();

signals:
    void frameActivated(coscope::FrameNo frame);  // show this frame in the trace
    void message(const QString& text);            // for the status bar

private:
    QTableView* makeTable(HealthModel* model, const QString& name);
    void update();
    void showFinding(int row);       // the detail pane
    void goToOccurrence(int index);  // of the current finding: emits frameActivated
    int currentFinding() const;

    Workspace* workspace_;
    HealthModel* findings_ = nullptr;
    HealthModel* nodes_ = nullptr;
    HealthModel* pdos_ = nullptr;
    QTableView* findingsView_ = nullptr;
    QTableView* nodesView_ = nullptr;
    QTabWidget* tabs_ = nullptr;
    QLabel* summary_ = nullptr;
    QLabel* verdict_ = nullptr;
    QPushButton* export_ = nullptr;
    QLabel* detail_ = nullptr;
    QAction* next_ = nullptr;
    QAction* previous_ = nullptr;
    QToolButton* nextButton_ = nullptr;
    QToolButton* previousButton_ = nullptr;
    int occurrence_ = -1;  // of the current finding's frames, -1 = none shown yet
    QCustomPlot* plot_ = nullptr;
    QElapsedTimer since_;
    uint64_t shownRevision_ = ~uint64_t{0};
    bool wasLive_ = false;
};

}  // namespace coscope::gui
