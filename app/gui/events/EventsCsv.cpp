// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/events/EventsCsv.h"

#include "core/logio/CsvField.h"

#include <QAbstractItemModel>
#include <QCoreApplication>
#include <QSaveFile>

namespace coscope::gui {

bool writeEventsCsv(const QString& path, const QAbstractItemModel& model, QString* error) {
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly)) {
        if (error) *error = QStringLiteral("%1: %2").arg(path, file.errorString());
        return false;
    }
    auto row = [&](auto cell) {
        QString line;
        for (int c = 0; c < model.columnCount(); ++c) {
            if (c) line += u',';
            line += logio::csvField(cell(c));
        }
        line += QStringLiteral("\r\n");
        file.write(line.toUtf8());
    };
    row([&](int c) { return model.headerData(c, Qt::Horizontal, Qt::DisplayRole).toString(); });
    for (int r = 0; r < model.rowCount(); ++r)
        row([&](int c) { return model.index(r, c).data(Qt::DisplayRole).toString(); });
    if (!file.commit()) {
        if (error) *error = QStringLiteral("%1: %2").arg(path, file.errorString());
        return false;
    }
    return true;
}

}  // namespace coscope::gui
