// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/canopen/Ds402Controller.h"
#include "core/canopen/HomingMethods.h"

#include "app/gui/wizards/ds402/Ds402Units.h"

#include <QWidget>

#include <array>
#include <optional>

class QComboBox;
class QLabel;
class QPushButton;

namespace coscope::gui {

class Ds402BitLamps;
class Ds402MotionPlot;
class IntegerSpinBox;

// The homing page of the CiA 402 wizard (CiA 402-2 §13; Delta extract §4.5.3, AIMOTOR extract
// §4.7): the drive's own homing methods 6098h with their descriptions (canopen::homing), the
// speeds 6099h:01/02, acceleration 609Ah and home offset 607Ch in the drive's units, Start and
// Stop, and while it runs statusword bits 10/12/13 (and the AIMOTOR's bit 15), the position and
// the result. What it sends goes through the wizard's Ds402Controller::home().
class Ds402HomingBox : public QWidget {
    Q_OBJECT
public:
    explicit Ds402HomingBox(QWidget* parent = nullptr);

    // The drive's methods (`known`: from its own manual, else CiA 402-2's), its units, and its
    // dictionary for the fields' types and limits.
    void setDrive(const canopen::homing::DriveHoming& table, bool known, const Ds402Units& units,
                  const QString& dictionary);
    // Values read from the drive; a field whose object could not be read is not written.
    void showDriveValue(uint16_t index, uint8_t sub, int64_t value);
    // The method typed or chosen (nullopt: the text is no number).
    std::optional<int> method() const;
    // What Start writes: the method and every field read from the drive or typed.
    canopen::Ds402HomingRequest request() const;
    void setButtons(bool canStart, bool canStop);
    void started();
    void showSample(const canopen::Ds402MotionSample& sample);
    void showResult(const QString& text, bool ok);
    QString resultText() const;
    QString progressText() const;

    QComboBox* methodCombo() const { return method_; }
    IntegerSpinBox* fastField() const { return fields_[0]; }
    IntegerSpinBox* slowField() const { return fields_[1]; }
    IntegerSpinBox* accelerationField() const { return fields_[2]; }
    IntegerSpinBox* offsetField() const { return fields_[3]; }
    QPushButton* startButton() const { return start_; }
    QPushButton* stopButton() const { return stop_; }
    Ds402BitLamps* lamps() const { return lamps_; }

signals:
    void startClicked();
    void stopClicked();

private:
    void describeMethod();

    canopen::homing::DriveHoming table_;
    bool known_ = false;
    Ds402Units units_ = Ds402Units::forDictionary({});
    QComboBox* method_ = nullptr;
    QLabel* about_ = nullptr;
    std::array<IntegerSpinBox*, 4> fields_{};  // 6099h:01, 6099h:02, 609Ah, 607Ch
    std::array<bool, 4> set_{};                // read from the drive or typed: written by Start
    std::array<bool, 4> typed_{};              // typed by the user: a late read does not overwrite it
    bool methodTyped_ = false;
    QPushButton* start_ = nullptr;
    QPushButton* stop_ = nullptr;
    Ds402BitLamps* lamps_ = nullptr;
    int homeFoundLamp_ = -1;
    QLabel* progress_ = nullptr;
    QLabel* result_ = nullptr;
    Ds402MotionPlot* plot_ = nullptr;
};

}  // namespace coscope::gui
