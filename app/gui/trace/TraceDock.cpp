// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/trace/TraceDock.h"

#include "app/gui/session/Workspace.h"
#include "app/gui/trace/FrameDetailsView.h"
#include "app/gui/trace/TraceFilter.h"
#include "app/gui/trace/TraceFind.h"
#include "app/gui/trace/TraceModel.h"
#include "app/gui/trace/TraceView.h"
#include "app/gui/trace/TraceWindow.h"

#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QElapsedTimer>
#include <QFrame>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QScrollBar>
#include <QSplitter>
#include <QStyle>
#include <QTableView>
#include <QToolBar>
#include <QToolButton>
#include <QVBoxLayout>
#include <utility>

namespace coscope::gui {

namespace {
constexpr int kFindSliceMs = 30;  // Find on the GUI thread at most this long, then on a worker
}

TraceDock::TraceDock(Workspace* workspace, QWidget* parent) : QDockWidget(tr("Trace"), parent), workspace_(workspace) {
    setObjectName(QStringLiteral("TraceDock"));
    auto* content = new QWidget(this);
    auto* layout = new QVBoxLayout(content);
    layout->setContentsMargins(2, 2, 2, 2);
    layout->setSpacing(2);

    model_ = new TraceModel(this);
    auto* bar = new QWidget(content);
    buildToolbar(bar);
    layout->addWidget(bar);

    report_ = new QFrame(content);
    report_->setObjectName(QStringLiteral("loadReport"));
    static_cast<QFrame*>(report_)->setFrameShape(QFrame::StyledPanel);
    auto* reportRow = new QHBoxLayout(report_);
    reportRow->setContentsMargins(6, 4, 4, 4);
    reportText_ = new QLabel(report_);
    reportText_->setObjectName(QStringLiteral("loadReportText"));
    reportText_->setWordWrap(true);
    reportText_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    reportRow->addWidget(reportText_, 1);
    auto* closeReport = new QToolButton(report_);
    closeReport->setObjectName(QStringLiteral("loadReportClose"));
    closeReport->setAutoRaise(true);
    closeReport->setIcon(QApplication::style()->standardIcon(QStyle::SP_TitleBarCloseButton));
    closeReport->setToolTip(tr("Close this report"));
    connect(closeReport, &QToolButton::clicked, this, &TraceDock::hideLoadReport);
    reportRow->addWidget(closeReport, 0, Qt::AlignTop);
    report_->hide();
    layout->addWidget(report_);

    auto* split = new QSplitter(Qt::Vertical, content);
    split->setObjectName(QStringLiteral("traceSplit"));
    // The table and the scroll bar spanning the whole trace (TraceView shows a window of it).
    auto* table = new QWidget(split);
    auto* tableRow = new QHBoxLayout(table);
    tableRow->setContentsMargins(0, 0, 0, 0);
    tableRow->setSpacing(0);
    view_ = new TraceView(model_, table);
    view_->setObjectName(QStringLiteral("traceView"));
    tableRow->addWidget(view_, 1);
    tableRow->addWidget(view_->traceScrollBar());
    view_->verticalHeader()->hide();
    view_->verticalHeader()->setDefaultSectionSize(view_->fontMetrics().height() + 4);
    view_->verticalHeader()->setSectionResizeMode(QHeaderView::Fixed);  // uniform rows: cheap for 10 M rows
    view_->horizontalHeader()->setStretchLastSection(true);
    view_->horizontalHeader()->setHighlightSections(false);
    view_->setSelectionBehavior(QAbstractItemView::SelectRows);
    view_->setSelectionMode(QAbstractItemView::SingleSelection);
    view_->setAlternatingRowColors(true);
    view_->setWordWrap(false);
    view_->setShowGrid(false);
    const int w = view_->fontMetrics().horizontalAdvance(QLatin1Char('0'));
    view_->setColumnWidth(TraceModel::Number, w * 8);
    view_->setColumnWidth(TraceModel::Time, w * 13);
    view_->setColumnWidth(TraceModel::Bus, w * 5);
    view_->setColumnWidth(TraceModel::CobId, w * 8);
    view_->setColumnWidth(TraceModel::Node, w * 5);
    view_->setColumnWidth(TraceModel::Service, w * 10);
    view_->setColumnWidth(TraceModel::Direction, w * 5);
    view_->setColumnWidth(TraceModel::Length, w * 4);
    view_->setColumnWidth(TraceModel::Data, w * 24);
    details_ = new FrameDetailsView(split);
    split->addWidget(table);
    split->addWidget(details_);
    split->setStretchFactor(0, 3);
    split->setStretchFactor(1, 1);
    layout->addWidget(split, 1);
    setWidget(content);

    connect(view_->selectionModel(), &QItemSelectionModel::currentRowChanged, this, &TraceDock::onCurrentChanged);
    // A transfer row opens and closes by a click on its arrow (the No. column) or a double click.
    connect(view_, &QAbstractItemView::clicked, this, [this](const QModelIndex& i) {
        if (i.column() == TraceModel::Number) toggleRow(view_->logicalRow(i));
    });
    connect(view_, &QAbstractItemView::doubleClicked, this, [this](const QModelIndex& i) {
        if (i.column() != TraceModel::Number) toggleRow(view_->logicalRow(i));
    });
    // Scrolling up by hand pauses following; the Follow button resumes it.
    connect(view_, &TraceView::userScrolled, this, [this](bool atEnd) {
        if (!atEnd && follow_->isChecked()) follow_->setChecked(false);
    });
    rebind();
}

TraceDock::~TraceDock() = default;

void TraceDock::buildToolbar(QWidget* host) {
    auto* row = new QHBoxLayout(host);
    row->setContentsMargins(0, 0, 0, 0);
    auto* tb = new QToolBar(host);
    tb->setObjectName(QStringLiteral("traceToolbar"));
    tb->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    tb->setIconSize(QSize(16, 16));
    QStyle* st = QApplication::style();
    follow_ = tb->addAction(st->standardIcon(QStyle::SP_MediaPlay), tr("Follow"));
    follow_->setObjectName(QStringLiteral("followAction"));
    follow_->setCheckable(true);
    follow_->setChecked(true);
    follow_->setToolTip(tr("Follow new frames (scrolling up pauses)"));
    connect(follow_, &QAction::toggled, this, [this, st](bool on) {
        follow_->setIcon(st->standardIcon(on ? QStyle::SP_MediaPlay : QStyle::SP_MediaPause));
        if (on) view_->scrollToEnd();
    });
    timeMode_ = new QComboBox(tb);
    timeMode_->setObjectName(QStringLiteral("timeMode"));
    timeMode_->addItems({tr("Absolute time"), tr("Relative time"), tr("Delta time")});
    timeMode_->setCurrentIndex(1);
    timeMode_->setToolTip(
        tr("How times are shown, here and in the Events, Health and Plot docks: the wall clock (from the log's "
           "header or the capture), seconds since the first frame, or since the row before (this table only)"));
    // One time base (issue 37 item 3): the other docks follow, Delta being relative for them.
    connect(timeMode_, &QComboBox::currentIndexChanged, this, [this](int i) {
        const auto mode = static_cast<TraceModel::TimeMode>(i);
        model_->setTimeMode(mode);
        // The wall clock to the microsecond ("14:40:00.004000") needs more room than seconds.
        const int digit = view_->fontMetrics().horizontalAdvance(QLatin1Char('0'));
        view_->setColumnWidth(TraceModel::Time, digit * (mode == TraceModel::TimeMode::Absolute ? 17 : 13));
        workspace_->setTimeMode(mode == TraceModel::TimeMode::Absolute ? TimeBase::Mode::WallClock
                                                                       : TimeBase::Mode::Relative);
    });
    tb->addWidget(timeMode_);
    latest_ = tb->addAction(st->standardIcon(QStyle::SP_FileDialogListView), tr("Latest per ID"));
    latest_->setObjectName(QStringLiteral("latestAction"));
    latest_->setCheckable(true);
    latest_->setToolTip(tr("One row per COB-ID showing its latest frame"));
    connect(latest_, &QAction::toggled, this, [this](bool on) { model_->setLatestPerCobId(on); });
    groupSdo_ = tb->addAction(st->standardIcon(QStyle::SP_FileDialogDetailedView), tr("Group SDO"));
    groupSdo_->setObjectName(QStringLiteral("groupSdoAction"));
    groupSdo_->setCheckable(true);
    groupSdo_->setToolTip(tr("Group SDO transfers: each transfer as one row; click its ▸ to show its frames"));
    connect(groupSdo_, &QAction::toggled, this, [this] {
        QString error;
        if (!applyFilter(filterEdit_->text(), &error)) emit message(error);
    });
    tb->addSeparator();

    filterEdit_ = new QLineEdit(tb);
    filterEdit_->setObjectName(QStringLiteral("filterEdit"));
    filterEdit_->setPlaceholderText(tr("Filter: node:5 svc:sdo,emcy id:580-5FF text"));
    filterEdit_->setClearButtonEnabled(true);
    // Shrinks before the buttons after it do, so Find, Next and Bookmark stay on the bar.
    filterEdit_->setMinimumWidth(120);
    filterEdit_->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
    connect(filterEdit_, &QLineEdit::returnPressed, this, [this] {
        QString error;
        if (!applyFilter(filterEdit_->text(), &error)) emit message(error);
    });
    // Emptying the box (its ✕ button, or deleting the text) removes the filter at once.
    connect(filterEdit_, &QLineEdit::textChanged, this, [this](const QString& text) {
        if (text.isEmpty() && (model_->isFiltered() || filterJob_)) applyFilter(QString());
    });
    tb->addWidget(filterEdit_);
    tb->addSeparator();
    findEdit_ = new QLineEdit(tb);
    findEdit_->setObjectName(QStringLiteral("findEdit"));
    findEdit_->setPlaceholderText(tr("Find"));
    findEdit_->setMaximumWidth(130);
    connect(findEdit_, &QLineEdit::returnPressed, this, [this] { find(findEdit_->text(), true); });
    connect(findEdit_, &QLineEdit::textChanged, this, [this] { setFindMissed(false); });
    tb->addWidget(findEdit_);
    // Find's arrows and Bookmark are icons only (text in the tooltip) so they fit at the default width.
    auto iconOnly = [tb](QAction* a, const QString& name) {
        a->setObjectName(name);
        if (auto* b = qobject_cast<QToolButton*>(tb->widgetForAction(a))) b->setToolButtonStyle(Qt::ToolButtonIconOnly);
        return a;
    };
    iconOnly(tb->addAction(st->standardIcon(QStyle::SP_ArrowUp), tr("Previous"), this,
                           [this] { find(findEdit_->text(), false); }),
             QStringLiteral("findPrevAction"))
        ->setToolTip(tr("Find previous"));
    iconOnly(tb->addAction(st->standardIcon(QStyle::SP_ArrowDown), tr("Next"), this,
                           [this] { find(findEdit_->text(), true); }),
             QStringLiteral("findNextAction"))
        ->setToolTip(tr("Find next"));
    tb->addSeparator();
    auto* mark = iconOnly(
        tb->addAction(st->standardIcon(QStyle::SP_DialogApplyButton), tr("Bookmark"), this, &TraceDock::toggleBookmark),
        QStringLiteral("bookmarkAction"));
    mark->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_B));
    mark->setToolTip(tr("Toggle a bookmark on the selected frame (Ctrl+B); F2 / Shift+F2 jump"));
    // F2 / Shift+F2 only while the focus is in the trace: elsewhere F2 edits (the Object Dictionary).
    // Named, for Help ▸ Keyboard shortcuts.
    auto* nextMark = new QAction(tr("Next bookmark"), this);
    nextMark->setShortcut(QKeySequence(Qt::Key_F2));
    nextMark->setShortcutContext(Qt::WidgetWithChildrenShortcut);
    connect(nextMark, &QAction::triggered, this, [this] { gotoBookmark(true); });
    auto* prevMark = new QAction(tr("Previous bookmark"), this);
    prevMark->setShortcut(QKeySequence(Qt::SHIFT | Qt::Key_F2));
    prevMark->setShortcutContext(Qt::WidgetWithChildrenShortcut);
    connect(prevMark, &QAction::triggered, this, [this] { gotoBookmark(false); });
    addAction(nextMark);
    addAction(prevMark);
    // Ctrl+F: to the find field; F3 / Shift+F3: find next / previous, while the focus is in this trace.
    const auto shortcut = [this](const QString& text, QKeySequence::StandardKey key, auto slot) {
        auto* a = new QAction(text, this);
        a->setShortcuts(key);
        a->setShortcutContext(Qt::WidgetWithChildrenShortcut);
        connect(a, &QAction::triggered, this, slot);
        addAction(a);
    };
    shortcut(tr("Find"), QKeySequence::Find, [this] {
        findEdit_->setFocus(Qt::ShortcutFocusReason);
        findEdit_->selectAll();
    });
    shortcut(tr("Find next"), QKeySequence::FindNext, [this] { find(findEdit_->text(), true); });
    shortcut(tr("Find previous"), QKeySequence::FindPrevious, [this] { find(findEdit_->text(), false); });
    row->addWidget(tb, 1);
    countLabel_ = new QLabel(host);
    countLabel_->setObjectName(QStringLiteral("traceCount"));
    row->addWidget(countLabel_);
}

void TraceDock::showLoadReport(const QString& text, bool problem) {
    report_->setStyleSheet(problem ? QStringLiteral("QFrame#loadReport { background: #fff4d6; }") : QString());
    reportText_->setText(text);
    report_->show();
}

void TraceDock::hideLoadReport() { report_->hide(); }
bool TraceDock::loadReportShown() const { return report_->isVisible(); }

void TraceDock::rebind() {
    hideLoadReport();
    findJob_.reset();
    filterJob_.reset();
    model_->setStore(workspace_->store());
    model_->setDecoder(workspace_->decoder());
    model_->setBusNames(workspace_->busNames());
    details_->setDecoder(workspace_->decoder());
    details_->clear();
    shownDetailsFor_ = -1;
    detailsLoading_ = false;
    if (!filterEdit_->text().trimmed().isEmpty()) applyFilter(filterEdit_->text());
    pendingFrame_.reset();  // a selection of the source before is nothing to keep
    // A log opened for review starts at its first frame, as in Wireshark or Logxaminer (and the
    // window does not chase a file still loading); a live capture follows the newest frames.
    if (workspace_->loadJob()) {
        setFollow(false);
        view_->scrollToTop();
    } else if (workspace_->isLive()) {
        setFollow(true);
    }
}

void TraceDock::refresh() {
    if (filterJob_ && filterJob_->isDone()) {
        if (!filterJob_->isCancelled()) {
            const FrameNo upTo = filterJob_->scannedUpTo();
            if (filterJob_->groupsSdo()) {
                auto filter =
                    filterJob_->filter().isEmpty() ? std::nullopt : std::optional<TraceFilter>(filterJob_->filter());
                model_->setView(std::move(filter), filterJob_->takeResult(), upTo, filterJob_->takeGroups(),
                                filterJob_->takeGroupedRows());
            } else {
                model_->setFilter(filterJob_->filter(), filterJob_->takeResult(), upTo);
            }
            shownDetailsFor_ = -1;
            onCurrentChanged();
        }
        filterJob_.reset();
        if (const auto n = std::exchange(pendingFrame_, std::nullopt)) {
            model_->refresh();
            if (!selectFrame(*n, pendingExact_) && pendingExact_ && model_->isFiltered()) showFrame(*n);
        }
    }
    if (!filterJob_) model_->refresh();
    const auto [top, bottom] = view_->visibleRows();
    model_->pinRows(top, bottom, view_->currentRow());  // what is shown stays in RAM
    if (detailsLoading_) onCurrentChanged();            // asks again; shows it once it is back
    if (shownDetailsFor_ != -1 && workspace_->decoder()->revision() != detailsRevision_) {  // dictionaries changed
        shownDetailsFor_ = -1;
        onCurrentChanged();
    }
    model_->setBusNames(workspace_->busNames());
    if (follow_->isChecked() && model_->rowCount() > 0) view_->scrollToEnd();
    const size_t total = workspace_->store() ? workspace_->store()->size() : 0;
    if (model_->isGrouped()) {
        countLabel_->setText(tr("%L1 rows, %L2 frames").arg(model_->rowCount()).arg(total));
        countLabel_->setToolTip(tr("%L1 SDO transfers grouped").arg(model_->groups()->size()));
    } else {
        countLabel_->setText(model_->isFiltered() || model_->latestPerCobId()
                                 ? tr("%L1 of %L2 frames").arg(model_->rowCount()).arg(total)
                                 : tr("%L1 frames").arg(total));
        countLabel_->setToolTip({});
    }
}

void TraceDock::setFollow(bool on) { follow_->setChecked(on); }
bool TraceDock::follows() const { return follow_->isChecked(); }

bool TraceDock::applyFilter(const QString& query, QString* error) {
    QString why;
    const auto filter = TraceFilter::parse(query, &why);
    if (!filter) {
        filterEdit_->setStyleSheet(QStringLiteral("background: #ffd7d7"));
        filterEdit_->setToolTip(why);
        if (error) *error = why;
        return false;
    }
    filterEdit_->setStyleSheet({});
    filterEdit_->setToolTip({});
    // The frame selected now stays selected, and in view, in the new rows (unless a frame
    // asked for by showFrame() is waiting for them).
    if (!pendingFrame_ || !pendingExact_) {
        pendingFrame_ = follows() ? std::nullopt : currentFrame();  // following: the newest rows
        pendingExact_ = false;
    }
    if (filterEdit_->text() != query) {
        const QSignalBlocker block(filterEdit_);  // not a second applyFilter() from textChanged
        filterEdit_->setText(query);
    }
    findJob_.reset();  // it searched the rows of the view before
    filterJob_.reset();
    const bool group = groupSdo_->isChecked();
    if ((filter->isEmpty() && !group) || !workspace_->store()) {
        model_->clearFilter();
        if (const auto n = std::exchange(pendingFrame_, std::nullopt)) selectFrame(*n, pendingExact_);
        return true;
    }
    filterJob_ = std::make_unique<FilterJob>(workspace_->store(), *filter, workspace_->decoder(), group);
    filterJob_->start();
    return true;
}

std::optional<FrameNo> TraceDock::currentFrame() const {
    const int row = view_->currentRow();
    if (row < 0 || !model_->store()) return std::nullopt;
    if (model_->rowKind(row) == TraceModel::RowKind::Transfer) {
        const auto frames = model_->groups()->frames(static_cast<size_t>(model_->groupAt(row)));
        if (!frames.empty()) return frames.front();
        return std::nullopt;
    }
    return model_->frameAt(row);
}

bool TraceDock::selectFrame(FrameNo n, bool exact) {
    int row = model_->rowOf(n);
    // A frame of a collapsed transfer: the transfer opened, its row selected.
    if (row >= 0 && exact && model_->rowKind(row) == TraceModel::RowKind::Transfer && model_->frameAt(row) != n) {
        model_->toggleExpanded(row);
        if (const int member = model_->rowOf(n); member >= 0) row = member;
    }
    if (row < 0 && !exact) row = model_->rowAtOrAfter(n);
    if (row < 0 && !exact && model_->rowCount() > 0) row = model_->rowCount() - 1;
    if (row < 0) return false;
    setFollow(false);
    view_->setCurrentRow(row, true);
    return true;
}

void TraceDock::clearFilter() { applyFilter(QString()); }

QJsonObject TraceDock::filtersJson() const {
    return {{QStringLiteral("filter"), filterEdit_->text().trimmed()},
            {QStringLiteral("groupSdo"), groupSdo_->isChecked()}};
}

void TraceDock::setFiltersJson(const QJsonObject& filters) {
    if (filters.isEmpty()) return;
    {
        const QSignalBlocker block(groupSdo_);  // one filter run, below
        groupSdo_->setChecked(filters.value(QStringLiteral("groupSdo")).toBool());
    }
    QString error;
    if (!applyFilter(filters.value(QStringLiteral("filter")).toString(), &error))
        emit message(tr("The project's trace filter is not valid: %1").arg(error));
}

void TraceDock::setGroupSdo(bool on) { groupSdo_->setChecked(on); }
bool TraceDock::groupsSdo() const { return groupSdo_->isChecked(); }

void TraceDock::toggleRow(int row) {
    if (row < 0 || model_->rowKind(row) != TraceModel::RowKind::Transfer) return;
    setFollow(false);
    model_->toggleExpanded(row);
}

Job* TraceDock::activeJob() const {
    if (findJob_) return findJob_.get();
    return filterJob_.get();
}

void TraceDock::showFrame(FrameNo n) {
    if (filterJob_) {  // the rows are being computed: selected when they are there
        pendingFrame_ = n;
        pendingExact_ = true;
        return;
    }
    model_->refresh();
    if (selectFrame(n, true)) return;
    if (model_->isFiltered() || model_->latestPerCobId()) {
        latest_->setChecked(false);
        pendingFrame_ = n;
        pendingExact_ = true;
        clearFilter();  // selects it now, or when the grouped rows are computed
        if (!filterJob_) pendingFrame_.reset();
    }
}

void TraceDock::setFindMissed(bool missed) {
    findEdit_->setStyleSheet(missed ? QStringLiteral("QLineEdit { background: #ffd7d7; }") : QString());
    findEdit_->setProperty("missed", missed);
}

bool TraceDock::find(const QString& text, bool forward) {
    findJob_.reset();  // a new search replaces one still running
    if (text.isEmpty()) return false;
    if (model_->rowCount() == 0 || !model_->store()) {
        setFindMissed(true);
        emit message(tr("'%1' not found: the trace is empty").arg(text));
        return false;
    }
    setFollow(false);
    const FindRows rows = model_->findRows();
    const int current = view_->currentRow();
    const int64_t from = current >= 0 ? model_->findPosition(current) + (forward ? 1 : -1)
                                      : (forward ? 0 : static_cast<int64_t>(rows.count) - 1);
    return findFrom(text, forward, rows, from);
}

bool TraceDock::findFrom(const QString& text, bool forward, const FindRows& rows, int64_t from) {
    // Rows whose frames are in RAM are tested here, for a moment; a frame paged out to the
    // journal (issue 16) is read back by the worker, so the GUI thread never waits for the disk.
    const TraceStore& store = *model_->store();
    FrameMatcher matcher(text, model_->decoder());
    QElapsedTimer clock;
    clock.start();
    uint32_t tick = 0;
    for (;;) {
        const FindStep step = findRows(store, rows, matcher, from, forward, [&](int64_t row, FrameNo) {
            if ((++tick & 0xFF) == 0 && clock.elapsed() > kFindSliceMs) return false;
            return findReadsResident(store, rows, static_cast<size_t>(row));
        });
        if (step.found >= 0) {
            const int row = model_->rowOfFindPosition(rows, step.found);
            if (row >= 0 && row == view_->currentRow()) {  // another frame of the selected transfer
                from = step.found + (forward ? 1 : -1);
                continue;
            }
            if (row < 0) {
                findMissed(text);
                return false;
            }
            view_->setCurrentRow(row, true);
            setFindMissed(false);
            return true;
        }
        if (step.next < 0) {
            findMissed(text);
            return false;
        }
        const uint64_t serial = ++findSerial_;
        findJob_ = std::make_unique<FindJob>(
            model_->store(), model_->decoder(), text, rows, step.next, forward, [this, serial] {
                QMetaObject::invokeMethod(
                    this, [this, serial] { onFindDone(serial); }, Qt::QueuedConnection);
            });
        findJob_->start();
        return false;
    }
}

void TraceDock::onFindDone(uint64_t serial) {
    if (!findJob_ || serial != findSerial_) return;  // replaced or stopped meanwhile
    findJob_->wait();
    const std::unique_ptr<FindJob> job = std::move(findJob_);
    if (job->isCancelled()) return;
    if (job->foundRow() < 0) {
        findMissed(job->text());
        return;
    }
    // The rows may have changed meanwhile (a live capture appends): the row of the frame or
    // transfer found.
    const int row = model_->rowOfFindPosition(job->rows(), job->foundRow());
    if (row < 0) {
        findMissed(job->text());
        return;
    }
    if (row == view_->currentRow()) {  // another frame of the selected transfer: go on
        findFrom(job->text(), job->forward(), model_->findRows(), job->foundRow() + (job->forward() ? 1 : -1));
        return;
    }
    view_->setCurrentRow(row, true);
    setFindMissed(false);
}

void TraceDock::findMissed(const QString& text) {
    emit message(tr("'%1' not found").arg(text));
    setFindMissed(true);
}

void TraceDock::toggleBookmark() {
    const int row = view_->currentRow();
    if (row < 0) {
        emit message(tr("Select a frame to bookmark"));
        return;
    }
    model_->toggleBookmark(model_->frameAt(row));
}

void TraceDock::gotoBookmark(bool forward) {
    const auto& marks = model_->bookmarks();
    if (marks.empty()) {
        emit message(tr("No bookmarks (Ctrl+B sets one)"));
        return;
    }
    const int row = view_->currentRow();
    const FrameNo cur = row >= 0 ? model_->frameAt(row) : (forward ? 0 : ~FrameNo(0));
    FrameNo target;
    if (forward) {
        auto it = marks.upper_bound(cur);
        target = it == marks.end() ? *marks.begin() : *it;
    } else {
        auto it = marks.lower_bound(cur);
        target = it == marks.begin() ? *marks.rbegin() : *std::prev(it);
    }
    showFrame(target);
}

void TraceDock::onCurrentChanged() {
    const int row = view_->currentRow();
    if (row < 0 || !model_->store()) {
        detailsLoading_ = false;
        details_->clear();
        shownDetailsFor_ = -1;
        return;
    }
    // A frame paged out to the journal is shown once the store's loader has read it back:
    // the GUI thread does not wait for the disk (issue 16).
    const bool wasLoading = std::exchange(detailsLoading_, model_->rowPagedOut(row));
    if (detailsLoading_) {
        if (!wasLoading || shownDetailsFor_ != -1) details_->showLoading();
        shownDetailsFor_ = -1;
        return;
    }
    if (model_->rowKind(row) == TraceModel::RowKind::Transfer) {  // keyed -2 - group
        const int64_t g = model_->groupAt(row);
        if (-2 - g == shownDetailsFor_) return;
        shownDetailsFor_ = -2 - g;
        detailsRevision_ = workspace_->decoder()->revision();
        const auto frames = model_->groups()->frames(static_cast<size_t>(g));
        details_->showTransfer(model_->transferRecord(g), std::vector<FrameNo>(frames.begin(), frames.end()));
        return;
    }
    const FrameNo n = model_->frameAt(row);
    if (static_cast<int64_t>(n) == shownDetailsFor_) return;
    shownDetailsFor_ = n;
    detailsRevision_ = workspace_->decoder()->revision();
    details_->showFrame(*model_->store(), n);
}

}  // namespace coscope::gui
