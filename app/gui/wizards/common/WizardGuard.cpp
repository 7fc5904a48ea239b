// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/wizards/common/WizardGuard.h"

#include "app/gui/session/Workspace.h"

#include <QHBoxLayout>
#include <QLabel>

namespace coscope::gui {

WizardGuard::WizardGuard(Workspace* workspace, QWidget* parent) : QWidget(parent), workspace_(workspace) {
    setObjectName(QStringLiteral("wizardGuard"));
    text_ = new QLabel(this);
    text_->setWordWrap(true);
    text_->setTextFormat(Qt::PlainText);
    text_->setStyleSheet(
        QStringLiteral("QLabel { background: #fff3cd; color: #5c4400; border: 1px solid #e0c060; padding: 6px; }"));
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(text_);
    if (workspace) {
        connect(workspace, &Workspace::sourceChanged, this, &WizardGuard::refresh);
        connect(workspace, &Workspace::busStateChanged, this, &WizardGuard::refresh);
    }
    refresh();
}

bool WizardGuard::canSend() const { return workspace_ && workspace_->canTransmit(); }

QString WizardGuard::reason() const {
    if (canSend()) return {};
    if (!workspace_ || !workspace_->bus())
        return tr(
            "No bus is connected, so nothing can be sent. Connect to the bus first; you can still prepare the steps "
            "and save them as a script.");
    if (workspace_->bus()->isListenOnly())
        return tr(
            "The bus is open in listen-only mode: CoScope never transmits on it. Reconnect without listen-only to send "
            "these commands; "
            "you can still prepare the steps and save them as a script.");
    if (workspace_->bus()->state() == CanBus::State::Opening)
        return tr("The bus is still opening; sending is possible once it is open.");
    if (workspace_->bus()->state() == CanBus::State::Lost)
        return tr("The bus was lost (%1); CoScope is reconnecting. Sending is possible again once it is back.")
            .arg(workspace_->bus()->errorString());
    return tr("The bus is not open (%1), so nothing can be sent.").arg(toString(workspace_->bus()->state()));
}

void WizardGuard::addSender(QWidget* widget) {
    if (!widget) return;
    senders_.append(widget);
    widget->setEnabled(canSend());
}

void WizardGuard::refresh() {
    const bool ok = canSend();
    text_->setText(reason());
    setVisible(!ok);
    for (const auto& w : senders_)
        if (w) w->setEnabled(ok);
    if (last_ != static_cast<int>(ok)) {
        last_ = static_cast<int>(ok);
        emit canSendChanged(ok);
    }
}

}  // namespace coscope::gui
