// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/plot/PlotDock.h"

#include "app/gui/files/LastFolders.h"
#include "app/gui/language/ObjectNameText.h"

#include "app/gui/plot/PlotCsv.h"
#include "app/gui/plot/RawSignalDialog.h"
#include "app/gui/plot/SignalPicker.h"
#include "app/gui/session/Workspace.h"
#include "core/od/NumberNotation.h"
#include "dissectors/SignalRecorder.h"

#include <QAction>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QJsonArray>
#include <QLabel>
#include <QMenu>
#include <QSplitter>
#include <QToolBar>
#include <QToolButton>
#include <QVBoxLayout>

#include <algorithm>
#include <map>

#include <spdlog/spdlog.h>

namespace coscope::gui {

using dissect::SignalInfo;
using dissect::SignalKey;

PlotDock::PlotDock(Workspace* workspace, QWidget* parent) : QDockWidget(tr("Plot"), parent), workspace_(workspace) {
    setObjectName(QStringLiteral("PlotDock"));
    auto* host = new QWidget(this);
    auto* layout = new QVBoxLayout(host);
    layout->setContentsMargins(2, 2, 2, 2);
    layout->setSpacing(2);
    buildToolbar(host);

    auto* split = new QSplitter(Qt::Horizontal, host);
    picker_ = new SignalPicker(split);
    auto* right = new QWidget(split);
    auto* rightLayout = new QVBoxLayout(right);
    rightLayout->setContentsMargins(0, 0, 0, 0);
    view_ = new PlotView(right);
    readout_ = new QLabel(right);
    readout_->setTextFormat(Qt::RichText);
    readout_->setWordWrap(true);
    rightLayout->addWidget(view_, 1);
    rightLayout->addWidget(readout_);
    split->addWidget(picker_);
    split->addWidget(right);
    split->setStretchFactor(0, 0);
    split->setStretchFactor(1, 1);
    split->setSizes({360, 900});
    layout->addWidget(split, 1);
    setWidget(host);

    connect(picker_, &SignalPicker::pickedChanged, this, [this] {
        if (!picker_->picked().empty()) autoPicked_ = true;  // the user chose: no auto-pick later
        updatePlotted();
    });
    connect(picker_, &SignalPicker::scaleChanged, this, &PlotDock::updatePlotted);
    connect(view_, &PlotView::userNavigated, this, [this] { setPaused(true); });
    connect(view_, &PlotView::frameClicked, this, &PlotDock::frameActivated);
    connect(view_, &PlotView::cursorsChanged, this, &PlotDock::updateReadout);
    // One time base (issue 37 item 3): the time axis as the trace shows times.
    connect(workspace_, &Workspace::timeModeChanged, this, [this] { view_->setTimeMode(workspace_->timeMode()); });
    rebind();
}

PlotDock::~PlotDock() = default;

void PlotDock::buildToolbar(QWidget* host) {
    auto* bar = new QToolBar(host);
    bar->setIconSize(QSize(16, 16));
    bar->setToolButtonStyle(Qt::ToolButtonTextOnly);
    host->layout()->addWidget(bar);

    mode_ = new QComboBox(bar);
    mode_->setObjectName(QStringLiteral("plotMode"));
    mode_->addItems({tr("Rolling window"), tr("Whole trace")});
    mode_->setToolTip(tr("Follow the newest samples over a window of seconds, or show the whole trace"));
    bar->addWidget(mode_);
    window_ = new QDoubleSpinBox(bar);
    window_->setObjectName(QStringLiteral("plotWindowSeconds"));
    window_->setRange(0.1, 3600);
    window_->setDecimals(1);
    window_->setValue(10);
    window_->setSuffix(tr(" s"));
    window_->setToolTip(tr("Width of the rolling window"));
    bar->addWidget(window_);
    pause_ = bar->addAction(tr("Pause"));
    pause_->setCheckable(true);
    pause_->setToolTip(tr("Freeze the view (data keeps being recorded); zoom and pan pause too"));
    bar->widgetForAction(pause_)->setObjectName(QStringLiteral("plotPause"));
    bar->addSeparator();
    layout_ = new QComboBox(bar);
    layout_->setObjectName(QStringLiteral("plotLayout"));
    layout_->addItems({tr("Stacked"), tr("Shared plot")});
    layout_->setToolTip(tr("Stacked plots sharing the time axis, or one plot with a y-axis per signal"));
    bar->addWidget(layout_);
    QAction* fit = bar->addAction(tr("Autoscale"));
    fit->setToolTip(tr("Fit the y-axes to the visible data"));
    autoY_ = bar->addAction(tr("Auto Y"));
    autoY_->setCheckable(true);
    autoY_->setChecked(true);
    autoY_->setToolTip(tr("Keep the y-axes fitted; off: drag and wheel zoom the y-axes too"));
    legend_ = bar->addAction(tr("Legend"));
    legend_->setCheckable(true);
    legend_->setChecked(true);
    QAction* clearCursors = bar->addAction(tr("Clear cursors"));
    bar->addSeparator();
    QAction* raw = bar->addAction(tr("Add raw signal…"), this, &PlotDock::addRawSignal);
    raw->setToolTip(
        tr("Plot bits of any frame (start bit, length, type, byte order, factor, offset, unit): for devices without a "
           "dictionary"));
    bar->widgetForAction(raw)->setObjectName(QStringLiteral("addRawSignal"));
    auto* exportButton = new QToolButton(bar);
    exportButton->setObjectName(QStringLiteral("plotExport"));
    exportButton->setText(tr("Export"));
    exportButton->setPopupMode(QToolButton::InstantPopup);
    auto* menu = new QMenu(exportButton);
    menu->addAction(tr("PNG image…"), this, [this] { exportDialog(QStringLiteral("png")); });
    menu->addAction(tr("PDF document…"), this, [this] { exportDialog(QStringLiteral("pdf")); });
    menu->addAction(tr("CSV of the visible window…"), this, [this] { exportDialog(QStringLiteral("csv")); });
    exportButton->setMenu(menu);
    bar->addWidget(exportButton);

    connect(mode_, &QComboBox::currentIndexChanged, this, [this](int i) { setWholeTrace(i == 1); });
    connect(window_, &QDoubleSpinBox::valueChanged, this, [this] {
        if (!whole_) setPaused(false);
    });
    connect(pause_, &QAction::toggled, this, &PlotDock::setPaused);
    connect(layout_, &QComboBox::currentIndexChanged, this,
            [this](int i) { setLayoutMode(i ? PlotView::Layout::Overlay : PlotView::Layout::Stacked); });
    connect(fit, &QAction::triggered, this, [this] {
        view_->rescaleY();
        view_->refresh(true);
    });
    connect(autoY_, &QAction::toggled, this, [this](bool on) { view_->setAutoScaleY(on); });
    connect(legend_, &QAction::toggled, this, [this](bool on) { view_->setLegendVisible(on); });
    connect(clearCursors, &QAction::triggered, this, [this] {
        view_->setCursor(0, std::nullopt);
        view_->setCursor(1, std::nullopt);
    });
}

void PlotDock::rebind() {
    recorder_ = workspace_->signalRecorder();
    catalogRevision_ = 0;
    autoPicked_ = false;
    picker_->clear();
    view_->setCursor(0, std::nullopt);
    view_->setCursor(1, std::nullopt);
    // Offline: the whole file; live: the rolling window.
    setWholeTrace(!workspace_->isLive() && workspace_->loadJob());
    setPaused(false);
    view_->setTimeRange(0.0, whole_ ? 1.0 : window_->value());  // no axes of the previous source
    updatePlotted();
    picker_->setEmptyHint(emptyReason());
    hintTicks_ = 0;
}

void PlotDock::pick(const SignalKey& key, bool on) { picker_->setPicked(key, on); }
std::vector<SignalKey> PlotDock::pickedSignals() const { return picker_->picked(); }

void PlotDock::setPaused(bool paused) {
    if (paused_ == paused && pause_->isChecked() == paused) return;
    paused_ = paused;
    const QSignalBlocker block(pause_);
    pause_->setChecked(paused);
    pause_->setText(paused ? tr("Resume") : tr("Pause"));
    if (!paused) refresh();
}

void PlotDock::setWholeTrace(bool whole) {
    whole_ = whole;
    const QSignalBlocker block(mode_);
    mode_->setCurrentIndex(whole ? 1 : 0);
    window_->setEnabled(!whole);
    setPaused(false);
}

void PlotDock::setWindowSeconds(double seconds) { window_->setValue(seconds); }
double PlotDock::windowSeconds() const { return window_->value(); }

void PlotDock::setLayoutMode(PlotView::Layout layout) {
    const QSignalBlocker block(layout_);
    layout_->setCurrentIndex(layout == PlotView::Layout::Overlay ? 1 : 0);
    view_->setLayoutMode(layout);
}

void PlotDock::updatePlotted() {
    std::vector<PlotSignal> plotted;
    int colour = 0;
    for (const SignalKey& key : picker_->picked()) {
        const SignalInfo* info = picker_->info(key);
        if (!info) continue;
        PlotSignal s;
        s.key = key;
        s.name = localSignalName(*info);  // the manual's name for a bundled dictionary's object
        s.label = key.raw ? s.name
                          : QStringLiteral("n%1 %2").arg(key.node).arg(
                                info->digital ? s.name.section(QStringLiteral(": "), 1) : s.name);
        if (key.bus) s.label = QStringLiteral("bus%1 ").arg(key.bus) + s.label;
        s.scale = picker_->scale(key);
        s.digital = info->digital;
        s.hex = !s.digital && !key.raw && od::hexKindFor(key.index, key.sub) == od::HexKind::Pattern &&
                s.scale.factor == 1.0 && s.scale.offset == 0.0;
        s.color = plotColor(colour++);
        s.buffer = recorder_ ? recorder_->buffer(key) : nullptr;
        plotted.push_back(std::move(s));
    }
    view_->setSignals(std::move(plotted));
    updateReadout();
}

// With nothing picked: position actual 6064h and velocity actual 606Ch of the first node
// whose TPDOs carry both.
void PlotDock::autoPick() {
    if (autoPicked_ || !picker_->picked().empty() || !wanted_.empty()) return;
    const auto& cat = picker_->catalog();
    for (const SignalInfo& p : cat) {
        if (p.key.index != 0x6064 || p.key.sub != 0 || p.digital || !p.pdo.startsWith(QLatin1String("TPDO"))) continue;
        const auto v = std::find_if(cat.begin(), cat.end(), [&](const SignalInfo& s) {
            return s.key.bus == p.key.bus && s.key.node == p.key.node && s.key.index == 0x606C && s.key.sub == 0 &&
                   !s.digital && s.pdo.startsWith(QLatin1String("TPDO"));
        });
        if (v == cat.end()) continue;
        const SignalKey a = p.key, b = v->key;
        picker_->setPicked(a, true);
        picker_->setPicked(b, true);
        autoPicked_ = true;
        return;
    }
}

QJsonObject PlotDock::layoutJson() const {
    QJsonArray keys;
    for (const SignalKey& k : picker_->picked()) keys.append(k.text());
    for (const SignalKey& k : wanted_) keys.append(k.text());
    return {{QStringLiteral("signals"), keys},
            {QStringLiteral("layout"),
             view_->layoutMode() == PlotView::Layout::Overlay ? QStringLiteral("overlay") : QStringLiteral("stacked")},
            {QStringLiteral("windowSeconds"), window_->value()}};
}

void PlotDock::setLayoutJson(const QJsonObject& layout) {
    if (layout.isEmpty()) return;
    wanted_.clear();
    for (const QJsonValue v : layout.value(QStringLiteral("signals")).toArray()) {
        if (const auto key = SignalKey::parse(v.toString())) wanted_.push_back(*key);
        else spdlog::warn("project plot layout: '{}' is not a signal", v.toString().toStdString());
    }
    for (const SignalKey& k : picker_->picked()) picker_->setPicked(k, false);
    const bool overlay = layout.value(QStringLiteral("layout")).toString() == QLatin1String("overlay");
    layout_->setCurrentIndex(overlay ? 1 : 0);
    if (const double w = layout.value(QStringLiteral("windowSeconds")).toDouble(); w > 0) window_->setValue(w);
    pickWanted();
}

void PlotDock::pickWanted() {
    if (wanted_.empty()) return;
    autoPicked_ = true;  // the project chose
    std::erase_if(wanted_, [&](const SignalKey& k) {
        if (!picker_->info(k)) return false;
        picker_->setPicked(k, true);
        return true;
    });
}

void PlotDock::refresh() {
    if (workspace_->signalRecorder() != recorder_ && recorder_) {
        // The same trace recorded again (dictionaries assigned to a log): keep picks and view.
        recorder_ = workspace_->signalRecorder();
        catalogRevision_ = 0;
    }
    if (!recorder_) return;
    if (const uint64_t rev = recorder_->catalogRevision(); rev != catalogRevision_) {
        catalogRevision_ = rev;
        picker_->setCatalog(recorder_->catalog());
        if (pendingPick_ && picker_->info(*pendingPick_)) {
            picker_->setPicked(*pendingPick_, true);
            pendingPick_.reset();
        }
        pickWanted();
        autoPick();
        updatePlotted();  // default scales may have changed (vendor parameters seen)
    }
    // Nothing to offer: say why, a few times a second (frames and nodes keep coming).
    if (picker_->catalog().empty() && ++hintTicks_ % 10 == 1) picker_->setEmptyHint(emptyReason());
    const std::optional<int64_t> origin = recorder_->originNs();
    if (!origin) return;
    view_->setOrigin(*origin);
    if (!paused_) {
        const double end = std::max(0.0, double(recorder_->latestNs() - *origin) / 1e9);
        if (whole_) view_->setTimeRange(0.0, std::max(end, 1.0));
        else if (end < window_->value())
            view_->setTimeRange(0.0, window_->value());  // the first window fills from the left
        else view_->setTimeRange(end - window_->value(), end);
    }
    if (!view_->isVisible() && !paused_) return;  // hidden: nothing to draw
    if (view_->refresh() && (view_->cursor(0) || view_->cursor(1))) updateReadout();
}

bool PlotDock::hasContent() const {
    const auto& plotted = view_->plotted();
    if (plotted.empty()) return false;
    const auto [from, to] = view_->timeRange();
    const int64_t t0 = view_->toNs(from), t1 = view_->toNs(to);
    bool moving = false;
    for (const PlotSignal& s : plotted) {
        if (!s.buffer) return false;
        const std::optional<SignalSample> a = s.buffer->first(), z = s.buffer->last();
        if (!a || !z) return false;
        if (workspace_->isLive() && z->timeNs - a->timeNs < 5'000'000'000) return false;  // live: a few seconds of it
        const SignalRange r = s.buffer->range(t0, t1, s.digital ? s.key.bit : -1);
        if (!r.valid) return false;
        if (!s.digital && r.max > r.min) moving = true;
    }
    return moving;
}

QString PlotDock::emptyReason() const {
    const uint64_t frames = recorder_ ? recorder_->framesConsumed() : 0;
    if (frames == 0) {
        if (workspace_->isLive()) return tr("No frames from the bus yet.");
        if (workspace_->loadJob() && !workspace_->loadJob()->isDone()) return tr("Reading the log…");
        if (workspace_->loadJob()) return tr("The log holds no frames.");
        return tr("Nothing to plot: connect to a bus (Bus menu) or open a log (File ▸ Open log…).");
    }
    auto nodeName = [](int bus, int node) {
        return bus ? tr("bus %1 node %2").arg(bus).arg(node) : tr("node %1").arg(node);
    };
    const auto pdos = recorder_->pdosSeen();
    if (pdos.empty()) {
        QStringList nodes;
        for (const canopen::NodeInfo& n : workspace_->nodes().snapshot()) nodes << QString::number(n.node);
        QString text =
            tr("No PDOs in this trace (%L1 frames): the plot shows the objects that PDOs carry.").arg(frames);
        if (!nodes.isEmpty()) text += u' ' + tr("Nodes seen: %1.").arg(nodes.join(QStringLiteral(", ")));
        if (workspace_->isLive())
            text += u' ' + tr("Nodes send their PDOs once started (Nodes dock: right-click ▸ Start).");
        return text;
    }
    // The PDOs seen, by node; a node without a dictionary cannot have its PDOs decoded.
    std::map<std::pair<int, int>, QStringList> byNode;
    for (const auto& p : pdos) byNode[{p.bus, p.node}] << QStringLiteral("%1 %2").arg(p.pdo, od::hexText(p.cobId));
    QStringList withoutDictionary, unknownMapping;
    for (const auto& [key, list] : byNode) {
        const auto info = key.first == 0 ? workspace_->nodes().node(key.second) : std::nullopt;
        const QString line =
            QStringLiteral("%1 (%2)").arg(nodeName(key.first, key.second), list.join(QStringLiteral(", ")));
        if (info && !info->dictionary.isEmpty()) unknownMapping << line;
        else withoutDictionary << line;
    }
    QString text;
    if (!withoutDictionary.isEmpty())
        text = tr("No dictionary for these nodes, so their PDOs cannot be decoded: %1. Assign one in the Nodes dock "
                  "(right-click the node ▸ Assign dictionary…)%2; its PDO signals are then listed here.")
                   .arg(withoutDictionary.join(QStringLiteral("; ")),
                        workspace_->isLive() ? tr(" or identify the nodes with Bus ▸ Scan network") : QString());
    if (!unknownMapping.isEmpty()) {
        if (!text.isEmpty()) text += u' ';
        text += tr("PDOs whose mapping is not known (changed before the trace began): %1.")
                    .arg(unknownMapping.join(QStringLiteral("; ")));
    }
    return text;
}

// The COB-ID offered first: the first PDO seen whose objects are not listed (no dictionary).
uint32_t PlotDock::rawSignalCobIdHint() const {
    if (!recorder_) return 0;
    const auto pdos = recorder_->pdosSeen();
    for (const auto& p : pdos) {
        const auto& cat = picker_->catalog();
        const bool listed = std::any_of(cat.begin(), cat.end(), [&](const SignalInfo& s) {
            return !s.key.raw && s.key.bus == p.bus && s.key.node == p.node && s.pdo == p.pdo;
        });
        if (!listed) return p.cobId;
    }
    return pdos.empty() ? 0 : pdos.front().cobId;
}

void PlotDock::addRawSignal() {
    RawSignalDialog dialog(rawSignalCobIdHint(), this);
    if (dialog.exec() != QDialog::Accepted) return;
    pendingPick_ = workspace_->addRawSignal(dialog.signal());
    autoPicked_ = true;  // the user chose what to plot
    catalogRevision_ = 0;
    refresh();
    emit message(tr("Raw signal %1 added: it is listed under COB-ID %2h once its frames are read")
                     .arg(dialog.signal().name, QString::number(dialog.signal().cobId, 16).toUpper()));
}

void PlotDock::updateReadout() { readout_->setText(view_->readoutHtml()); }

bool PlotDock::exportPng(const QString& path, QString* error) {
    if (view_->savePng(path)) return true;
    if (error) *error = tr("%1: cannot write the PNG image").arg(path);
    return false;
}

bool PlotDock::exportPdf(const QString& path, QString* error) {
    if (view_->savePdf(path)) return true;
    if (error) *error = tr("%1: cannot write the PDF document").arg(path);
    return false;
}

bool PlotDock::exportCsv(const QString& path, QString* error) {
    const auto [from, to] = view_->timeRange();
    return writePlotCsv(path, view_->plotted(), view_->toNs(from), view_->toNs(to), view_->origin(), error);
}

void PlotDock::exportDialog(const QString& kind) {
    const QString filter = kind == u"png"   ? tr("PNG image (*.png)")
                           : kind == u"pdf" ? tr("PDF document (*.pdf)")
                                            : tr("CSV (*.csv)");
    QString path = files::askSaveFile(this, kind == u"csv" ? files::kExports : files::kPlotImages, tr("Export plot"),
                                      QStringLiteral("plot.%1").arg(kind), filter);
    if (path.isEmpty()) return;
    if (!path.endsWith(u'.' + kind, Qt::CaseInsensitive)) path += u'.' + kind;
    QString error;
    const bool ok = kind == u"png"   ? exportPng(path, &error)
                    : kind == u"pdf" ? exportPdf(path, &error)
                                     : exportCsv(path, &error);
    emit message(ok ? tr("Plot exported to %1").arg(path) : error);
}

}  // namespace coscope::gui
