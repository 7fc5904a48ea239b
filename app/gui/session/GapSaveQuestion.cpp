// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/session/GapSaveQuestion.h"

#include "core/logio/LogFormats.h"
#include "core/trace/TraceStore.h"

#include <QMessageBox>
#include <QPushButton>

#include <spdlog/spdlog.h>

namespace coscope::gui {

bool GapSaveQuestion::confirm(QWidget* parent, const TraceStore* store, const QString& path, const QString& format,
                              bool quiet) {
    const size_t gaps = store ? store->gaps().size() : 0;
    if (gaps == 0) return true;
    const QString name = logio::LogFormats::writerFormatFor(path, format, nullptr);
    const auto writer = name.isEmpty() ? nullptr : logio::LogFormats::createWriter(name);
    if (!writer || writer->keepsGaps()) return true;  // an unknown format fails in the save job
    if (quiet) {
        spdlog::warn("saving {}: the {} format cannot hold the trace's {} gaps", path.toStdString(), name.toStdString(),
                     gaps);
        return true;
    }
    QMessageBox box(
        QMessageBox::Warning, tr("Save trace"),
        tr("The trace has %n gap(s) (adapter lost); the %1 format cannot hold them, so the saved file will not "
           "show where frames are missing. pcapng, ASC, TRC and CSV keep them.",
           nullptr, int(gaps))
            .arg(name),
        QMessageBox::Save | QMessageBox::Cancel, parent);
    box.button(QMessageBox::Save)->setText(tr("Save anyway"));
    box.setDefaultButton(QMessageBox::Cancel);
    return box.exec() == QMessageBox::Save;
}

}  // namespace coscope::gui
