// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/health/HealthDock.h"

#include "app/gui/files/LastFolders.h"
#include "app/gui/health/HealthExport.h"
#include "app/gui/health/HealthModel.h"
#include "app/gui/health/HealthRuleText.h"
#include "app/gui/session/Workspace.h"
#include "dissectors/HealthOutput.h"
#include "dissectors/NetworkHealth.h"

#include <QAction>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QItemSelectionModel>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QSplitter>
#include <QStyle>
#include <QTabWidget>
#include <QTableView>
#include <QToolButton>
#include <QVBoxLayout>

#include <qcustomplot.h>

#include <limits>

namespace coscope::gui {

namespace {
constexpr qint64 kRefreshMs = 500;
}

HealthDock::HealthDock(Workspace* workspace, QWidget* parent)
    : QDockWidget(tr("Health"), parent), workspace_(workspace) {
    setObjectName(QStringLiteral("HealthDock"));
    findings_ = new HealthModel(HealthModel::Table::Findings, this);
    nodes_ = new HealthModel(HealthModel::Table::Nodes, this);
    pdos_ = new HealthModel(HealthModel::Table::Pdos, this);

    auto* body = new QWidget(this);
    auto* layout = new QVBoxLayout(body);
    layout->setContentsMargins(2, 2, 2, 2);
    verdict_ = new QLabel(body);
    verdict_->setObjectName(QStringLiteral("healthVerdict"));
    QFont bold = verdict_->font();
    bold.setBold(true);
    bold.setPointSizeF(bold.pointSizeF() * 1.15);
    verdict_->setFont(bold);
    auto* top = new QHBoxLayout;
    top->addWidget(verdict_, 1);
    export_ = new QPushButton(tr("Export report…"), body);
    export_->setObjectName(QStringLiteral("healthExport"));
    export_->setToolTip(
        tr("Save the report for a ticket: an HTML page or a PDF, each finding with the frame numbers it rests on"));
    connect(export_, &QPushButton::clicked, this, &HealthDock::exportReport);
    top->addWidget(export_);
    layout->addLayout(top);
    summary_ = new QLabel(body);
    summary_->setObjectName(QStringLiteral("healthSummary"));
    summary_->setText(tr("No frames yet"));
    layout->addWidget(summary_);

    auto* split = new QSplitter(Qt::Vertical, body);
    findingsView_ = makeTable(findings_, QStringLiteral("healthFindingsView"));
    findingsView_->horizontalHeader()->setSectionResizeMode(HealthModel::Text, QHeaderView::Stretch);
    findingsView_->setToolTip(tr("What to look at first, the worst at the top"));
    findingsView_->setMinimumHeight(findingsView_->verticalHeader()->defaultSectionSize() *
                                    7);  // a header and six findings
    // The findings with, under them, the current one explained and its occurrences to step through.
    auto* findingsBox = new QWidget(split);
    auto* findingsLayout = new QVBoxLayout(findingsBox);
    findingsLayout->setContentsMargins(0, 0, 0, 0);
    findingsLayout->addWidget(findingsView_, 1);
    auto* detailRow = new QHBoxLayout;
    detail_ = new QLabel(findingsBox);
    detail_->setObjectName(QStringLiteral("healthFindingDetail"));
    detail_->setWordWrap(true);
    detail_->setTextFormat(Qt::RichText);
    detail_->setAlignment(Qt::AlignLeft | Qt::AlignTop);
    detail_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    detail_->setText(tr(
        "Click a finding to see what happened, why it matters and what to check, and its first frame in the trace."));
    detailRow->addWidget(detail_, 1);
    auto* steps = new QVBoxLayout;
    previous_ = new QAction(style()->standardIcon(QStyle::SP_ArrowUp), tr("Previous occurrence"), this);
    previous_->setObjectName(QStringLiteral("healthPreviousOccurrence"));
    previous_->setShortcut(QKeySequence(Qt::SHIFT | Qt::Key_F8));
    previous_->setToolTip(tr("Show the finding's previous frame in the trace (Shift+F8)"));
    next_ = new QAction(style()->standardIcon(QStyle::SP_ArrowDown), tr("Next occurrence"), this);
    next_->setObjectName(QStringLiteral("healthNextOccurrence"));
    next_->setShortcut(QKeySequence(Qt::Key_F8));
    next_->setToolTip(tr("Show the finding's next frame in the trace (F8)"));
    for (QAction* a : {previous_, next_}) {
        a->setShortcutContext(Qt::WidgetWithChildrenShortcut);
        a->setEnabled(false);
        addAction(a);
    }
    connect(previous_, &QAction::triggered, this, [this] { goToOccurrence(occurrence_ - 1); });
    connect(next_, &QAction::triggered, this, [this] { goToOccurrence(occurrence_ + 1); });
    previousButton_ = new QToolButton(findingsBox);
    previousButton_->setObjectName(QStringLiteral("healthPreviousButton"));
    previousButton_->setDefaultAction(previous_);
    previousButton_->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    nextButton_ = new QToolButton(findingsBox);
    nextButton_->setObjectName(QStringLiteral("healthNextButton"));
    nextButton_->setDefaultAction(next_);
    nextButton_->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    for (QToolButton* b : {previousButton_, nextButton_}) {
        b->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
        steps->addWidget(b);
    }
    steps->addStretch(1);
    detailRow->addLayout(steps);
    findingsLayout->addLayout(detailRow);
    split->addWidget(findingsBox);
    // A click (or Enter) on a finding: its first frame in the trace; moving through the list
    // explains the finding under the cursor.
    connect(findingsView_, &QTableView::clicked, this, [this](const QModelIndex& i) {
        showFinding(i.row());
        goToOccurrence(0);
    });
    connect(findingsView_, &QTableView::activated, this, [this](const QModelIndex& i) {
        showFinding(i.row());
        goToOccurrence(0);
    });
    connect(findingsView_->selectionModel(), &QItemSelectionModel::currentRowChanged, this,
            [this](const QModelIndex& i) {
                occurrence_ = -1;
                showFinding(i.row());
            });

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
    split->setStretchFactor(0, 3);
    split->setStretchFactor(1, 2);
    layout->addWidget(split, 1);
    setWidget(body);
    since_.start();
    // One time base (issue 37 item 3): the findings' times as the trace shows them.
    connect(workspace_, &Workspace::timeModeChanged, this, [this] {
        findings_->setTimeMode(workspace_->timeMode());
        showFinding(currentFinding());
    });
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
    // The verdict (issue 37): errors and warnings, CoScope's own traffic not counted.
    int counts[4] = {0, 0, 0, 0};
    for (const dissect::HealthFinding& f : r.findings)
        if (!f.own) ++counts[std::clamp(f.severity, 0, 3)];
    QStringList parts;
    // English has no plural table here (no coscope_en.ts): one and many as two texts.
    const int crit = counts[dissect::HealthFinding::Critical], err = counts[dissect::HealthFinding::Error],
              warn = counts[dissect::HealthFinding::Warning];
    if (crit) parts << tr("%1 critical").arg(crit);
    if (err) parts << (err == 1 ? tr("1 error") : tr("%1 errors").arg(err));
    if (warn) parts << (warn == 1 ? tr("1 warning") : tr("%1 warnings").arg(warn));
    verdict_->setText(r.bus.frames == 0 ? QString()
                      : parts.isEmpty() ? tr("No problems found")
                                        : tr("Problems found: %1").arg(parts.join(tr(", "))));
    verdict_->setStyleSheet(parts.isEmpty() ? QStringLiteral("color:#2e7d32") : QStringLiteral("color:#b00020"));
    // The worst finding explained at once; a click still leads to its frames.
    if (currentFinding() < 0 && findings_->rowCount() > 0)
        findingsView_->setCurrentIndex(findings_->index(0, HealthModel::Text));
    showFinding(currentFinding());
    const dissect::BusHealth& b = r.bus;
    if (b.frames == 0) summary_->setText(tr("No frames yet"));
    else
        summary_->setText(tr("%n frame(s) over %1 s; bus load average %2 %, peak %3 % at %4 bit/s; %5 error frame(s)",
                             nullptr, int(std::min<uint64_t>(b.frames, INT32_MAX)))
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
    // Scaled to the data (issue 37 item 7): a bus at 3 % shows its shape, not a line on the floor.
    plot_->yAxis->setRange(0, std::max(dissect::loadScaleTopPct(b.loadPeakPct), b.loadPeakPct));
    if (plot_->isVisible()) plot_->replot(QCustomPlot::rpQueuedReplot);
}

void HealthDock::exportReport() {
    const HealthMonitor& m = workspace_->health();
    const dissect::HealthReport r = m.report(workspace_->isLive() ? nowNs() : std::numeric_limits<int64_t>::min());
    const QString source = workspace_->sourceName().isEmpty() ? QStringLiteral("capture") : workspace_->sourceName();
    const QString html = tr("HTML page (*.html)"), pdf = tr("PDF (*.pdf)");
    QString chosen;
    QString path = files::askSaveFile(this, files::kExports, tr("Export the health report"),
                                      QFileInfo(source).completeBaseName() + QStringLiteral("-health.html"),
                                      html + QStringLiteral(";;") + pdf, &chosen);
    if (path.isEmpty()) return;
    const bool asPdf = path.endsWith(QLatin1String(".pdf"), Qt::CaseInsensitive) ||
                       (chosen == pdf && !path.endsWith(QLatin1String(".html"), Qt::CaseInsensitive));
    if (asPdf && !path.endsWith(QLatin1String(".pdf"), Qt::CaseInsensitive)) path += QStringLiteral(".pdf");
    // The report's own words are English, as `coscope-cli stats --format html` writes them (for
    // whoever reads the ticket); the title names the log.
    const QString title = QStringLiteral("CoScope network health: %1").arg(source);
    QString error;
    const bool ok = asPdf ? writeHealthPdf(path, r, title, plot_->toPixmap(960, 240).toImage(), &error)
                          : writeHealthHtml(path, r, title, &error);
    if (!ok) {
        QMessageBox::warning(this, tr("Export the health report"),
                             tr("The report could not be written: %1").arg(error));
        return;
    }
    emit message(tr("Health report written to %1").arg(path));
}

int HealthDock::currentFinding() const {
    const QModelIndex i = findingsView_->currentIndex();
    return i.isValid() && i.row() < findings_->rowCount() ? i.row() : -1;
}

void HealthDock::showFinding(int row) {
    const auto& findings = findings_->report().findings;
    if (row < 0 || row >= static_cast<int>(findings.size())) {
        previous_->setEnabled(false);
        next_->setEnabled(false);
        return;
    }
    const dissect::HealthFinding& f = findings[static_cast<size_t>(row)];
    const dissect::Occurrences& at = f.at;
    QString where;
    if (at.count) {
        const TimeBase base = findings_->timeBase();
        const QString first = base.shortText(at.firstNs), last = base.shortText(at.lastNs);
        where = at.count == 1 ? tr("Once, at %1.").arg(first)
                              : tr("%1 times, from %2 to %3.").arg(at.count).arg(first, last);
    }
    if (!at.frames.empty()) {
        where += QLatin1Char(' ') +
                 (occurrence_ >= 0 ? tr("Frame %1 of %2 shown in the trace.").arg(occurrence_ + 1).arg(at.frames.size())
                                   : tr("Click the finding to show its first frame in the trace."));
    }
    auto esc = [](const QString& t) { return t.toHtmlEscaped(); };
    detail_->setText(
        QStringLiteral("<b>%1</b><br>%2 %3<br>%4 %5<br><span style='color:#555'>%6%7</span>")
            .arg(esc(healthRuleText(f, RulePart::What)), tr("<b>Why:</b>"), esc(healthRuleText(f, RulePart::Why)),
                 tr("<b>Check:</b>"), esc(healthRuleText(f, RulePart::Check)), esc(where),
                 f.own ? QStringLiteral(" ") + esc(tr("CoScope's own traffic: not counted in the verdict."))
                       : QString()));
    previous_->setEnabled(occurrence_ > 0);
    next_->setEnabled(!at.frames.empty() && occurrence_ + 1 < static_cast<int>(at.frames.size()));
}

void HealthDock::goToOccurrence(int index) {
    const int row = currentFinding();
    if (row < 0) return;
    const dissect::HealthFinding& f = findings_->report().findings[static_cast<size_t>(row)];
    if (index < 0 || index >= static_cast<int>(f.at.frames.size())) return;
    occurrence_ = index;
    showFinding(row);
    emit frameActivated(static_cast<FrameNo>(f.at.frames[static_cast<size_t>(index)]));
}

}  // namespace coscope::gui
