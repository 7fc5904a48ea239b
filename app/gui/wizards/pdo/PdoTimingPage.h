// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QWizardPage>

#include <cstdint>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QPushButton;

namespace coscope::gui {

class IntegerSpinBox;

class PdoWizard;

// Page 3: when the message goes out (or, for an RPDO, when the drive acts on it): transmission
// type explained in plain words, inhibit time, event timer and the CAN-ID (COB-ID).
class PdoTimingPage : public QWizardPage {
    Q_OBJECT
public:
    explicit PdoTimingPage(PdoWizard* wizard);

    void initializePage() override;
    bool isComplete() const override;

    void setTransmissionType(uint8_t type);
    void setEventTimerMs(int ms);
    void setInhibitMs(double ms);
    void setCobId(uint32_t canId, bool valid);

private:
    void toState();  // controls -> state.wanted
    void explain();

    PdoWizard* wizard_;
    QComboBox* mode_;
    IntegerSpinBox* every_;
    IntegerSpinBox* other_;
    QDoubleSpinBox* inhibit_;
    IntegerSpinBox* event_;
    IntegerSpinBox* cob_;  // the 11-bit CAN-ID, "182h"
    QCheckBox* valid_;
    QPushButton* defaultCob_;
    QLabel* explain_;
    QLabel* inhibitLabel_;
    QLabel* eventLabel_;
    bool loading_ = false;
};

}  // namespace coscope::gui
