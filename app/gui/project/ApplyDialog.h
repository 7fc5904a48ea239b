// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/project/ProjectApply.h"

#include <QDialog>

class QLabel;
class QPlainTextEdit;
class QPushButton;

namespace coscope::gui {

class ProjectSession;
class Workspace;

// "Apply the project": reads the drives and shows the dry run (the exact SDO writes per node),
// writes them after one confirmation (the first refusal stops, that node's old values are put
// back), then offers to store the parameters in the drives (1010h, its own confirmation) and to
// save the report. ProjectApply does the work.
class ApplyDialog : public QDialog {
    Q_OBJECT
public:
    // `nodes`: only these (a replaced drive), empty = all of the project's.
    ApplyDialog(const ProjectSession& session, Workspace* workspace, std::vector<uint8_t> nodes,
                QWidget* parent = nullptr);

    QPushButton* applyButton() const { return applyButton_; }
    QPushButton* storeButton() const { return storeButton_; }
    QPushButton* saveButton() const { return saveButton_; }
    QString reportText() const;
    bool finished() const { return finished_; }
    const project::ApplyReport& lastReport() const { return report_; }

signals:
    void applied(bool ok);

private:
    void prepared(std::vector<project::NodeApplyPlan> plans);
    void runApply();
    void finish(project::ApplyReport report);  // the result shown; applied() emitted
    void runStore();
    void saveReport();
    void setStatus(const QString& text);

    Workspace* workspace_;
    project::ProjectApply* apply_ = nullptr;
    std::vector<project::NodeApplyPlan> plans_;
    std::vector<uint8_t> written_;
    project::ApplyReport report_;
    QLabel* status_;
    QPlainTextEdit* text_;
    QPushButton* applyButton_;
    QPushButton* storeButton_;
    QPushButton* saveButton_;
    bool finished_ = false;
};

}  // namespace coscope::gui
