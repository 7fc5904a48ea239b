// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/session/EnabledDrivesQuestion.h"

#include "app/gui/session/Workspace.h"
#include "core/canopen/MasterContext.h"

#include <QLocale>
#include <QMessageBox>
#include <QPushButton>
#include <QStringList>

#include <spdlog/spdlog.h>

namespace coscope::gui {

QString EnabledDrivesQuestion::text(const QString& nodes, int count, Closing closing) {
    const bool one = count == 1;
    switch (closing) {
    case Closing::Quit:
        return one ? tr("Node %1 is enabled by CoScope: disable it and quit?").arg(nodes)
                   : tr("Nodes %1 are enabled by CoScope: disable them and quit?").arg(nodes);
    case Closing::Disconnect:
        return one ? tr("Node %1 is enabled by CoScope: disable it and disconnect?").arg(nodes)
                   : tr("Nodes %1 are enabled by CoScope: disable them and disconnect?").arg(nodes);
    case Closing::Connect:
        return one ? tr("Node %1 is enabled by CoScope: disable it and connect anew?").arg(nodes)
                   : tr("Nodes %1 are enabled by CoScope: disable them and connect anew?").arg(nodes);
    case Closing::OpenLog:
        return one ? tr("Node %1 is enabled by CoScope: disable it and open the log?").arg(nodes)
                   : tr("Nodes %1 are enabled by CoScope: disable them and open the log?").arg(nodes);
    }
    return {};
}

bool EnabledDrivesQuestion::confirm(QWidget* parent, Workspace* workspace, Closing closing, bool quiet) {
    canopen::MasterContext* master = workspace ? workspace->master() : nullptr;
    if (!master || master->enabledDrives().isEmpty()) return true;
    QStringList names;
    const auto drives = master->enabledDrives().drives();
    for (const auto& d : drives)
        names << (d.axis ? tr("%1 (axis %2)").arg(d.node).arg(d.axis) : QString::number(d.node));
    const QString nodes = QLocale().createSeparatedList(names);
    if (quiet) {
        spdlog::warn("closing the bus: disabling {} enabled by CoScope", master->enabledDrives().names().toStdString());
        return true;
    }
    QMessageBox box(QMessageBox::Warning, tr("Drive enabled"), text(nodes, int(drives.size()), closing),
                    QMessageBox::Yes | QMessageBox::Cancel, parent);
    box.setInformativeText(
        tr("CoScope sends Disable voltage (6040h = 0000h; Quick stop first to a drive that may be moving) and waits to "
           "see it on the bus before the connection closes. Cancel leaves everything as it is."));
    const char* yes = closing == Closing::Quit         ? QT_TR_NOOP("Disable and quit")
                      : closing == Closing::Disconnect ? QT_TR_NOOP("Disable and disconnect")
                      : closing == Closing::Connect    ? QT_TR_NOOP("Disable and connect")
                                                       : QT_TR_NOOP("Disable and open the log");
    box.button(QMessageBox::Yes)->setText(tr(yes));
    box.setDefaultButton(QMessageBox::Cancel);
    return box.exec() == QMessageBox::Yes;
}

}  // namespace coscope::gui
