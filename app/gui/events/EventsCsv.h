// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QString>

class QAbstractItemModel;

namespace coscope::gui {

// Writes the rows of `model` as shown (its column headers first, then each cell's display text,
// RFC 4180 quoting, UTF-8 with CRLF line ends as spreadsheets expect). False and `error` (the
// file and why) when the file cannot be written; a file written before is then left as it was.
bool writeEventsCsv(const QString& path, const QAbstractItemModel& model, QString* error);

}  // namespace coscope::gui
