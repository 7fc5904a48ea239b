// SPDX-License-Identifier: GPL-3.0-or-later
// Folder app/gui/plot/ owns the plot dock: signals picked from PDO mappings and SDO values, the
// plot view (cost follows pixels) and CSV export.
#pragma once

#include "app/gui/plot/PlotView.h"
#include "dissectors/SignalCatalog.h"

#include <QDockWidget>
#include <QJsonObject>

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

class QAction;
class QComboBox;
class QDoubleSpinBox;
class QLabel;

namespace coscope::dissect {
class SignalRecorder;
}

namespace coscope::gui {

class SignalPicker;
class Workspace;

// The Plot dock: PDO signals of any node, live from the bus or from a log (QCustomPlot).
// Left: the signal picker (search, per node the PDO-mapped objects, unit and factor); right:
// the plot with a toolbar (rolling window of N seconds or the whole trace, pause/resume,
// stacked or shared plot, autoscale, legend, cursors, export PNG/PDF/CSV) and the cursor
// readout. The samples come from the workspace's SignalRecorder (filled on the ingest
// thread); refresh() pulls them at the window's ≤ 30 Hz tick.
class PlotDock : public QDockWidget {
    Q_OBJECT
public:
    explicit PlotDock(Workspace* workspace, QWidget* parent = nullptr);
    ~PlotDock() override;

    void rebind();   // the workspace's source changed
    void refresh();  // the window's ≤ 30 Hz tick
    // True when there is something worth a screenshot (signals plotted with data).
    bool hasContent() const;

    // For the toolbar, scripts and tests.
    void pick(const dissect::SignalKey& key, bool on = true);
    std::vector<dissect::SignalKey> pickedSignals() const;
    void setPaused(bool paused);
    bool isPaused() const { return paused_; }
    void setWholeTrace(bool whole);
    bool wholeTrace() const { return whole_; }
    void setWindowSeconds(double seconds);
    double windowSeconds() const;
    void setLayoutMode(PlotView::Layout layout);
    // The plot layout a project keeps (ProjectSession): the picked signals (SignalKey::text),
    // stacked or overlaid, the rolling window's seconds. Signals not in the catalogue yet are
    // picked as soon as the trace shows them, on this source or the next.
    QJsonObject layoutJson() const;
    void setLayoutJson(const QJsonObject& layout);
    bool exportPng(const QString& path, QString* error = nullptr);
    bool exportPdf(const QString& path, QString* error = nullptr);
    bool exportCsv(const QString& path, QString* error = nullptr);  // the visible window
    PlotView* view() const { return view_; }
    SignalPicker* picker() const { return picker_; }

signals:
    void message(const QString& text);
    void frameActivated(uint32_t frame);  // a click in the plot: jump to this trace frame

private:
    void buildToolbar(QWidget* host);
    void updatePlotted();
    void autoPick();
    void pickWanted();  // wanted_ signals the catalogue now has
    void exportDialog(const QString& kind);
    // "Add raw signal…": a signal of any frame defined by hand, kept by the workspace and
    // picked once the trace shows it.
    void addRawSignal();
    uint32_t rawSignalCobIdHint() const;
    void updateReadout();
    // Why the signal list is empty and what could be plotted (nodes, PDOs seen, the Nodes dock's
    // Assign dictionary); shown by the picker while it has no signal.
    QString emptyReason() const;

    Workspace* workspace_;
    std::shared_ptr<dissect::SignalRecorder> recorder_;
    SignalPicker* picker_ = nullptr;
    PlotView* view_ = nullptr;
    QLabel* readout_ = nullptr;
    QComboBox* mode_ = nullptr;
    QDoubleSpinBox* window_ = nullptr;
    QAction* pause_ = nullptr;
    QComboBox* layout_ = nullptr;
    QAction* autoY_ = nullptr;
    QAction* legend_ = nullptr;
    uint64_t catalogRevision_ = 0;
    std::optional<dissect::SignalKey> pendingPick_;  // a raw signal just added
    std::vector<dissect::SignalKey> wanted_;         // a project's picks the catalogue lacks yet
    bool autoPicked_ = false;
    bool paused_ = false;
    bool whole_ = false;
    int hintTicks_ = 0;
};

}  // namespace coscope::gui
