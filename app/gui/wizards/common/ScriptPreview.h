// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/canopen/CommandScript.h"

#include <QWidget>

namespace coscope::gui {

// The dry run every wizard offers: the exact sequence (step, what is sent, why) as a table,
// with "Save as script…" writing it for `coscope-cli script run`. Steps can be marked as done
// or failed while a run progresses.
class ScriptPreview : public QWidget {
    Q_OBJECT
public:
    explicit ScriptPreview(QWidget* parent = nullptr);

    void setScript(const canopen::CommandScript& script);
    const canopen::CommandScript& script() const;
    void markStep(int step, bool ok, const QString& detail = {});
    bool saveTo(const QString& path, QString* error) const;
    int rowCount() const;
};

}  // namespace coscope::gui
