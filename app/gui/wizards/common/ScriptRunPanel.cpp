// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/wizards/common/ScriptRunPanel.h"
#include "app/gui/language/CoreText.h"

#include "app/gui/wizards/common/BusLossAdvice.h"

#include "app/gui/session/Workspace.h"
#include "app/gui/wizards/common/ScriptPreview.h"
#include "app/gui/wizards/common/WizardGuard.h"
#include "core/canopen/SdoClient.h"

#include <QHBoxLayout>

#include <spdlog/spdlog.h>

#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QVBoxLayout>
#include <algorithm>

namespace coscope::gui {

ScriptRunPanel::ScriptRunPanel(Workspace* workspace, QWidget* parent) : QWidget(parent), workspace_(workspace) {
    guard_ = new WizardGuard(workspace, this);
    preview_ = new ScriptPreview(this);
    run_ = new QPushButton(tr("Run"), this);
    run_->setObjectName(QStringLiteral("runScript"));
    stop_ = new QPushButton(tr("Stop"), this);
    stop_->setObjectName(QStringLiteral("stopScript"));
    status_ = new QLabel(this);
    status_->setWordWrap(true);
    status_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    auto* buttons = new QHBoxLayout;
    buttons->addWidget(status_, 1);
    buttons->addWidget(run_);
    buttons->addWidget(stop_);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(guard_);
    layout->addWidget(preview_, 1);
    layout->addLayout(buttons);
    connect(run_, &QPushButton::clicked, this, &ScriptRunPanel::onRunClicked);
    connect(stop_, &QPushButton::clicked, this, &ScriptRunPanel::stop);
    connect(guard_, &WizardGuard::canSendChanged, this, &ScriptRunPanel::updateButtons);
    if (workspace)
        connect(workspace, &Workspace::sourceChanged, this, [this] {
            if (isRunning()) {
                stop();
                setStatus(tr("Stopped: the connection changed."));
            }
            runner_.reset();  // it refers to the old bus's services
        });
    // A lost adapter stops a run at once and says what the device may be left in (issue 16).
    if (workspace)
        connect(workspace, &Workspace::busStateChanged, this, [this, workspace](CanBus::State s) {
            if (s != CanBus::State::Lost || !isRunning()) return;
            const int step = std::max(0, runner_->currentStep());
            stopReason_ = BusLossAdvice::scriptMessage(workspace->bus() ? workspace->bus()->errorString() : QString(),
                                                       step, static_cast<int>(preview_->script().steps.size()));
            spdlog::warn("script run stopped: bus lost at step {}", step + 1);
            stop();
            setStatus(stopReason_);
        });
    updateButtons();
}

ScriptRunPanel::~ScriptRunPanel() {
    if (runner_) runner_->cancel();
}

void ScriptRunPanel::setScript(const canopen::CommandScript& script) {
    if (isRunning()) stop();
    preview_->setScript(script);
    setStatus(QString());
    updateButtons();
}

const canopen::CommandScript& ScriptRunPanel::script() const { return preview_->script(); }

bool ScriptRunPanel::isRunning() const { return runner_ && runner_->isRunning(); }

QString ScriptRunPanel::statusText() const { return status_->text(); }

void ScriptRunPanel::setStatus(const QString& text) { status_->setText(text); }

void ScriptRunPanel::updateButtons() {
    const bool running = isRunning();
    run_->setEnabled(!running && guard_->canSend() && !preview_->script().steps.empty());
    stop_->setEnabled(running);
}

void ScriptRunPanel::onRunClicked() {
    if (!confirmation_.isEmpty() &&
        QMessageBox::question(this, tr("Send these commands?"), confirmation_, QMessageBox::Yes | QMessageBox::No,
                              QMessageBox::No) != QMessageBox::Yes)
        return;
    QString why;
    if (!run(&why)) setStatus(why);
}

bool ScriptRunPanel::run(QString* why) {
    if (isRunning()) {
        if (why) *why = tr("A run is in progress.");
        return false;
    }
    if (!guard_->canSend() || !workspace_ || !workspace_->master() || !workspace_->sdo()) {
        if (why) *why = guard_->reason().isEmpty() ? tr("The bus cannot send now.") : guard_->reason();
        return false;
    }
    if (!runner_) {
        runner_ = std::make_unique<canopen::ScriptRunner>(*workspace_->master(), *workspace_->sdo());
        connect(runner_.get(), &canopen::ScriptRunner::stepStarted, this, [this](int step) {
            preview_->markRunning(step);
            setStatus(tr("Step %1 of %2…").arg(step + 1).arg(preview_->rowCount()));
        });
        connect(runner_.get(), &canopen::ScriptRunner::stepFinished, preview_, &ScriptPreview::markStep);
    }
    preview_->clearMarks();
    stopReason_.clear();
    const bool ok = runner_->run(preview_->script(), [this](const canopen::ScriptRunResult& r) {
        if (r.ok) setStatus(tr("Done: %n step(s) completed.", nullptr, r.stepsDone));
        else if (r.cancelled)
            setStatus(stopReason_.isEmpty() ? tr("Stopped at step %1; nothing further was sent.").arg(r.failedStep + 1)
                                            : stopReason_);
        else setStatus(tr("Failed at %1").arg(coreText(r.error)));
        updateButtons();
        emit finished(r);
    });
    if (!ok) {
        if (why) *why = tr("A run is in progress.");
        return false;
    }
    updateButtons();
    emit started();
    return true;
}

void ScriptRunPanel::stop() {
    if (runner_) runner_->cancel();
    updateButtons();
}

}  // namespace coscope::gui
