// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/master/HeartbeatGuardQuestion.h"

#include "app/gui/events/EventLog.h"
#include "app/gui/language/CoreText.h"
#include "app/gui/master/MasterSettings.h"
#include "app/gui/session/Workspace.h"
#include "core/canopen/HeartbeatGuard.h"

#include <QCheckBox>
#include <QMessageBox>
#include <QPushButton>
#include <QSettings>

#include <algorithm>

namespace coscope::gui {

using canopen::GuardedDrives;

const QString HeartbeatGuardQuestion::kSettingsKey = QStringLiteral("master/heartbeatGuard");

namespace {
// CoScope's heartbeat for the guard when the user did not ask for one in the master settings:
// 100 ms, so a drive stops within 300 ms (as `coscope-cli ds402 jog --watchdog`).
constexpr uint16_t kGuardHeartbeatMs = 100;
}  // namespace

HeartbeatGuardQuestion::HeartbeatGuardQuestion(Workspace* workspace, QWidget* window)
    : QObject(window), workspace_(workspace), window_(window) {}

HeartbeatGuardQuestion::~HeartbeatGuardQuestion() {
    if (box_) box_->deleteLater();
}

void HeartbeatGuardQuestion::refresh() {
    // A new bus brings new guards (maybe at the old one's address: the QPointer went null).
    GuardedDrives* guards = workspace_->guardedDrives();
    if (guards != guards_.data() || (!guards && box_)) bind(guards);
    if (guards_) guards_->poll();
}

void HeartbeatGuardQuestion::bind(GuardedDrives* guards) {
    guards_ = guards;
    waiting_.clear();
    if (box_) box_->deleteLater();  // about the bus that closed
    box_ = nullptr;
    asking_ = 0;
    if (!guards) return;
    applySettings();
    connect(guards, &GuardedDrives::consentNeeded, this, [this](int node, int) { consentNeeded(node); });
    connect(guards, &GuardedDrives::changed, this, &HeartbeatGuardQuestion::report);
    // Asked before this face existed (the window rebuilt its actions for another language).
    for (const GuardedDrives::Drive& d : guards->drives())
        if (d.state == GuardedDrives::State::Undecided) consentNeeded(d.node);
}

void HeartbeatGuardQuestion::consentNeeded(int node) {
    const QString remembered = QSettings().value(kSettingsKey).toString();
    if (remembered == u"always" || remembered == u"never") return answered(node, remembered == u"always", false);
    if (node == asking_ || std::find(waiting_.begin(), waiting_.end(), node) != waiting_.end()) return;
    waiting_.push_back(node);
    if (!box_) ask(waiting_.front());
}

void HeartbeatGuardQuestion::applySettings() {
    if (!guards_) return;
    const MasterSettings m = MasterSettings::load();
    guards_->setHeartbeat(static_cast<uint8_t>(m.heartbeatNode),
                          m.heartbeat ? static_cast<uint16_t>(m.heartbeatMs) : kGuardHeartbeatMs);
}

void HeartbeatGuardQuestion::ask(int node) {
    waiting_.pop_front();
    asking_ = node;
    const int periodMs = guards_->heartbeatPeriodMs();
    const int stopMs = canopen::HeartbeatGuard::consumerTimeFor(static_cast<uint16_t>(periodMs));
    auto* box = new QMessageBox(
        QMessageBox::Question, tr("Stop the drive if CoScope dies?"),
        tr("Node %1 is enabled by CoScope. Should it stop by itself if CoScope or the cable dies?").arg(node),
        QMessageBox::Yes | QMessageBox::No, window_);
    box->setObjectName(QStringLiteral("heartbeatGuardQuestion"));
    box->setInformativeText(
        tr("CoScope will produce its heartbeat (node %1) every %2 ms and set node %3's heartbeat consumer 1016h and "
           "its abort "
           "connection option 6007h (quick stop, where the drive has one), so the drive stops by itself within %4 ms "
           "when CoScope or the cable dies. The old values are put back when the drive is disabled or the bus closes.")
            .arg(guards_->heartbeatNode())
            .arg(periodMs)
            .arg(node)
            .arg(stopMs));
    box->button(QMessageBox::Yes)->setText(tr("Guard the drive"));
    box->button(QMessageBox::No)->setText(tr("Not now"));
    auto* remember = new QCheckBox(tr("Remember my answer"), box);
    remember->setObjectName(QStringLiteral("rememberAnswer"));
    box->setCheckBox(remember);
    box->setDefaultButton(QMessageBox::Yes);
    // Not modal: the panel that enabled the drive stays usable while the question is open.
    box->setWindowModality(Qt::NonModal);
    box->setAttribute(Qt::WA_DeleteOnClose);
    connect(box, &QMessageBox::finished, this, [this, box, node, remember] {
        if (box != box_) return;  // about a bus that closed
        box_ = nullptr;
        asking_ = 0;
        answered(node, box->clickedButton() == box->button(QMessageBox::Yes), remember->isChecked());
        if (!waiting_.empty()) ask(waiting_.front());
    });
    box_ = box;
    box->show();
}

void HeartbeatGuardQuestion::answered(int node, bool yes, bool remember) {
    if (remember) QSettings().setValue(kSettingsKey, yes ? QStringLiteral("always") : QStringLiteral("never"));
    if (!guards_) return;
    guards_->consent(static_cast<uint8_t>(node), yes);
    if (!yes)
        emit message(
            tr("Node %1 does not watch CoScope's heartbeat: if CoScope or the cable dies, it keeps its last command")
                .arg(node));
}

void HeartbeatGuardQuestion::report(int node, int axis, GuardedDrives::State state, const QString& text) {
    Q_UNUSED(axis);
    using State = GuardedDrives::State;
    if (state != State::Armed && state != State::Released && state != State::Failed) return;
    const bool failed = state == State::Failed;
    workspace_->events().add(renderedEvent(failed ? TraceEvent::Kind::BusError : TraceEvent::Kind::Info, nowNs(),
                                           kNoFrame, node, [text] { return coreText(text); }));
    if (failed) emit error(tr("Heartbeat guard: %1").arg(coreText(text)));
    else emit message(coreText(text));
}

}  // namespace coscope::gui
