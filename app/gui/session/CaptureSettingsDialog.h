// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QDialog>

class QDialogButtonBox;
class QSpinBox;

namespace coscope::gui {

// File ▸ Capture settings (issue 16): the trace memory budget (MemoryBudget.h; 0 = automatic, a
// quarter of the RAM, at most 4 GiB) and how long and how much of the old capture journals are
// kept (JournalOffer.h journalCleanupPolicy()). OK stores them in QSettings and emits applied();
// the caller applies them at once (the live trace's budget, a clean-up of the journal folder).
class CaptureSettingsDialog : public QDialog {
    Q_OBJECT
public:
    explicit CaptureSettingsDialog(QWidget* parent = nullptr);

    QSpinBox* memoryBudget() const { return budget_; }
    QSpinBox* keepDays() const { return keepDays_; }
    QSpinBox* keepMegabytes() const { return keepMegabytes_; }
    QDialogButtonBox* buttons() const { return buttons_; }

signals:
    void applied();

private:
    void store();

    QSpinBox* budget_ = nullptr;
    QSpinBox* keepDays_ = nullptr;
    QSpinBox* keepMegabytes_ = nullptr;
    QDialogButtonBox* buttons_ = nullptr;
};

}  // namespace coscope::gui
