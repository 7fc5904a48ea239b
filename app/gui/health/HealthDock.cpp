// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/health/HealthDock.h"

#include "app/gui/health/HealthModel.h"
#include "app/gui/session/Workspace.h"

#include <QHeaderView>
#include <QLabel>
#include <QSplitter>
#include <QTabWidget>
#include <QTableView>
#include <QVBoxLayout>

#include <qcustomplot.h>

#include <limits>

namespace coscope::gui {

namespace {
constexpr qint64 kRefreshMs = 500;
}

HealthDock::HealthDock(Workspace* workspace, QWidget* parent) : QDockWidget(tr("Health"), parent), workspace_(workspace) {
    setObjectName(QStringLiteral("HealthDock"));
    findings_ = new HealthModel(HealthModel::Table::Findings, this);
    nodes_ = new HealthModel(HealthModel::Table::Nodes, this);
    pdos_ = new HealthModel(HealthModel::Table::Pdos, this);

    auto* body = new QWidget(this);
    auto* layout = new QVBoxLayout(body);
    layout->setContentsMargins(2, 2, 2, 2);
    summary_ = new QLabel(body);
    summary_->setObjectName(QStringLiteral("healthSummary"));
    summary_->setText(tr("No frames yet"));
    layout->addWidget(summary_);

    auto* split = new QSplitter(Qt::Vertical, body);
    findingsView_ = makeTable(findings_, QStringLiteral("healthFindingsView"));
    findingsView_->horizontalHeader()->setSectionResizeMode(HealthModel::Text, QHeaderView::Stretch);
    findingsView_->setToolTip(tr("What to look at first, the worst at the top"));
    split->addWidget(findingsView_);

    tabs_ = new QTabWidget(split);
    tabs_->setObjectName(QStringLiteral("healthTabs"));
    nodesView_ = makeTable(nodes_, QStringLiteral("healthNodesView"));
    tabs_->addTab(nodesView_, tr("Nodes"));
    tabs_->addTab(makeTable(pdos_, QStringLiteral("healthPdosView")), tr("PDOs"));
    plot_ = new QCustomPlot(tabs_);
    plot_->setObjectName(QStringLiteral("healthLoadPlot"));
    plot_->addGraph();
    plot_->graph(0)->setName(tr("Average load"));
    plot_->graph(0)->setLineStyle(QCPGraph::lsStepLeft);
    plot_->graph(0)->setBrush(QColor(74, 144, 217, 80));
    plot_->graph(0)->setPen(QPen(QColor(74, 144, 217)));
    plot_->addGraph();
    plot_->graph(1)->setName(tr("Peak load"));
    plot_->graph(1)->setLineStyle(QCPGraph::lsStepLeft);
    plot_->graph(1)->setPen(QPen(QColor(60, 60, 60), 1, Qt::DashLine));
    plot_->xAxis->setLabel(tr("Time (s)"));
    plot_->yAxis->setLabel(tr("Bus load (%)"));
    plot_->yAxis->setRange(0, 100);
    plot_->legend->setVisible(true);
    plot_->setMinimumHeight(120);
    tabs_->addTab(plot_, tr("Bus load"));
    split->addWidget(tabs_);
    split->setStretchFactor(0, 1);
    split->setStretchFactor(1, 2);
    layout->addWidget(split, 1);
    setWidget(body);
    since_.start();
    rebind();
}

QTableView* HealthDock::makeTable(HealthModel* model, const QString& name) {
    auto* view = new QTableView(this);
    view->setObjectName(name);
    view->setModel(model);
    view->verticalHeader()->hide();
    view->verticalHeader()->setDefaultSectionSize(view->fontMetrics().height() + 4);
    view->setSelectionBehavior(QAbstractItemView::SelectRows);
    view->setAlternatingRowColors(true);
    view->setShowGrid(false);
    view->setWordWrap(false);
    view->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    return view;
}

void HealthDock::rebind() {
    shownRevision_ = ~uint64_t{0};
    update();
}

void HealthDock::refresh() {
    if (!isVisible()) return;
    const bool live = workspace_->isLive();
    // Live, a silence is news too: recompute on the clock even without new frames.
    if (since_.elapsed() < kRefreshMs) return;
    if (!live && !wasLive_ && workspace_->health().revision() == shownRevision_) return;
    update();
}

void HealthDock::update() {
    since_.restart();
    const HealthMonitor& m = workspace_->health();
    wasLive_ = workspace_->isLive();
    shownRevision_ = m.revision();
    const dissect::HealthReport r = m.report(wasLive_ ? nowNs() : std::numeric_limits<int64_t>::min());
    findings_->setReport(r);
    nodes_->setReport(r);
    pdos_->setReport(r);
    const dissect::BusHealth& b = r.bus;
    if (b.frames == 0) summary_->setText(tr("No frames yet"));
    else
        summary_->setText(tr("%n frame(s) over %1 s; bus load average %2 %, peak %3 % at %4 bit/s; %5 error frame(s)", nullptr, int(std::min<uint64_t>(b.frames, INT32_MAX)))
                              .arg(b.durationS, 0, 'f', 1)
                              .arg(b.loadAvgPct, 0, 'f', 1)
                              .arg(b.loadPeakPct, 0, 'f', 1)
                              .arg(b.bitRate)
                              .arg(b.errorFrames));
    QVector<double> x, avg, peak;
    for (const dissect::LoadBucket& l : b.loadOverTime) {
        x << l.startS;
        avg << l.avgPct;
        peak << l.peakPct;
    }
    if (!b.loadOverTime.empty()) {  // close the last step
        x << b.loadOverTime.back().startS + b.loadOverTime.back().seconds;
        avg << avg.back();
        peak << peak.back();
    }
    plot_->graph(0)->setData(x, avg, true);
    plot_->graph(1)->setData(x, peak, true);
    plot_->xAxis->setRange(0, x.isEmpty() ? 1.0 : std::max(1.0, x.back()));
    plot_->yAxis->setRange(0, std::max(100.0, b.loadPeakPct));
    if (plot_->isVisible()) plot_->replot(QCustomPlot::rpQueuedReplot);
}

}  // namespace coscope::gui
