// SPDX-License-Identifier: GPL-3.0-or-later
// Folder app/gui/program/ owns the program (firmware) download dialog, a face over
// canopen::ProgramDownload (CiA 302-3), opened from the Nodes dock.
#pragma once

#include "core/canopen/ProgramDownload.h"

#include <QDialog>
#include <QPointer>

class QCheckBox;
class QLabel;
class QLineEdit;
class QProgressBar;
class QPushButton;
class QSpinBox;

namespace coscope::gui {

class Workspace;

// Download a program to one node: the file, what the node reports now (100Ah, 1F56h, 1F57h),
// a confirmation that says the node stops its application (and which drive CoScope disables
// first), progress with bytes and rate, Cancel, and the result with the old and new version.
// A failed or cancelled download claims nothing and offers to download again from the start.
// On a listen-only bus nothing can be started and the dialog says why.
class ProgramDownloadDialog : public QDialog {
    Q_OBJECT
public:
    ProgramDownloadDialog(Workspace* workspace, int node, QWidget* parent = nullptr);
    ~ProgramDownloadDialog() override;

    int node() const { return node_; }
    bool isDownloading() const { return service_ && service_->isRunning(); }
    // The last outcome (empty before the first download ended).
    const std::optional<canopen::ProgramDownloadOutcome>& outcome() const { return outcome_; }
    // Starts the download of the file in the field; `confirm` asks first (the Download button
    // always does; the screenshot view does not). False when refused (no file, listen-only...).
    bool startDownload(bool confirm = true);
    // The file field, as if typed (the screenshot view).
    void setImageFile(const QString& path);
    // The program number field (the sub-index of 1F50h/1F51h), as if typed (a project's program).
    void setProgramNumber(int program);
    int progressPermille() const;
    // Not while a download runs (Cancel first): closing would leave the node half-written.
    void reject() override;

signals:
    void finished(bool ok);

private:
    void readNodeState();
    void showState(const canopen::ProgramState& s);
    void showOutcome(const canopen::ProgramDownloadOutcome& o);
    void updateEnabled();
    QString stepText(canopen::ProgramStep step) const;
    QString enabledDrivesOnNode() const;

    Workspace* workspace_;
    int node_;
    QPointer<canopen::ProgramDownload> service_;
    std::optional<canopen::ProgramDownloadOutcome> outcome_;
    QLineEdit* file_ = nullptr;
    QPushButton* browse_ = nullptr;
    QSpinBox* program_ = nullptr;
    QCheckBox* block_ = nullptr;
    QCheckBox* start_ = nullptr;
    QLabel* version_ = nullptr;
    QLabel* softwareId_ = nullptr;
    QLabel* flash_ = nullptr;
    QPushButton* readAgain_ = nullptr;
    QLabel* warning_ = nullptr;
    QProgressBar* progress_ = nullptr;
    QLabel* status_ = nullptr;
    QPushButton* download_ = nullptr;
    QPushButton* cancel_ = nullptr;
    QPushButton* close_ = nullptr;
};

}  // namespace coscope::gui
