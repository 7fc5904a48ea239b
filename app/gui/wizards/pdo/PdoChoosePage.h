// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QWizardPage>

class QComboBox;
class QLabel;
class QTreeWidget;
class QTimer;

namespace coscope::gui {

class PdoWizard;
class PdoFrameLayout;

// Page 1: which drive and which PDO; shows what the PDO carries now, read from the device,
// and what to know about this drive.
class PdoChoosePage : public QWizardPage {
    Q_OBJECT
public:
    explicit PdoChoosePage(PdoWizard* wizard);

    bool isComplete() const override;
    // Re-reads the node list from the node table (keeps the selection).
    void refreshNodes();
    // Shows the state's target and current configuration.
    void showTarget();
    int currentRows() const;

private:
    void onSelectionChanged();

    PdoWizard* wizard_;
    QComboBox* nodeBox_;
    QComboBox* pdoBox_;
    QLabel* status_;
    QLabel* notes_;
    QTreeWidget* current_;
    PdoFrameLayout* layout_;
    QTimer* nodesTimer_;
    bool filling_ = false;
};

}  // namespace coscope::gui
