// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QDockWidget>
#include <QElapsedTimer>

class QCustomPlot;
class QLabel;
class QTableView;
class QTabWidget;

namespace coscope::gui {

class HealthModel;
class Workspace;

// The Health dock (issue 15): findings worst first, per-node and PDO tables, the bus load over
// time as a plot. Live and offline: the report comes from the workspace's HealthMonitor, which
// runs the same dissectors/ code as `coscope-cli stats`. Recomputed at most twice a second.
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

private:
    QTableView* makeTable(HealthModel* model, const QString& name);
    void update();

    Workspace* workspace_;
    HealthModel* findings_ = nullptr;
    HealthModel* nodes_ = nullptr;
    HealthModel* pdos_ = nullptr;
    QTableView* findingsView_ = nullptr;
    QTableView* nodesView_ = nullptr;
    QTabWidget* tabs_ = nullptr;
    QLabel* summary_ = nullptr;
    QCustomPlot* plot_ = nullptr;
    QElapsedTimer since_;
    uint64_t shownRevision_ = ~uint64_t{0};
    bool wasLive_ = false;
};

}  // namespace coscope::gui
