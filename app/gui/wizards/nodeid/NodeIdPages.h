// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QWizardPage>

class QButtonGroup;
class QComboBox;
class QLabel;
class QPushButton;
class QRadioButton;
class QTableWidget;

namespace coscope::gui {

class IntegerSpinBox;
class NodeIdWizard;
class ScriptPreview;

// Page 1: which device — the nodes seen on the bus, a scan, or LSS Fastscan for a device that
// has no node-ID yet; and what kind of device it is (its dictionary: the vendor's parameters).
class NodeIdFindPage : public QWizardPage {
    Q_OBJECT
public:
    explicit NodeIdFindPage(NodeIdWizard* wizard);
    bool isComplete() const override;
    void refresh();  // node list and target from the wizard
    QTableWidget* nodeTable() const { return table_; }
    QPushButton* scanButton() const { return scan_; }
    QPushButton* fastscanButton() const { return fastscan_; }
    QLabel* refusalLabel() const { return refusal_; }

private:
    NodeIdWizard* wizard_;
    QLabel* refusal_;
    QTableWidget* table_;
    QPushButton* scan_;
    QPushButton* fastscan_;
    QLabel* status_;
    QComboBox* dictionary_;
    QLabel* target_;
    uint64_t shownRevision_ = ~uint64_t(0);
    bool dictionaryChosen_ = false;  // the user picked the device type for the chosen node
};

// Page 2: node-ID or bit rate, the new value, LSS or the drive's parameter, and in plain words
// what will happen and when it takes effect.
class NodeIdChangePage : public QWizardPage {
    Q_OBJECT
public:
    explicit NodeIdChangePage(NodeIdWizard* wizard);
    bool isComplete() const override;
    void initializePage() override;
    void refresh();
    QLabel* explanationLabel() const { return explanation_; }

private:
    NodeIdWizard* wizard_;
    QRadioButton* nodeId_;
    QRadioButton* bitRate_;
    IntegerSpinBox* newId_;
    QComboBox* newRate_;
    QRadioButton* viaLss_;
    QRadioButton* viaVendor_;
    QLabel* explanation_;
    QLabel* problem_;
    bool updating_ = false;
};

// Page 3: the dry run (the exact sequence, nothing sent yet, savable as a script), then
// "Change it now", progress step by step and the outcome.
class NodeIdRunPage : public QWizardPage {
    Q_OBJECT
public:
    explicit NodeIdRunPage(NodeIdWizard* wizard);
    void initializePage() override;
    bool isComplete() const override;
    ScriptPreview* preview() const { return preview_; }
    QPushButton* runButton() const { return run_; }
    QLabel* statusLabel() const { return status_; }

private:
    static QString dryRunSubTitle();
    NodeIdWizard* wizard_;
    QLabel* intro_;
    ScriptPreview* preview_;
    QPushButton* run_;
    QLabel* status_;
};

}  // namespace coscope::gui
