// SPDX-License-Identifier: GPL-3.0-or-later
// Folder core/logio/ owns log files: one reader/writer per format (candump, CSV, pcap/pcapng, PEAK
// trc, Vector asc/blf; readers for SavvyCAN GVRET, BUSMASTER, IXXAT and Kvaser exports, ASAM MDF4 bus logging) and the
// registry that sniffs content.
#pragma once

#include "core/logio/LogReader.h"
#include "core/logio/LogWriter.h"

#include <QString>
#include <QStringList>

#include <memory>
#include <vector>

class QIODevice;

namespace coscope::logio {

// The log formats CoScope knows, by name: candump, asc, blf, trc, pcap (pcap and pcapng), csv,
// and read only: gvret (SavvyCAN), busmaster, ixxat, kvaser, mf4 (ASAM MDF4 bus logging).
struct LogFormatInfo {
    QString name;
    QString description;
    QStringList extensions;  // lower case, without the dot
    bool canRead = false;
    bool canWrite = false;
};

namespace LogFormats {

const std::vector<LogFormatInfo>& all();

// Format name from the first bytes of a file (magic numbers, characteristic lines); empty when
// the content says nothing definite.
QString detectContent(const QByteArray& head);
// Format name from a file name's extension; empty when unknown.
QString formatForExtension(const QString& path);
// Content first, then the extension. Peeks at the device without consuming it.
QString detect(QIODevice* device, const QString& fileName);

std::unique_ptr<LogReader> createReader(const QString& format);
// Opens `path`, detects its format and reads the header. On failure returns nullptr with a
// one-line reason in *error.
std::unique_ptr<LogReader> openReader(const QString& path, QString* error);

// Writer by format name or alias ("candump", "log", "asc", "trc", "pcapng", "csv").
std::unique_ptr<LogWriter> createWriter(const QString& format);
// Writer format for an output file: `explicitFormat` when given, else from the extension.
QString writerFormatFor(const QString& outputPath, const QString& explicitFormat, QString* error);

}  // namespace LogFormats

}  // namespace coscope::logio
