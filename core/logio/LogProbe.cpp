// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/logio/LogProbe.h"

#include "core/logio/LogFormats.h"

#include <QBuffer>
#include <QFile>

namespace coscope::logio {

namespace {
constexpr size_t kProbeProblems = 5;
bool isBinaryLog(const QString& format) { return format == u"blf" || format == u"pcap"; }
// Formats whose blocks link to any place in the file (MDF4): the first part alone says
// nothing, the reader seeks in the whole file for its first frame.
bool needsWholeFile(const QString& format) { return format == u"mf4"; }
}  // namespace

LogProbe probeLog(const QString& path) {
    LogProbe probe;
    // The same checks and messages as a full open: readable, known format, header.
    if (!LogFormats::openReader(path, &probe.error)) return probe;
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        probe.error = QStringLiteral("cannot open %1: %2").arg(path, file.errorString());
        return probe;
    }
    probe.format = LogFormats::detect(&file, path);
    probe.formatByName = LogFormats::detectContent(file.peek(8192)).isEmpty();
    QByteArray head = needsWholeFile(probe.format) ? QByteArray() : file.read(LogProbe::kProbeBytes);
    const bool whole = needsWholeFile(probe.format) || file.atEnd();
    // A text log cut at the last whole line, so that the cut is no bad line.
    if (!whole && !isBinaryLog(probe.format)) {
        const qsizetype nl = head.lastIndexOf('\n');
        if (nl > 0) head.truncate(nl + 1);
    }
    auto reader = LogFormats::createReader(probe.format);
    QBuffer buffer(&head);
    buffer.open(QIODevice::ReadOnly);
    file.seek(0);
    if (!reader || !reader->open(needsWholeFile(probe.format) ? static_cast<QIODevice*>(&file) : &buffer, path)) {
        probe.error = reader ? QStringLiteral("%1: %2").arg(path, reader->errorString())
                             : QStringLiteral("%1: cannot be read").arg(path);
        return probe;
    }
    CanFrame frame;
    if (reader->read(&frame, 1) > 0) {
        probe.usable = true;
        return probe;
    }
    // A binary log cut in the middle of a record says nothing about the rest of the file.
    if (!whole && isBinaryLog(probe.format)) {
        probe.usable = true;
        return probe;
    }
    if (reader->hasError()) {
        probe.error = QStringLiteral("%1: %2").arg(path, reader->errorString());
        return probe;
    }
    const auto& seen = reader->diagnostics();
    probe.problems.assign(seen.begin(), seen.begin() + std::min(seen.size(), kProbeProblems));
    probe.usable = probe.problems.empty();
    return probe;
}

}  // namespace coscope::logio
