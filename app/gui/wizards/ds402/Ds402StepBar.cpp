// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/wizards/ds402/Ds402StepBar.h"

#include "app/gui/language/CoreText.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>

namespace coscope::gui {

using canopen::ds402::Command;
using canopen::ds402::State;

QString ds402StepExplanation(Command c) {
    switch (c) {
    case Command::FaultReset:
        return QObject::tr(
            "Fault reset (transition 15): clears the fault once its cause is removed. Sends controlword 6040h = 0000h, "
            "then "
            "0080h (bit 7 rising). Expect Switch on disabled: fault bit 3 off, bit 6 on.");
    case Command::Shutdown:
        return QObject::tr(
            "Shutdown (transition 2): gets the drive ready, the motor stays without power. Sends 6040h = 0006h. "
            "Expect Ready to switch on: bits 0 and 5 on, bit 6 off.");
    case Command::SwitchOn:
        return QObject::tr(
            "Switch on (transition 3): switches the power stage on, the motor is not yet energised; needs main power. "
            "Sends 6040h = 0007h. Expect Switched on: bits 0, 1, 4 (voltage enabled) and 5 on.");
    case Command::EnableOperation:
        return QObject::tr(
            "Enable operation (transition 4): energises the motor, which then holds its position and follows commands. "
            "Sends 6040h = 000Fh. Expect Operation enabled: bits 0, 1, 2 and 5 on.");
    default: return coreText(canopen::ds402::commandName(c));
    }
}

Ds402StepBar::Ds402StepBar(QWidget* parent) : QGroupBox(tr("Step through — one button per transition"), parent) {
    auto* layout = new QVBoxLayout(this);
    auto* row = new QHBoxLayout;
    const std::pair<Command, QString> steps[] = {{Command::FaultReset, tr("1  Fault reset")},
                                                 {Command::Shutdown, tr("2  Shutdown")},
                                                 {Command::SwitchOn, tr("3  Switch on")},
                                                 {Command::EnableOperation, tr("4  Enable operation…")}};
    for (const auto& [cmd, text] : steps) {
        auto* b = new QPushButton(text, this);
        b->setObjectName(QStringLiteral("step_%1").arg(canopen::ds402::commandName(cmd).toLower().replace(u' ', u'_')));
        b->setToolTip(ds402StepExplanation(cmd));
        connect(b, &QPushButton::clicked, this, [this, c = cmd] { emit stepClicked(c); });
        buttons_[cmd] = b;
        row->addWidget(b);
    }
    layout->addLayout(row);
    next_ = new QLabel(this);
    next_->setObjectName(QStringLiteral("nextStep"));
    next_->setWordWrap(true);
    next_->setAlignment(Qt::AlignLeft | Qt::AlignTop);
    next_->setFixedHeight(next_->fontMetrics().lineSpacing() * 3 + 4);  // the steps do not move as it changes
    layout->addWidget(next_);
}

QPushButton* Ds402StepBar::button(Command c) const {
    auto it = buttons_.find(c);
    return it == buttons_.end() ? nullptr : it->second;
}

void Ds402StepBar::enableNext(std::optional<Command> next, bool canRun) {
    for (auto& [cmd, b] : buttons_) {
        b->setEnabled(canRun && next && *next == cmd);
        QFont f = b->font();
        f.setBold(b->isEnabled());
        b->setFont(f);
    }
}

void Ds402StepBar::explain(State s, bool cia402) {
    const auto next = canopen::ds402::nextEnableCommand(s);
    if (!cia402) next_->clear();
    else if (s == State::OperationEnabled)
        next_->setText(
            tr("The drive is enabled (Operation enabled). Choose a mode and try a test move, or press Disable."));
    else if (s == State::QuickStopActive)
        next_->setText(tr("Quick stop is active: press Disable to leave it (Disable voltage, transition 12)."));
    else if (next) next_->setText(tr("Next: %1").arg(ds402StepExplanation(*next)));
    else
        next_->setText(tr("The drive is in %1; wait for it to settle, then read the state again.")
                           .arg(coreText(canopen::ds402::stateName(s))));
}

void Ds402StepBar::setNote(const QString& text) { next_->setText(text); }

}  // namespace coscope::gui
