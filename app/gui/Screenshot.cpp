// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/Screenshot.h"

#include "app/gui/MainWindow.h"
#include "app/gui/events/EventsDock.h"
#include "app/gui/events/EventsModel.h"
#include "app/gui/help/HelpWindow.h"
#include "app/gui/nodes/NodesDock.h"
#include "app/gui/nodes/NodesModel.h"
#include "app/gui/od/ObjectDictionaryDock.h"
#include "app/gui/plot/PlotDock.h"
#include "app/gui/program/ProgramDownloadDialog.h"
#include "app/gui/project/CompareDialog.h"
#include "app/gui/project/ProjectActions.h"
#include "app/gui/session/Workspace.h"
#include "app/gui/trace/TraceDock.h"
#include "app/gui/trace/TraceModel.h"
#include "app/gui/trace/TraceView.h"
#include "core/sim/ProgramImage.h"

#include <QApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QPointer>
#include <QTableView>
#include <QTimer>

#include <cstdio>
#include <memory>

namespace coscope::gui {

namespace {
// "program-download": the dialog of node 1's program download frozen mid-transfer (a 1 MiB
// image of the virtual drives' format, block SDO). Opened once node 1 is known; ready while the
// progress is between 35 % and 65 %.
bool programDownloadMidway(MainWindow* w) {
    static QPointer<ProgramDownloadDialog> dialog;
    if (!dialog) {
        if (w->nodesDock()->model()->rowOfNode(1) < 0 || !w->workspace()->canTransmit()) return false;
        const QString path = QDir::temp().filePath(QStringLiteral("coscope-drive-firmware-2.0.img"));
        QFile f(path);
        if (!f.open(QIODevice::WriteOnly)) return false;
        QByteArray payload(1024 * 1024, Qt::Uninitialized);
        for (qsizetype i = 0; i < payload.size(); ++i) payload[i] = static_cast<char>((i * 7919) >> 3);
        f.write(sim::makeProgramImage(payload, QStringLiteral("2.0.0")));
        f.close();
        dialog = w->nodesDock()->openProgramDownload(1);
        if (!dialog) return false;
        dialog->setImageFile(path);
        dialog->startDownload(false);
        return false;
    }
    return dialog->progressPermille() >= 350 && dialog->progressPermille() <= 650;
}
}  // namespace

bool viewHasContent(MainWindow* w, const QString& view) {
    Workspace* ws = w->workspace();
    if (ws->loadJob() && !ws->loadJob()->isDone()) return false;
    const bool offline = ws->loadJob() != nullptr;
    const int rows = w->traceDock()->model()->rowCount();
    if (view == u"nodes") return w->nodesDock()->model()->rowCount() > 0 && (offline || rows > 50);
    if (view == u"events") return w->eventsDock()->model()->rowCount() > 0;
    if (view == u"od") return w->odDock()->hasContent();
    if (view == u"plot") return w->plotDock()->hasContent();
    if (view == u"help") return help::HelpWindow::of(w) && help::HelpWindow::of(w)->isVisible();
    if (view == u"program-download") return programDownloadMidway(w);
    if (view == u"project-compare")
        return w->projectActions()->compareDialog() && w->projectActions()->compareDialog()->hasResult();
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
        // A transfer in progress is taken at once (it would be over after the settling).
        const bool midway = view == u"program-download";
        if (!(ready && (midway || clock->elapsed() - *readySince > 1500)) && clock->elapsed() < 20000) return;
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
                    if (m->data(m->index(r, TraceModel::Service), Qt::DisplayRole)
                            .toString()
                            .startsWith(QLatin1String("TPDO"))) {
                        pick = r;
                        break;
                    }
                tv->setCurrentRow(pick, false);
                tv->scrollToEnd();
            }
        }
        QApplication::processEvents();
        QWidget* shown = view.startsWith(QLatin1String("wizard-")) && window->openedWizard() ? window->openedWizard()
                         : view == u"help" && help::HelpWindow::of(window) ? help::HelpWindow::of(window)
                                                                           : static_cast<QWidget*>(window);
        if (midway)
            if (auto* d = window->nodesDock()->findChild<ProgramDownloadDialog*>()) shown = d;
        if (view == u"project-compare" && window->projectActions()->compareDialog())
            shown = window->projectActions()->compareDialog();
        const bool ok = shown->grab().save(file, "PNG");
        std::fprintf(ok ? stdout : stderr, ok ? "screenshot written to %s\n" : "coscope: cannot write screenshot %s\n",
                     qPrintable(file));
        QApplication::exit(ok ? 0 : 1);
    });
    timer->start();
}

}  // namespace coscope::gui
