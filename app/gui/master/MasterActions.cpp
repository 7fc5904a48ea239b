// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/master/MasterActions.h"

#include "app/gui/language/CoreText.h"
#include "app/gui/master/HeartbeatGuardQuestion.h"
#include "app/gui/master/MasterSettings.h"
#include "app/gui/master/MasterSettingsDialog.h"
#include "app/gui/session/Workspace.h"
#include "core/canopen/GuardedDrives.h"
#include "core/canopen/HeartbeatProducer.h"
#include "core/canopen/SdoClient.h"
#include "core/canopen/SyncProducer.h"

#include <QAction>
#include <QApplication>
#include <QLocale>
#include <QPointer>
#include <QStyle>
#include <QWidget>

#include <memory>

#include <spdlog/spdlog.h>

namespace coscope::gui {

MasterActions::MasterActions(Workspace* workspace, QWidget* window)
    : QObject(window), workspace_(workspace), window_(window) {
    sync_ = new QAction(window->style()->standardIcon(QStyle::SP_MediaPlay), tr("&SYNC producer"), this);
    sync_->setObjectName(QStringLiteral("syncAction"));
    sync_->setIconText(tr("SYNC"));
    sync_->setCheckable(true);
    sync_->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_Y));
    connect(sync_, &QAction::triggered, this, [this](bool on) {
        if (!on) {
            stopSync();
            emit message(tr("SYNC stopped"));
            return;
        }
        QString why;
        if (!startSync(&why)) {
            sync_->setChecked(false);
            emit error(tr("Cannot start SYNC: %1").arg(why));
        }
    });
    settings_ = new QAction(tr("&Master settings…"), this);
    settings_->setObjectName(QStringLiteral("masterSettingsAction"));
    connect(settings_, &QAction::triggered, this, &MasterActions::showSettings);
    guardQuestion_ = new HeartbeatGuardQuestion(workspace, window);
    guardQuestion_->setParent(this);  // the window rebuilds its actions when the language changes
    connect(guardQuestion_, &HeartbeatGuardQuestion::message, this, &MasterActions::message);
    connect(guardQuestion_, &HeartbeatGuardQuestion::error, this, &MasterActions::error);
    refresh();
}

bool MasterActions::startSync(QString* error) {
    canopen::SyncProducer* sync = workspace_->syncProducer();
    if (!sync || !workspace_->canTransmit()) {
        if (error)
            *error = workspace_->bus() && workspace_->bus()->isListenOnly() ? tr("the bus is listen-only")
                                                                            : tr("no bus is open");
        return false;
    }
    const MasterSettings m = MasterSettings::load();
    sync->setPeriodUs(m.syncPeriodUs);
    sync->setCounterOverflow(m.syncCounter);
    sync->setCobId(m.syncCobId);
    QString why;
    if (!sync->start(&why)) {
        if (error) *error = coreText(why);
        return false;
    }
    spdlog::info("SYNC started: {} µs, counter {}, COB-ID {:X}h", m.syncPeriodUs, m.syncCounter, m.syncCobId);
    emit message(
        tr("SYNC every %1 on %2h")
            .arg(MasterSettings::periodText(m.syncPeriodUs), QString::number(m.syncCobId & 0x1FFFFFFF, 16).toUpper()));
    if (m.writeCyclePeriod) writeCyclePeriod(m.syncPeriodUs);
    sync_->setChecked(true);
    return true;
}

void MasterActions::stopSync() {
    if (canopen::SyncProducer* sync = workspace_->syncProducer()) sync->stop();
    sync_->setChecked(false);
}

// 1006h of every node known on the bus, one SDO download each (never retried); one message
// with the outcome.
void MasterActions::writeCyclePeriod(uint32_t periodUs) {
    canopen::SyncProducer* sync = workspace_->syncProducer();
    canopen::SdoClient* sdo = workspace_->sdo();
    if (!sync || !sdo) return;
    struct Tally {
        int pending = 0;
        QStringList failed;
        int ok = 0;
    };
    auto tally = std::make_shared<Tally>();
    QPointer<MasterActions> self(this);
    for (const canopen::NodeInfo& n : workspace_->nodes().snapshot()) {
        ++tally->pending;
        const int node = n.node;
        sync->writeCommunicationCyclePeriod(
            *sdo, static_cast<uint8_t>(node), [self, tally, node, periodUs](const canopen::SdoResult& r) {
                if (r.ok) ++tally->ok;
                else tally->failed << tr("node %1 (%2)").arg(node).arg(coreText(r.error));
                if (--tally->pending > 0 || !self) return;
                if (tally->failed.isEmpty())
                    emit self->message(tr("1006h = %1 µs written to %n node(s)", nullptr, tally->ok).arg(periodUs));
                else emit self->error(tr("1006h not written to %1").arg(tally->failed.join(QStringLiteral(", "))));
            });
    }
}

void MasterActions::showSettings() {
    auto* dialog = new MasterSettingsDialog(window_);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    connect(dialog, &MasterSettingsDialog::applied, this, [this] {
        // A running SYNC takes the new period, counter and COB-ID at once.
        if (canopen::SyncProducer* sync = workspace_->syncProducer(); sync && sync->isRunning()) {
            QString why;
            if (!startSync(&why)) emit error(tr("Cannot start SYNC: %1").arg(why));
        }
        heartbeatFor_ = nullptr;  // set up again with the new settings
        applyHeartbeat();
        guardQuestion_->applySettings();
    });
    dialog->open();
}

// CoScope's heartbeat runs while the bus can transmit and the settings ask for it.
void MasterActions::applyHeartbeat() {
    canopen::HeartbeatProducer* hb = workspace_->heartbeatProducer();
    if (!hb || !workspace_->canTransmit()) return;
    if (heartbeatFor_ == hb) return;
    // A drive watches it (GuardedDrives): stopping it or changing its node-ID would make the
    // drive stop. The new settings apply once no drive watches it any more.
    if (canopen::GuardedDrives* guards = workspace_->guardedDrives(); guards && guards->holdsHeartbeat()) {
        if (!heartbeatHeld_)
            emit message(
                tr("CoScope's heartbeat keeps running as it is while a drive watches it; the new settings apply once "
                   "it is released"));
        heartbeatHeld_ = true;
        return;
    }
    heartbeatHeld_ = false;
    heartbeatFor_ = hb;
    const MasterSettings m = MasterSettings::load();
    hb->stop();
    if (!m.heartbeat) return;
    hb->setNodeId(static_cast<uint8_t>(m.heartbeatNode));
    hb->setPeriodMs(m.heartbeatMs);
    QString why;
    if (!hb->start(&why)) emit error(tr("Cannot start CoScope's heartbeat: %1").arg(coreText(why)));
}

void MasterActions::refresh() {
    const bool can = workspace_->canTransmit();
    QString why;
    if (!workspace_->bus()) why = tr("Connect to a bus first");
    else if (workspace_->bus()->isListenOnly()) why = tr("Listen-only connection: CoScope sends nothing");
    else if (!can) why = tr("The bus is not open");
    sync_->setEnabled(can || sync_->isChecked());
    sync_->setToolTip(why.isEmpty() ? tr("Start or stop the SYNC producer (Bus ▸ Master settings… sets its period)")
                                    : why);
    canopen::SyncProducer* sync = workspace_->syncProducer();
    const bool running = sync && sync->isRunning();
    if (sync_->isChecked() != running) sync_->setChecked(running);
    if (sync && !running && !sync->lastError().isEmpty() &&
        sync_->property("reported").toString() != sync->lastError()) {
        sync_->setProperty("reported", sync->lastError());
        emit error(tr("SYNC stopped: %1").arg(coreText(sync->lastError())));
    }
    if (!workspace_->heartbeatProducer()) heartbeatFor_ = nullptr;
    applyHeartbeat();
    guardQuestion_->refresh();
}

QString MasterActions::statusText() const {
    QStringList parts;
    if (canopen::SyncProducer* sync = workspace_->syncProducer(); sync && sync->isRunning())
        parts << tr("SYNC %1 (%L2)").arg(MasterSettings::periodText(sync->periodUs())).arg(sync->sent());
    if (canopen::HeartbeatProducer* hb = workspace_->heartbeatProducer(); hb && hb->isRunning())
        parts << tr("Heartbeat %1 ms").arg(hb->periodMs());
    if (canopen::GuardedDrives* guards = workspace_->guardedDrives()) {
        QStringList nodes;
        for (uint8_t n : guards->guardedNodes()) nodes << QString::number(n);
        if (!nodes.isEmpty())
            parts << tr("guarding node %1", nullptr, int(nodes.size())).arg(QLocale().createSeparatedList(nodes));
    }
    return parts.join(QStringLiteral(" · "));
}

}  // namespace coscope::gui
