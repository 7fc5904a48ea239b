// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/Screenshot.h"

#include "app/gui/MainWindow.h"
#include "app/gui/events/EventsDock.h"
#include "app/gui/events/EventsModel.h"
#include "app/gui/nodes/NodesDock.h"
#include "app/gui/nodes/NodesModel.h"
#include "app/gui/od/ObjectDictionaryDock.h"
#include "app/gui/plot/PlotDock.h"
#include "app/gui/project/CompareDialog.h"
#include "app/gui/project/ProjectActions.h"
#include "app/gui/session/Workspace.h"
#include "app/gui/trace/TraceDock.h"
#include "app/gui/trace/TraceModel.h"
#include "app/gui/trace/TraceView.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QTableView>
#include <QTimer>

#include <cstdio>
#include <memory>

namespace coscope::gui {

bool viewHasContent(MainWindow* w, const QString& view) {
    Workspace* ws = w->workspace();
    if (ws->loadJob() && !ws->loadJob()->isDone()) return false;
    const bool offline = ws->loadJob() != nullptr;
    const int rows = w->traceDock()->model()->rowCount();
    if (view == u"nodes") return w->nodesDock()->model()->rowCount() > 0 && (offline || rows > 50);
    if (view == u"events") return w->eventsDock()->model()->rowCount() > 0;
    if (view == u"od") return w->odDock()->hasContent();
    if (view == u"plot") return w->plotDock()->hasContent();
    if (view == u"project-compare") return w->projectActions()->compareDialog() && w->projectActions()->compareDialog()->hasResult();
    if (view.startsWith(QLatin1String("wizard-"))) {
        // Opened by showStartView once nodes are known; ready when the wizard says so (property
        // "screenshotReady").
        if (!w->openedWizard()) return false;
        const QVariant ready = w->openedWizard()->property("screenshotReady");
        return !ready.isValid() || ready.toBool();
    }
    return rows > (offline ? 0 : 60);
}

void takeScreenshotWhenReady(MainWindow* window, const QString& file, const QString& view) {
    auto* timer = new QTimer(window);
    auto clock = std::make_shared<QElapsedTimer>();
    auto readySince = std::make_shared<qint64>(-1);
    clock->start();
    timer->setInterval(100);
    QObject::connect(timer, &QTimer::timeout, window, [=] {
        const bool ready = viewHasContent(window, view);
        if (ready && *readySince < 0) *readySince = clock->elapsed();
        // Settle 1.5 s after content appeared (more rows, nodes identified), or give up at 20 s.
        if (!(ready && clock->elapsed() - *readySince > 1500) && clock->elapsed() < 20000) return;
        timer->stop();
        window->refresh();
        if (view == u"trace") {  // show a decoded frame in the details pane
            TraceView* tv = window->traceDock()->view();
            const int rows = window->traceDock()->model()->rowCount();
            if (rows > 0) {
                window->traceDock()->setFollow(false);
                // A TPDO near the end if there is one (named signals), else a row near the end.
                const TraceModel* m = window->traceDock()->model();
                int pick = std::max(0, rows - 8);
                for (int r = rows - 4; r >= 0 && r > rows - 200; --r)
                    if (m->data(m->index(r, TraceModel::Service), Qt::DisplayRole).toString().startsWith(QLatin1String("TPDO"))) {
                        pick = r;
                        break;
                    }
                tv->setCurrentRow(pick, false);
                tv->scrollToEnd();
            }
        }
        QApplication::processEvents();
        QWidget* shown = view.startsWith(QLatin1String("wizard-")) && window->openedWizard() ? window->openedWizard() : window;
        if (view == u"project-compare" && window->projectActions()->compareDialog()) shown = window->projectActions()->compareDialog();
        const bool ok = shown->grab().save(file, "PNG");
        std::fprintf(ok ? stdout : stderr, ok ? "screenshot written to %s\n" : "coscope: cannot write screenshot %s\n", qPrintable(file));
        QApplication::exit(ok ? 0 : 1);
    });
    timer->start();
}

}  // namespace coscope::gui
