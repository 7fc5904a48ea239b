// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QGroupBox>

#include <cstdint>
#include <optional>

class QComboBox;
class QLabel;
class QPushButton;

namespace coscope::gui {

// The mode of operation box of the CiA 402 wizard: the modes the drive lists in 6502h to choose
// from, "Set and verify" (6060h written, 6061h read back; CiA 402-2 §6.3) and the mode the
// drive shows in 6061h. The box shows the drive's own mode until the user picks another one.
class Ds402ModeBox : public QGroupBox {
    Q_OBJECT
public:
    explicit Ds402ModeBox(QWidget* parent = nullptr);

    QComboBox* combo() const { return combo_; }
    // Nothing read (another drive, or the connection is gone): no mode shown or chosen.
    void forget(bool label = true);
    // The modes 6502h lists. Returns whether 6061h had been read: then show it again.
    bool setSupported(uint32_t supported);
    // 6061h as read; true when it changed (the box then selects it).
    bool showDriveMode(int8_t mode);
    void showVerified(int8_t mode);  // 6061h read back after Set and verify
    int8_t driveMode() const { return driveMode_; }
    // The mode picked in the box, when one is.
    std::optional<int8_t> chosen() const;
    void setChoosable(bool on);

signals:
    void setRequested(int8_t mode);

private:
    void updateSetButton();

    QComboBox* combo_ = nullptr;
    QPushButton* set_ = nullptr;
    QLabel* shown_ = nullptr;
    int8_t driveMode_ = 0;
    bool read_ = false;  // 6061h was read since the drive was chosen
    bool choosable_ = false;
};

}  // namespace coscope::gui
