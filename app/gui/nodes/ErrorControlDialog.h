// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/canopen/NodeTable.h"

#include <QDialog>

class QLabel;
class QRadioButton;
class QSpinBox;

namespace coscope::gui {

// How CoScope watches one node's error control (Nodes dock ▸ Heartbeat and guarding…): not at
// all, its heartbeat within a consumer time, or node guarding with a guard time and a life time
// factor (CiA 301 §7.2.8.3.2) for a node without heartbeat. Node guarding transmits (an RTR on
// 700h + node every guard time): off, with the reason, on a listen-only bus. The choice goes to
// canopen::HeartbeatMonitor (NodesDock).
class ErrorControlDialog : public QDialog {
    Q_OBJECT
public:
    enum class Kind { None, Heartbeat, Guarding };
    struct Choice {
        Kind kind = Kind::None;
        int consumerTimeMs = 0;
        int guardTimeMs = 0;
        int lifeTimeFactor = 0;
    };

    // `guardingOffWhy`: why node guarding cannot be chosen ("" when it can).
    ErrorControlDialog(const canopen::NodeInfo& node, const QString& guardingOffWhy, QWidget* parent = nullptr);

    Choice choice() const;

private:
    void updateEnabled();

    QRadioButton* none_;
    QRadioButton* heartbeat_;
    QRadioButton* guarding_;
    QSpinBox* consumerTime_;
    QSpinBox* guardTime_;
    QSpinBox* lifeFactor_;
    QLabel* lifeTime_;
};

}  // namespace coscope::gui
