// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QWizardPage>

class QCheckBox;
class QLabel;
class QPushButton;

namespace coscope::gui {

class PdoWizard;
class ScriptPreview;

// Page 4: the dry run (the exact NMT/SDO sequence, why each step, savable as a script), the
// options (store in the drive, start the node), Apply, and the outcome in plain words.
class PdoApplyPage : public QWizardPage {
    Q_OBJECT
public:
    explicit PdoApplyPage(PdoWizard* wizard);

    void initializePage() override;
    bool isComplete() const override;

    ScriptPreview* preview() const { return preview_; }
    // Rebuilds the dry run from the wizard's state and options.
    void refreshPreview();
    // The option boxes follow the wizard's options; the dry run is rebuilt.
    void syncOptions();
    void showOutcome();
    QString resultText() const;

private:
    PdoWizard* wizard_;
    ScriptPreview* preview_;
    QCheckBox* store_;
    QCheckBox* start_;
    QPushButton* apply_;
    QLabel* guard_;
    QLabel* result_;
};

}  // namespace coscope::gui
