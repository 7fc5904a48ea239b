// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/canopen/Ds402Controller.h"

#include "app/gui/wizards/ds402/Ds402Units.h"

#include <QWidget>

#include <array>

class QCheckBox;
class QLabel;
class QProgressBar;
class QPushButton;

namespace coscope::gui {

class Ds402BitLamps;
class Ds402MotionPlot;
class IntegerSpinBox;

// The profile position move of the CiA 402 wizard (CiA 402-2 §12; Delta extract §4.5.1,
// AIMOTOR extract §4.6 A): target 607Ah absolute or relative (controlword bit 6), profile
// velocity 6081h, acceleration 6083h and deceleration 6084h in the drive's units; armed like
// the test move and run only while "Hold to move" is held. Shows the set-point handshake
// (6040h bit 4 → 6041h bit 12 → bit 4 low → bit 10 target reached) and the way to the target.
class Ds402PositionMoveBox : public QWidget {
    Q_OBJECT
public:
    explicit Ds402PositionMoveBox(QWidget* parent = nullptr);

    void setDrive(const Ds402Units& units, const QString& dictionary);
    // 6081h/6083h/6084h as read from the drive (0 keeps the page's own value).
    void showDriveValue(uint16_t index, int64_t value);
    // The limits line: software limits 607Dh or the test move's.
    void showLimits(const QString& text);
    canopen::Ds402PositionMove move() const;
    // "by 1000 inc (relative, 607Ah = 1000) at up to 2000 inc/s (6081h)" for the confirmation.
    QString describe(const canopen::Ds402PositionMove& move) const;
    void setButtons(bool armEnabled, bool holdEnabled);
    // A move from `from` to `to` begins: the way shown, the handshake cleared.
    void started(int32_t from, int32_t to);
    void showControlword(uint16_t cw);  // as the controller sends it
    void showSample(const canopen::Ds402MotionSample& sample);
    void showResult(const QString& text, bool ok);
    QString resultText() const;
    QString handshakeText() const;

    IntegerSpinBox* targetField() const { return target_; }
    QCheckBox* relativeBox() const { return relative_; }
    IntegerSpinBox* velocityField() const { return fields_[0]; }
    QPushButton* armButton() const { return arm_; }
    QPushButton* holdButton() const { return hold_; }
    Ds402BitLamps* lamps() const { return lamps_; }
    QProgressBar* way() const { return way_; }

signals:
    void armClicked();
    void holdPressed();
    void holdReleased();

private:
    void showHandshake();

    Ds402Units units_ = Ds402Units::forDictionary({});
    IntegerSpinBox* target_ = nullptr;
    QCheckBox* relative_ = nullptr;
    std::array<IntegerSpinBox*, 3> fields_{};  // 6081h, 6083h, 6084h
    std::array<bool, 3> typed_{};              // typed by the user: a late read does not overwrite it
    QLabel* limits_ = nullptr;
    QPushButton* arm_ = nullptr;
    QPushButton* hold_ = nullptr;
    Ds402BitLamps* lamps_ = nullptr;
    QLabel* handshake_ = nullptr;
    QProgressBar* way_ = nullptr;
    QLabel* result_ = nullptr;
    Ds402MotionPlot* plot_ = nullptr;
    // The handshake as seen: 0 nothing, 1 bit 4 sent, 2 acknowledged (bit 4 low after bit 12), 3 target reached.
    int phase_ = 0;
    uint16_t controlword_ = 0;
    int32_t from_ = 0, to_ = 0;
};

}  // namespace coscope::gui
