// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/project/ProjectCompare.h"

#include <QDialog>

class QCheckBox;
class QLabel;
class QPushButton;
class QTableView;

namespace coscope::gui {

class CompareModel;
class ProjectSession;
class Workspace;

// The machine compared with the project (ProjectCompare): a table of the nodes that are not as
// in the project and of the configured objects (project, drive, dictionary default, state),
// "Only differences", export as HTML and CSV, "Apply the project…", the guided replacement of a
// drive (a node replaced or missing: node-ID wizard, then that node's project applied and
// compared again) and "Download the project's program…" for a node whose project names one.
class CompareDialog : public QDialog {
    Q_OBJECT
public:
    CompareDialog(ProjectSession& session, Workspace* workspace, QWidget* parent = nullptr);

    void compare();  // runs again; the table is kept until the new result is in
    bool isRunning() const { return running_; }
    bool hasResult() const { return hasResult_; }
    CompareModel* model() const { return model_; }
    QTableView* table() const { return table_; }
    QCheckBox* onlyDifferencesBox() const { return only_; }
    QPushButton* compareButton() const { return compareButton_; }
    QPushButton* applyButton() const { return applyButton_; }
    QPushButton* replaceButton() const { return replaceButton_; }
    QPushButton* programButton() const { return programButton_; }
    // The apply dialog last opened from here (tests), or null.
    QDialog* applyDialog() const;

    // "Apply the project…" (of `nodes`, empty = all); once written, compared again.
    void openApply(std::vector<uint8_t> nodes);
    // Shows `report` as if it came from the bus (screenshots).
    void showReport(const project::CompareReport& report);

private:
    void exportAs(bool html);
    void replaceDrive();
    // A missing node: the node-ID wizard gives a new drive of the same type its node-ID (LSS or
    // vendor parameters), then the node's project is applied and the machine compared again.
    void replaceMissing(uint8_t node);
    // The node of a drive of the project node's type that the project does not have, if the last
    // comparison found one (a new drive at its factory node-ID).
    std::optional<uint8_t> sameTypeNotInProject(uint8_t node) const;
    void downloadProgram();
    uint8_t selectedNode() const;  // 0 = none
    void updateButtons();

    ProjectSession& session_;
    Workspace* workspace_;
    CompareModel* model_;
    QTableView* table_;
    QLabel* status_;
    QCheckBox* only_;
    QPushButton* compareButton_;
    QPushButton* applyButton_;
    QPushButton* replaceButton_;
    QPushButton* programButton_;
    QPushButton* htmlButton_;
    QPushButton* csvButton_;
    QObject* applyDialog_ = nullptr;
    bool running_ = false;
    bool hasResult_ = false;
};

}  // namespace coscope::gui
