// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/canopen/ProcessData.h"
#include "eds/DictionaryLibrary.h"

#include <QDockWidget>

#include <memory>
#include <vector>

class QCheckBox;
class QComboBox;
class QGroupBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QSpinBox;
class QTimer;
class QVBoxLayout;

namespace coscope::canopen {
class BusMaster;
}

namespace coscope::gui {

class Workspace;

// Process data (issue 35): manual control of a drive through its RPDOs. Per node, the mapped
// objects of its RPDOs by their dictionary names, with editors in the dictionary's units (Delta
// 60FFh in rpm from 0.1 rpm, AIMOTOR in pulses) and the controlword 6040h as named bits; its
// TPDOs' values live beside them (the plot's SignalRecorder). Sent once, on change, every N ms or
// with each SYNC by the bus's canopen::ProcessData; RPDOs with motion objects only while "Hold to
// run" is held, after the user armed them. Listen-only or no bus: disabled with the reason.
class ProcessDataDock : public QDockWidget {
    Q_OBJECT
public:
    explicit ProcessDataDock(Workspace* workspace, QWidget* parent = nullptr);
    ~ProcessDataDock() override;

    // The bus's master services (null: no bus). The dock sends through their SYNC producer and
    // scheduler; call before the BusMaster goes.
    void setMaster(canopen::BusMaster* master);
    canopen::ProcessData* processData() const { return data_.get(); }

    QComboBox* nodeBox() const { return node_; }
    QPushButton* holdButton() const { return hold_; }
    QPushButton* armButton() const { return arm_; }
    // The editor of a mapped object (null when not shown).
    QLineEdit* editor(uint16_t index, uint8_t sub) const;
    QCheckBox* controlwordBit(int bit) const;

private:
    struct Row;
    void refreshNodes();
    void showNode();
    void rebuildRows();
    void commit(Row& row);
    void commitControlword(Row& row);
    void showValues();
    void refreshLive();
    void updateEnabled();
    void startStop();
    void sendOnce();
    void arm();
    void disarm();
    void showError(const QString& message);

    Workspace* workspace_;
    canopen::BusMaster* master_ = nullptr;
    std::unique_ptr<canopen::ProcessData> data_;
    eds::DictionaryPtr dictionary_;
    QString dictionaryName_;
    bool armed_ = false;

    QLabel* reason_ = nullptr;
    QComboBox* node_ = nullptr;
    QComboBox* mode_ = nullptr;
    QSpinBox* period_ = nullptr;
    QPushButton* start_ = nullptr;
    QPushButton* send_ = nullptr;
    QWidget* pdoArea_ = nullptr;
    QVBoxLayout* pdoLayout_ = nullptr;
    QLabel* live_ = nullptr;
    QLabel* status_ = nullptr;
    QPushButton* arm_ = nullptr;
    QPushButton* hold_ = nullptr;
    QTimer* feed_ = nullptr;
    QTimer* poll_ = nullptr;
    std::vector<std::unique_ptr<Row>> rows_;
    std::vector<QGroupBox*> groups_;
};

}  // namespace coscope::gui
