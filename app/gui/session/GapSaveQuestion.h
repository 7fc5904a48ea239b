// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QCoreApplication>
#include <QString>

class QWidget;

namespace coscope {
class TraceStore;
}

namespace coscope::gui {

// Issue 16 "Lost adapter": a gap of the capture must not vanish unseen. Before Save As writes a
// format without a place for it (candump, BLF; LogWriter::keepsGaps()), the user is asked
// "Save anyway?". True: save (no gaps, a format that keeps them, an unknown format — the save
// job reports that —, or the user agreed). `quiet` (tests, --screenshot): logs it and saves.
class GapSaveQuestion {
    Q_DECLARE_TR_FUNCTIONS(GapSaveQuestion)
public:
    static bool confirm(QWidget* parent, const TraceStore* store, const QString& path, const QString& format,
                        bool quiet);
};

}  // namespace coscope::gui
