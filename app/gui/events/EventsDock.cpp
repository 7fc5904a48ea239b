// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/events/EventsDock.h"

#include "app/gui/events/EventsModel.h"
#include "app/gui/session/Workspace.h"

#include <QHeaderView>
#include <QScrollBar>
#include <QTableView>

namespace coscope::gui {

EventsDock::EventsDock(Workspace* workspace, QWidget* parent)
    : QDockWidget(tr("Events"), parent), workspace_(workspace) {
    setObjectName(QStringLiteral("EventsDock"));
    model_ = new EventsModel(this);
    view_ = new QTableView(this);
    view_->setObjectName(QStringLiteral("eventsView"));
    view_->setModel(model_);
    view_->verticalHeader()->hide();
    view_->verticalHeader()->setDefaultSectionSize(view_->fontMetrics().height() + 4);
    view_->setSelectionBehavior(QAbstractItemView::SelectRows);
    view_->setAlternatingRowColors(true);
    view_->setShowGrid(false);
    view_->setWordWrap(false);
    view_->horizontalHeader()->setStretchLastSection(false);
    view_->horizontalHeader()->setSectionResizeMode(EventsModel::Text, QHeaderView::Stretch);
    const int w = view_->fontMetrics().horizontalAdvance(QLatin1Char('0'));
    view_->setColumnWidth(EventsModel::Time, w * 12);
    view_->setColumnWidth(EventsModel::Node, w * 6);
    view_->setColumnWidth(EventsModel::Kind, w * 20);
    view_->setColumnWidth(EventsModel::Frame, w * 10);
    view_->setToolTip(tr("Double-click an event to show its frame in the trace"));
    setWidget(view_);
    connect(view_, &QTableView::activated, this, [this](const QModelIndex& idx) {
        if (!idx.isValid()) return;
        const TraceEvent& e = model_->eventAt(idx.row());
        if (e.frame != kNoFrame) emit frameActivated(e.frame);
    });
    rebind();
}

void EventsDock::rebind() { model_->setLog(&workspace_->events()); }

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
    if (atEnd && model_->rowCount() != before) view_->scrollToBottom();
}

}  // namespace coscope::gui
