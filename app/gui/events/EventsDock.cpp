// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/events/EventsDock.h"

#include "app/gui/events/EventsCsv.h"
#include "app/gui/events/EventsFilterModel.h"
#include "app/gui/events/EventsModel.h"
#include "app/gui/files/LastFolders.h"
#include "app/gui/session/Workspace.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QScrollBar>
#include <QTableView>
#include <QVBoxLayout>

namespace coscope::gui {

namespace {
constexpr TraceEvent::Kind kKinds[] = {TraceEvent::Kind::Emcy,
                                       TraceEvent::Kind::EmcyReset,
                                       TraceEvent::Kind::SdoAbort,
                                       TraceEvent::Kind::NmtState,
                                       TraceEvent::Kind::BootUp,
                                       TraceEvent::Kind::NmtCommand,
                                       TraceEvent::Kind::HeartbeatTimeout,
                                       TraceEvent::Kind::BusError,
                                       TraceEvent::Kind::Dropped,
                                       TraceEvent::Kind::Info};
}  // namespace

EventsDock::EventsDock(Workspace* workspace, QWidget* parent)
    : QDockWidget(tr("Events"), parent), workspace_(workspace) {
    setObjectName(QStringLiteral("EventsDock"));
    model_ = new EventsModel(this);
    shown_ = new EventsFilterModel(this);
    shown_->setSourceModel(model_);
    auto* host = new QWidget(this);
    auto* column = new QVBoxLayout(host);
    column->setContentsMargins(0, 0, 0, 0);
    column->setSpacing(2);
    buildBar(host);
    view_ = new QTableView(host);
    view_->setObjectName(QStringLiteral("eventsView"));
    view_->setModel(shown_);
    view_->verticalHeader()->hide();
    view_->verticalHeader()->setDefaultSectionSize(view_->fontMetrics().height() + 4);
    view_->setSelectionBehavior(QAbstractItemView::SelectRows);
    view_->setAlternatingRowColors(true);
    view_->setShowGrid(false);
    view_->setWordWrap(false);
    view_->horizontalHeader()->setStretchLastSection(false);
    view_->horizontalHeader()->setSectionResizeMode(EventsModel::Text, QHeaderView::Stretch);
    // In the order the events came until a column's header is clicked.
    view_->horizontalHeader()->setSortIndicator(-1, Qt::AscendingOrder);
    view_->setSortingEnabled(true);
    const int w = view_->fontMetrics().horizontalAdvance(QLatin1Char('0'));
    view_->setColumnWidth(EventsModel::Time, w * 12);
    view_->setColumnWidth(EventsModel::Node, w * 6);
    view_->setColumnWidth(EventsModel::Kind, w * 20);
    view_->setColumnWidth(EventsModel::Severity, w * 9);
    view_->setColumnWidth(EventsModel::Frame, w * 10);
    view_->setToolTip(tr("Double-click an event to show its frame in the trace; click a column's title to sort"));
    column->addWidget(view_, 1);
    setWidget(host);
    connect(view_, &QTableView::activated, this, [this](const QModelIndex& idx) {
        if (!idx.isValid()) return;
        const TraceEvent& e = model_->eventAt(shown_->mapToSource(idx).row());
        if (e.frame != kNoFrame) emit frameActivated(e.frame);
    });
    connect(workspace_, &Workspace::timeModeChanged, this, [this] {
        model_->setTimeMode(workspace_->timeMode());
        // The wall clock to the microsecond ("14:40:05.004995") needs more room than seconds.
        const int digit = view_->fontMetrics().horizontalAdvance(QLatin1Char('0'));
        view_->setColumnWidth(EventsModel::Time,
                              digit * (workspace_->timeMode() == TimeBase::Mode::WallClock ? 17 : 12));
    });
    rebind();
}

void EventsDock::buildBar(QWidget* host) {
    auto* bar = new QHBoxLayout;
    bar->setContentsMargins(2, 2, 2, 0);
    node_ = new QComboBox(host);
    node_->setObjectName(QStringLiteral("eventsNodeFilter"));
    node_->setToolTip(tr("Only the events of one node"));
    node_->addItem(tr("All nodes"), -1);
    connect(node_, &QComboBox::currentIndexChanged, this, [this] {
        const int n = node_->currentData().toInt();
        shown_->setNode(n >= 0 ? std::optional<int>(n) : std::nullopt);
        updateCount();
    });
    kind_ = new QComboBox(host);
    kind_->setObjectName(QStringLiteral("eventsKindFilter"));
    kind_->setToolTip(tr("Only the events of one kind"));
    kind_->addItem(tr("All kinds"), -1);
    for (TraceEvent::Kind k : kKinds) kind_->addItem(eventKindName(k), static_cast<int>(k));
    connect(kind_, &QComboBox::currentIndexChanged, this, [this] {
        const int k = kind_->currentData().toInt();
        shown_->setKind(k >= 0 ? std::optional<TraceEvent::Kind>(static_cast<TraceEvent::Kind>(k)) : std::nullopt);
        updateCount();
    });
    severity_ = new QComboBox(host);
    severity_->setObjectName(QStringLiteral("eventsSeverityFilter"));
    severity_->setToolTip(tr("Only the events at least this severe"));
    severity_->addItem(tr("All severities"), static_cast<int>(EventSeverity::Info));
    severity_->addItem(tr("Warnings and errors"), static_cast<int>(EventSeverity::Warning));
    severity_->addItem(tr("Errors only"), static_cast<int>(EventSeverity::Error));
    connect(severity_, &QComboBox::currentIndexChanged, this, [this] {
        shown_->setLeastSeverity(static_cast<EventSeverity>(severity_->currentData().toInt()));
        updateCount();
    });
    count_ = new QLabel(host);
    count_->setObjectName(QStringLiteral("eventsCount"));
    export_ = new QPushButton(tr("Export CSV…"), host);
    export_->setObjectName(QStringLiteral("eventsExportCsv"));
    export_->setToolTip(tr("Write the events shown (with the filters and the order above) to a CSV file"));
    connect(export_, &QPushButton::clicked, this, &EventsDock::exportCsv);
    bar->addWidget(node_);
    bar->addWidget(kind_);
    bar->addWidget(severity_);
    bar->addStretch(1);
    bar->addWidget(count_);
    bar->addWidget(export_);
    static_cast<QVBoxLayout*>(host->layout())->addLayout(bar);
}

void EventsDock::rebind() {
    model_->setLog(&workspace_->events());
    updateNodeChoices();
    updateCount();
}

void EventsDock::updateNodeChoices() {
    // The nodes the events name, added as they appear; the choice made stays.
    const std::set<int>& nodes = model_->nodes();
    if (static_cast<size_t>(node_->count() - 1) == nodes.size()) return;
    const int chosen = node_->currentData().toInt();
    const QSignalBlocker block(node_);
    while (node_->count() > 1) node_->removeItem(1);
    for (int n : nodes) node_->addItem(tr("Node %1").arg(n), n);
    const int at = node_->findData(chosen);
    node_->setCurrentIndex(at >= 0 ? at : 0);
    if (at < 0 && chosen >= 0) shown_->setNode(std::nullopt);
}

void EventsDock::updateCount() {
    const int all = model_->rowCount();
    count_->setText(shown_->isNarrowed() ? tr("%L1 of %L2 events").arg(shown_->rowCount()).arg(all)
                                         : tr("%Ln event(s)", nullptr, all));
    export_->setEnabled(shown_->rowCount() > 0);
}

void EventsDock::exportCsv() {
    const QString path =
        files::askSaveFile(this, files::kExports, tr("Export events"), QStringLiteral("events.csv"), tr("CSV (*.csv)"));
    if (path.isEmpty()) return;
    QString error;
    if (!writeEventsCsv(path, *shown_, &error)) {
        QMessageBox::warning(this, tr("Export events"), tr("The events could not be written: %1").arg(error));
        return;
    }
    emit message(tr("%Ln event(s) written to %1", nullptr, shown_->rowCount()).arg(path));
}

void EventsDock::refresh() {
    const auto& s = workspace_->store();
    if (!s || s->empty()) {
        model_->setOrigin(0);
        originStore_.reset();
    } else if (originStore_.lock() != s) {
        model_->setOrigin(s->record(0).timestampNs);
        originStore_ = s;
    }
    auto* sb = view_->verticalScrollBar();
    const bool atEnd = sb->value() >= sb->maximum() - 2;
    const int before = model_->rowCount();
    model_->refresh();
    if (model_->rowCount() != before) {
        updateNodeChoices();
        updateCount();
        if (atEnd) view_->scrollToBottom();
    }
}

}  // namespace coscope::gui
