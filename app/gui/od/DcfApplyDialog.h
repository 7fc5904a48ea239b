// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/canopen/DeviceConfiguration.h"

#include <QDialog>

#include <vector>

class QLabel;
class QPushButton;
class QTreeWidget;

namespace coscope::gui {

// Applying a DCF to a node, in two steps shown in one dialog: the preview (every SDO write with
// the value and the node's current one, and the entries that are not written with the reason),
// confirmed with "Write N objects"; then the report (each write ok or the abort text).
class DcfApplyDialog : public QDialog {
    Q_OBJECT
public:
    DcfApplyDialog(const QString& file, const canopen::ApplyPlan& plan, QWidget* parent = nullptr);

    // Switches to the report: one line per write with its result.
    void showResults(const std::vector<canopen::ConfigEntryResult>& results, bool cancelled);
    QTreeWidget* list() const { return list_; }

private:
    QLabel* summary_;
    QTreeWidget* list_;
    QPushButton* write_;
    QPushButton* close_;
    canopen::ApplyPlan plan_;
};

}  // namespace coscope::gui
