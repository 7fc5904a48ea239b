// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "app/gui/master/MasterSettings.h"

#include <QDialog>

#include <optional>

class QCheckBox;
class QDialogButtonBox;
class QDoubleSpinBox;
class QGroupBox;
class QLabel;
class QLineEdit;
class QSpinBox;

namespace coscope::gui {

// Bus ▸ Master settings…: the SYNC producer (period with µs resolution, counter 1019h, COB-ID
// 1005h, whether to write 1006h to the nodes when it starts) and CoScope's own heartbeat
// (node-ID, period). OK checks the values, stores them (MasterSettings) and emits applied().
class MasterSettingsDialog : public QDialog {
    Q_OBJECT
public:
    explicit MasterSettingsDialog(QWidget* parent = nullptr);

    MasterSettings settings() const;
    // Empty when the values are usable, else what is wrong.
    QString problem() const;

    QDoubleSpinBox* period() const { return period_; }
    QSpinBox* counter() const { return counter_; }
    QLineEdit* cobId() const { return cobId_; }
    QDialogButtonBox* buttons() const { return buttons_; }

signals:
    void applied();

protected:
    void accept() override;

private:
    QDoubleSpinBox* period_ = nullptr;
    QSpinBox* counter_ = nullptr;
    QLineEdit* cobId_ = nullptr;
    QCheckBox* write1006_ = nullptr;
    QGroupBox* heartbeat_ = nullptr;
    QSpinBox* heartbeatNode_ = nullptr;
    QSpinBox* heartbeatMs_ = nullptr;
    QLabel* problem_ = nullptr;
    QDialogButtonBox* buttons_ = nullptr;
};

// "80h", "0x80", "128" -> 128; nullopt when it is not a number.
std::optional<uint32_t> parseCobIdText(const QString& text);

}  // namespace coscope::gui
