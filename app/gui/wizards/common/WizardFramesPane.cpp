// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/wizards/common/WizardFramesPane.h"
#include "app/gui/language/CoreText.h"
#include "app/gui/language/ObjectNameText.h"

#include "app/gui/session/Workspace.h"
#include "core/canopen/CobId.h"
#include "dissectors/Dissection.h"

#include <QAbstractTableModel>
#include <QBrush>
#include <QFontDatabase>
#include <QHeaderView>
#include <QLabel>
#include <QScrollBar>
#include <QTableView>
#include <QTimer>
#include <QVBoxLayout>

#include <QCoreApplication>
#include <deque>

namespace coscope::gui {

namespace {

constexpr int kPollMs = 40;              // 25 Hz, within the ≤ 30 Hz budget of DESIGN.md
constexpr size_t kScanPerTick = 200000;  // frames examined per tick (a busy bus never stalls the GUI)
constexpr int kMaxRows = 2000;           // oldest rows go when a node's PDOs flood the pane

}  // namespace

// Not anonymous: WizardFramesPane::Private holds a FramesModel.
namespace framespane {

struct Row {
    FrameNo frame = 0;
    int64_t timeNs = 0;
    bool tx = false;
    QString cobId, data, summary;
};

// Rows appended at the end only (beginInsertRows), oldest removed at the front.
class FramesModel : public QAbstractTableModel {
public:
    enum Column { Time, Direction, CobId, Data, Summary, ColumnCount };

    int rowCount(const QModelIndex& parent = {}) const override {
        return parent.isValid() ? 0 : static_cast<int>(rows_.size());
    }
    int columnCount(const QModelIndex& parent = {}) const override { return parent.isValid() ? 0 : ColumnCount; }

    QVariant data(const QModelIndex& index, int role) const override {
        if (!index.isValid() || index.row() >= static_cast<int>(rows_.size())) return {};
        const Row& r = rows_[static_cast<size_t>(index.row())];
        switch (role) {
        case Qt::DisplayRole:
            switch (index.column()) {
            case Time: return QString::number(static_cast<double>(r.timeNs - t0_) / 1e9, 'f', 3);
            case Direction: return r.tx ? QStringLiteral("Tx") : QStringLiteral("Rx");
            case CobId: return r.cobId;
            case Data: return r.data;
            case Summary: return r.summary;
            default: return {};
            }
        case Qt::ToolTipRole:
            if (index.column() == Summary) return r.summary;
            return {};
        case Qt::FontRole:
            if (index.column() == CobId || index.column() == Data)
                return QFontDatabase::systemFont(QFontDatabase::FixedFont);
            return {};
        case Qt::ForegroundRole:
            if (index.column() == Direction && r.tx) return QBrush(QColor(30, 90, 200));
            return {};
        case Qt::TextAlignmentRole:
            if (index.column() == Time || index.column() == CobId)
                return QVariant::fromValue(Qt::AlignRight | Qt::AlignVCenter);
            return {};
        default: return {};
        }
    }

    QVariant headerData(int section, Qt::Orientation o, int role) const override {
        if (o != Qt::Horizontal || role != Qt::DisplayRole) return {};
        switch (section) {
        case Time: return QCoreApplication::translate("WizardFramesPane", "Time (s)");
        case Direction: return QCoreApplication::translate("WizardFramesPane", "Dir");
        case CobId: return QStringLiteral("COB-ID");
        case Data: return QCoreApplication::translate("WizardFramesPane", "Data");
        case Summary: return QCoreApplication::translate("WizardFramesPane", "Meaning");
        default: return {};
        }
    }

    void clear() {
        if (rows_.empty()) return;
        beginResetModel();  // only on markStart / source change, never per frame
        rows_.clear();
        endResetModel();
    }

    void append(std::vector<Row>&& more) {
        if (more.empty()) return;
        if (rows_.empty()) t0_ = more.front().timeNs;
        // Trim first so the pane holds at most kMaxRows.
        const size_t total = rows_.size() + more.size();
        if (total > static_cast<size_t>(kMaxRows)) {
            size_t drop = std::min(rows_.size(), total - kMaxRows);
            if (drop > 0) {
                beginRemoveRows({}, 0, static_cast<int>(drop) - 1);
                rows_.erase(rows_.begin(), rows_.begin() + static_cast<std::ptrdiff_t>(drop));
                endRemoveRows();
            }
            if (more.size() > static_cast<size_t>(kMaxRows))
                more.erase(more.begin(), more.begin() + static_cast<std::ptrdiff_t>(more.size() - kMaxRows));
        }
        const int first = static_cast<int>(rows_.size());
        beginInsertRows({}, first, first + static_cast<int>(more.size()) - 1);
        for (Row& r : more) rows_.push_back(std::move(r));
        endInsertRows();
    }

    const Row& row(int i) const { return rows_[static_cast<size_t>(i)]; }

private:
    std::deque<Row> rows_;
    int64_t t0_ = 0;
};

}  // namespace framespane

struct WizardFramesPane::Private {
    Workspace* workspace = nullptr;
    framespane::FramesModel model;
    QTableView* view = nullptr;
    QTimer* timer = nullptr;
    std::shared_ptr<TraceStore> store;  // the store being followed (replaced with the source)
    size_t next = 0;                    // next frame number to examine
    int node = -1;
    // The view follows the newest row until the user scrolls away from the end, and again once
    // they scroll back to it. Kept as a flag (not read off the scroll bar when rows come): a
    // pane moved to a smaller page, or shown again, keeps following.
    bool follow = true;
    dissect::Dissection scratch;

    bool wanted(const TraceRecord& r) const {
        if (r.flags & (CanFrame::Extended | CanFrame::Error)) return false;
        const auto info = canopen::classifyCobId(r.id, false);
        // Requests and answers: SDO, NMT, LSS, boot-up/heartbeat and EMCY. SYNC, TIME and the
        // PDOs are cyclic traffic that would bury them (the trace shows everything).
        switch (info.service) {
        case canopen::Service::Nmt:
        case canopen::Service::LssRequest:
        case canopen::Service::LssResponse: return true;
        case canopen::Service::SdoRequest:
        case canopen::Service::SdoResponse:
        case canopen::Service::NmtErrorControl:
        case canopen::Service::Emcy: return node < 0 || info.node == node;
        default: return false;
        }
    }

    framespane::Row makeRow(FrameNo n) {
        const TraceRecord& r = store->record(n);
        framespane::Row row;
        row.frame = n;
        row.timeNs = r.timestampNs;
        row.tx = r.flags & CanFrame::Tx;
        row.cobId = QStringLiteral("%1").arg(r.id, 3, 16, QLatin1Char('0')).toUpper();
        if (r.flags & CanFrame::Remote) {
            row.data = QStringLiteral("RTR");
        } else {
            const auto p = store->payload(n);
            row.data = QString::fromLatin1(
                QByteArray(reinterpret_cast<const char*>(p.data()), static_cast<qsizetype>(p.size()))
                    .toHex(' ')
                    .toUpper());
        }
        const auto decoder = workspace ? workspace->decoder() : nullptr;
        if (decoder) {
            scratch.reset(dissect::Dissection::Level::Flat);
            decoder->decodeAt(*store, n, scratch);
            row.summary =
                coreLines(localObjectNames(scratch, scratch.summary));  // the dissectors' English in the UI language
            if (!scratch.warnings.isEmpty()) {
                QStringList warnings = scratch.warnings;
                for (QString& w : warnings) w = coreText(localObjectNames(scratch, w));
                row.summary += QStringLiteral("  ⚠ ") + warnings.join(QStringLiteral("; "));
            }
        }
        return row;
    }
};

WizardFramesPane::WizardFramesPane(Workspace* workspace, QWidget* parent)
    : QWidget(parent), d_(std::make_unique<Private>()) {
    d_->workspace = workspace;
    d_->view = new QTableView(this);
    d_->view->setModel(&d_->model);
    d_->view->setObjectName(QStringLiteral("wizardFrames"));
    d_->view->verticalHeader()->hide();
    d_->view->verticalHeader()->setDefaultSectionSize(d_->view->fontMetrics().height() + 4);
    d_->view->setSelectionBehavior(QAbstractItemView::SelectRows);
    d_->view->setEditTriggers(QAbstractItemView::NoEditTriggers);
    d_->view->setWordWrap(false);
    d_->view->setAlternatingRowColors(true);
    auto* h = d_->view->horizontalHeader();
    h->setSectionResizeMode(QHeaderView::Interactive);
    h->setStretchLastSection(true);
    const int digit = d_->view->fontMetrics().horizontalAdvance(QLatin1Char('0'));
    d_->view->setColumnWidth(framespane::FramesModel::Time, digit * 10);
    d_->view->setColumnWidth(framespane::FramesModel::Direction, digit * 4);
    d_->view->setColumnWidth(framespane::FramesModel::CobId, digit * 8);
    d_->view->setColumnWidth(framespane::FramesModel::Data, digit * 26);

    auto* title = new QLabel(tr("Frames on the bus for this wizard"), this);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(title);
    layout->addWidget(d_->view);

    QScrollBar* bar = d_->view->verticalScrollBar();
    connect(bar, &QScrollBar::valueChanged, this, [this, bar](int value) { d_->follow = value >= bar->maximum() - 2; });
    connect(bar, &QScrollBar::rangeChanged, this, [this] {
        if (d_->follow) d_->view->scrollToBottom();
    });

    d_->timer = new QTimer(this);
    d_->timer->setInterval(kPollMs);
    connect(d_->timer, &QTimer::timeout, this, &WizardFramesPane::poll);
    if (workspace) {
        d_->store = workspace->store();
        d_->next = d_->store ? d_->store->size() : 0;
        connect(workspace, &Workspace::sourceChanged, this, [this] {
            // A new store: everything in it is newer than the mark.
            d_->store = d_->workspace->store();
            d_->next = 0;
            d_->model.clear();
        });
    }
    d_->timer->start();
}

WizardFramesPane::~WizardFramesPane() = default;

void WizardFramesPane::setNode(int node) { d_->node = (node >= 1 && node <= 127) ? node : -1; }

void WizardFramesPane::markStart() {
    if (d_->workspace) d_->store = d_->workspace->store();
    d_->next = d_->store ? d_->store->size() : 0;
    d_->model.clear();
}

void WizardFramesPane::poll() {
    if (!d_->store) return;
    const size_t size = d_->store->size();
    if (d_->next >= size) return;
    const size_t end = std::min(size, d_->next + kScanPerTick);
    std::vector<framespane::Row> rows;
    for (size_t n = d_->next; n < end; ++n)
        if (d_->wanted(d_->store->record(static_cast<FrameNo>(n))))
            rows.push_back(d_->makeRow(static_cast<FrameNo>(n)));
    d_->next = end;
    if (rows.empty()) return;
    const bool follow = d_->follow;
    d_->model.append(std::move(rows));
    if (follow) d_->view->scrollToBottom();
}

int WizardFramesPane::rowCount() const { return d_->model.rowCount(); }

QString WizardFramesPane::rowText(int row) const {
    if (row < 0 || row >= d_->model.rowCount()) return {};
    const framespane::Row& r = d_->model.row(row);
    return QStringLiteral("%1 %2 %3  %4")
        .arg(r.tx ? QStringLiteral("Tx") : QStringLiteral("Rx"), r.cobId, r.data, r.summary);
}

}  // namespace coscope::gui
