// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/canopen/Ds402.h"

#include <QGroupBox>

#include <map>
#include <optional>

class QLabel;
class QPushButton;

namespace coscope::gui {

// The step bar of the CiA 402 wizard: one button per transition of the enable sequence (fault
// reset 15, shutdown 2, switch on 3, enable operation 4; CiA 402-2 §6.2) with only the next one
// enabled, and under it what that step does in plain words.
class Ds402StepBar : public QGroupBox {
    Q_OBJECT
public:
    explicit Ds402StepBar(QWidget* parent = nullptr);

    QPushButton* button(canopen::ds402::Command command) const;
    // Enables (in bold) the button of `next` alone, when the wizard `canRun` a step.
    void enableNext(std::optional<canopen::ds402::Command> next, bool canRun);
    // The line under the buttons for a drive in `state` (nothing when it is no CiA 402 drive).
    void explain(canopen::ds402::State state, bool cia402);
    void setNote(const QString& text);

signals:
    void stepClicked(canopen::ds402::Command command);

private:
    std::map<canopen::ds402::Command, QPushButton*> buttons_;
    QLabel* next_ = nullptr;
};

// What a step does, in a technician's words with the CiA term beside it.
QString ds402StepExplanation(canopen::ds402::Command command);

}  // namespace coscope::gui
