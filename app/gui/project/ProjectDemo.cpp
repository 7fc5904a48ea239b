// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/project/ProjectDemo.h"

#include "app/gui/MainWindow.h"
#include "app/gui/project/CompareDialog.h"
#include "app/gui/project/ProjectActions.h"
#include "app/gui/project/ProjectSession.h"
#include "app/gui/session/Workspace.h"
#include "core/canopen/SdoClient.h"
#include "core/project/ProjectBackup.h"
#include "core/sim/SimBus.h"
#include "core/sim/SimNetwork.h"
#include "core/sim/VirtualDevice.h"
#include "eds/ProjectDictionaries.h"
#include "eds/ScanMatcher.h"

#include <QPointer>
#include <QTimer>

namespace coscope::gui {

void startProjectCompareDemo(MainWindow* window) {
    auto* timer = new QTimer(window);
    timer->setInterval(100);
    QObject::connect(timer, &QTimer::timeout, window, [window, timer] {
        Workspace* ws = window->workspace();
        if (!ws->bus() || ws->bus()->state() != CanBus::State::Open || !ws->sdo() || !ws->nodes().node(3)) return;
        timer->stop();
        timer->deleteLater();
        auto* backup = new project::ProjectBackup(*ws->sdo(), eds::projectDictionaryResolver({}), window);
        backup->setMatcher(eds::scanMatcher());
        backup->setScanRange(1, 8);
        project::Project start;
        start.name = QStringLiteral("Packaging line 2");
        start.busUrl = ws->bus()->url().toString();
        QPointer<MainWindow> w(window);
        backup->start(start, {}, [w, backup](const project::Project& p, const std::vector<project::BackupNodeResult>&) {
            backup->deleteLater();
            if (!w) return;
            w->projectActions()->session()->setProject(p);
            auto* sim = dynamic_cast<SimBus*>(w->workspace()->bus());
            if (sim && sim->network()) {
                sim::SimNetwork* net = sim->network();
                net->runOnNetworkThread([net] {
                    if (auto* d = net->device(1)) {
                        d->setValue(0x1017, 0, od::Value::unsignedInt(500));
                        d->setValue(0x6081, 0, od::Value::unsignedInt(5000));
                    }
                });
                net->replaceDevice(3, 0x51000099);
            }
            QTimer::singleShot(500, w, [w] {
                if (w) w->projectActions()->showCompare();
            });
        });
    });
    timer->start();
}

}  // namespace coscope::gui
