// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "dissectors/RawSignal.h"

#include <QDialog>

class QComboBox;
class QLabel;
class QLineEdit;
class QSpinBox;

namespace coscope::gui {

// "Add raw signal": bits of any frame read by hand, for devices without a dictionary
// (dissectors/RawSignal.h): COB-ID, start bit, length, type, byte order, factor, offset, unit
// and name. OK checks the definition and says what is wrong instead of closing.
class RawSignalDialog : public QDialog {
    Q_OBJECT
public:
    explicit RawSignalDialog(uint32_t cobId, QWidget* parent = nullptr);

    dissect::RawSignal signal() const { return signal_; }  // valid once accepted
    void accept() override;

private:
    // The definition typed, or an empty optional with the reason shown.
    bool read(dissect::RawSignal& s);

    QLineEdit* name_;
    QLineEdit* cobId_;
    QSpinBox* start_;
    QSpinBox* length_;
    QComboBox* type_;
    QComboBox* order_;
    QLineEdit* factor_;
    QLineEdit* offset_;
    QLineEdit* unit_;
    QLabel* problem_;
    dissect::RawSignal signal_;
};

}  // namespace coscope::gui
