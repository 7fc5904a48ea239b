// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/canopen/CommandScript.h"

#include <QWidget>

class QLabel;
class QPushButton;
class QTableWidget;

namespace coscope::gui {

// The dry run every wizard offers: the exact sequence (step, what is sent, why) as a table,
// with "Save as script…" writing it for `coscope-cli script run`. Steps can be marked as done
// or failed while a run progresses.
//
// Columns: # | What it does (ScriptStep::describe) | Script line (toLine) | Why | Result.
// A row turns green when marked done, red when failed (the detail goes in Result and the
// tooltip), blue while running (markRunning). setScript() clears every mark.
class ScriptPreview : public QWidget {
    Q_OBJECT
public:
    explicit ScriptPreview(QWidget* parent = nullptr);

    void setScript(const canopen::CommandScript& script);
    const canopen::CommandScript& script() const;
    void markStep(int step, bool ok, const QString& detail = {});
    bool saveTo(const QString& path, QString* error) const;
    int rowCount() const;

    // Added with the implementation:
    void markRunning(int step);  // the step now on the bus
    void clearMarks();           // before running the same script again
    // "done", "failed: <detail>", "running" or "" for a row (tests, accessibility).
    QString stepState(int step) const;

signals:
    // After "Save as script…" wrote a file.
    void saved(const QString& path);

private:
    void saveInteractively();
    void setRowColour(int row, const QColor& colour);

    canopen::CommandScript script_;
    QLabel* title_ = nullptr;
    QTableWidget* table_ = nullptr;
    QPushButton* save_ = nullptr;
    QStringList states_;
};

}  // namespace coscope::gui
