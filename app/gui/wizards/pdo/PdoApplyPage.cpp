// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/wizards/pdo/PdoApplyPage.h"

#include "app/gui/wizards/common/ScriptPreview.h"
#include "app/gui/wizards/common/WizardGuard.h"
#include "app/gui/wizards/pdo/PdoWizard.h"

#include <QCheckBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>

namespace coscope::gui {

PdoApplyPage::PdoApplyPage(PdoWizard* wizard) : wizard_(wizard) {
    setTitle(tr("Check and apply"));
    setSubTitle(
        tr("This is exactly what will be sent, step by step (dry run: nothing has been sent yet). "
           "If the drive refuses a step, the wizard stops, tells you why and writes the old settings back."));
    preview_ = new ScriptPreview(this);
    preview_->setObjectName(QStringLiteral("pdoPreview"));
    store_ = new QCheckBox(tr("Keep after power-off: store the drive's parameters (1010h:01 = \"save\")"), this);
    store_->setObjectName(QStringLiteral("pdoStore"));
    start_ = new QCheckBox(tr("Start the drive's process data afterwards (NMT start: operational)"), this);
    start_->setObjectName(QStringLiteral("pdoStart"));
    apply_ = new QPushButton(tr("Apply to the drive"), this);
    apply_->setObjectName(QStringLiteral("pdoApply"));
    guard_ = new QLabel(this);
    guard_->setWordWrap(true);
    guard_->setStyleSheet(QStringLiteral("color: #b00020"));
    result_ = new QLabel(this);
    result_->setObjectName(QStringLiteral("pdoResult"));
    result_->setWordWrap(true);
    result_->setTextInteractionFlags(Qt::TextSelectableByMouse);

    auto* options = new QHBoxLayout;
    auto* checks = new QVBoxLayout;
    checks->addWidget(store_);
    checks->addWidget(start_);
    options->addLayout(checks, 1);
    options->addWidget(apply_, 0, Qt::AlignBottom);
    auto* banner = new WizardGuard(wizard_->workspace(), this);
    banner->addSender(apply_);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(banner);
    layout->addWidget(preview_, 2);
    layout->addLayout(options);
    layout->addWidget(guard_);
    layout->addWidget(result_);
    auto* slot = new QVBoxLayout;
    slot->setObjectName(QStringLiteral("framesSlot"));
    layout->addLayout(slot, 1);

    connect(store_, &QCheckBox::toggled, this, [this](bool on) { wizard_->setStoreAfterApply(on); });
    connect(start_, &QCheckBox::toggled, this, [this](bool on) { wizard_->setStartAfterApply(on); });
    connect(apply_, &QPushButton::clicked, this, [this] {
        QString why;
        if (!wizard_->apply(&why)) guard_->setText(why);
        showOutcome();
    });
    connect(wizard_, &PdoWizard::applyFinished, this, [this] {
        showOutcome();
        emit completeChanged();
    });
}

void PdoApplyPage::initializePage() {
    store_->setEnabled(wizard_->canStore());
    store_->setToolTip(wizard_->canStore()
                           ? tr("Without this the new mapping is lost when the drive is switched off or reset")
                           : tr("This drive's dictionary has no 1010h (store parameters)"));
    if (!wizard_->canStore()) wizard_->setStoreAfterApply(false);
    syncOptions();
    showOutcome();
}

void PdoApplyPage::syncOptions() {
    store_->setChecked(wizard_->storeAfterApply());
    start_->setChecked(wizard_->startAfterApply());
    if (wizard_->currentId() == PdoWizard::ApplyPageId) refreshPreview();
}

bool PdoApplyPage::isComplete() const { return !wizard_->isApplying(); }

void PdoApplyPage::refreshPreview() {
    QString error;
    const canopen::CommandScript script = wizard_->dryRun(&error);
    preview_->setScript(script);
    const QString refusal = wizard_->sendRefusal();
    guard_->setText(!refusal.isEmpty() ? refusal : error);
    apply_->setEnabled(refusal.isEmpty() && error.isEmpty() && !wizard_->isApplying());
}

void PdoApplyPage::showOutcome() {
    apply_->setEnabled(wizard_->sendRefusal().isEmpty() && !wizard_->isApplying());
    apply_->setText(wizard_->isApplying() ? tr("Applying…") : tr("Apply to the drive"));
    QString html;
    switch (wizard_->outcome()) {
    case PdoWizard::Outcome::None: break;
    case PdoWizard::Outcome::Succeeded:
        html =
            QStringLiteral("<span style='color:#1b5e20'><b>%1</b></span>").arg(wizard_->outcomeText().toHtmlEscaped());
        break;
    case PdoWizard::Outcome::Failed:
        html = QStringLiteral("<span style='color:#b00020'>%1</span>")
                   .arg(wizard_->outcomeText().toHtmlEscaped().replace(QLatin1Char('\n'), QStringLiteral("<br>")));
        break;
    }
    result_->setText(html);
}

QString PdoApplyPage::resultText() const { return wizard_->outcomeText(); }

}  // namespace coscope::gui
