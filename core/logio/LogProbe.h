// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/logio/LogReader.h"

#include <QString>

#include <vector>

namespace coscope::logio {

// Whether a file can be opened as a CAN log at all, found out before anything is thrown away
// for it (the GUI keeps the log that is open when the new one cannot be read). Reads the
// format, the header and the first part of the file (at most kProbeBytes): usable when that
// part holds a frame, or holds no problem (a log of only comments, a large header).
struct LogProbe {
    static constexpr qint64 kProbeBytes = 256 * 1024;

    bool usable = false;
    QString format;             // as LogFormats::detect names it; empty when unknown
    bool formatByName = false;  // no format recognised its content: `format` is the file name's guess
    // Why not (unreadable file, unknown format, bad header, read error), with the file's name;
    // empty when the file opened and only its lines were bad (see problems).
    QString error;
    // The first problems of the first part (line numbers of a text log, record numbers of a
    // binary one) when it held no frame.
    std::vector<LogDiagnostic> problems;
};

LogProbe probeLog(const QString& path);

}  // namespace coscope::logio
