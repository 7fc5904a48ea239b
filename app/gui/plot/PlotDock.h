// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QDockWidget>

#include <cstdint>

namespace coscope::gui {

class Workspace;

// The Plot dock: PDO signals of any node, live from the bus or from a log (QCustomPlot).
class PlotDock : public QDockWidget {
    Q_OBJECT
public:
    explicit PlotDock(Workspace* workspace, QWidget* parent = nullptr);

    void rebind();   // the workspace's source changed
    void refresh();  // the window's ≤ 30 Hz tick
    // True when there is something worth a screenshot (signals plotted with data).
    bool hasContent() const;

signals:
    void message(const QString& text);
    void frameActivated(uint32_t frame);  // a click in the plot: jump to this trace frame

private:
    Workspace* workspace_;
};

}  // namespace coscope::gui
