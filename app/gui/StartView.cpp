// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/StartView.h"

#include "app/gui/MainWindow.h"
#include "app/gui/nodes/NodesDock.h"
#include "app/gui/nodes/NodesModel.h"
#include "app/gui/project/ProjectDemo.h"
#include "app/gui/session/Workspace.h"
#include "app/gui/trace/TraceDock.h"
#include "app/gui/trace/TraceModel.h"

#include <QElapsedTimer>
#include <QTimer>

#include <memory>

namespace coscope::gui {

namespace {
constexpr int kWaitForNodesMs = 10000;
}

void showStartView(MainWindow* window, const QString& view) {
    if (view == u"project-compare") return startProjectCompareDemo(window);
    if (!view.startsWith(QLatin1String("wizard-"))) {
        window->showView(view);
        return;
    }
    auto* timer = new QTimer(window);
    auto clock = std::make_shared<QElapsedTimer>();
    clock->start();
    timer->setInterval(100);
    QObject::connect(timer, &QTimer::timeout, window, [=] {
        // Live: wait until nodes were seen and some traffic identified them.
        const bool nodesKnown =
            window->nodesDock()->model()->rowCount() > 0 && window->traceDock()->model()->rowCount() >= 50;
        if (window->workspace()->isLive() && !nodesKnown && clock->elapsed() < kWaitForNodesMs) return;
        timer->stop();
        timer->deleteLater();
        window->showView(view);
    });
    timer->start();
}

}  // namespace coscope::gui
