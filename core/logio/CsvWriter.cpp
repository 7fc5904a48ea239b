// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/logio/CsvWriter.h"

#include "core/logio/CaptureGapText.h"

#include <cstdio>

namespace coscope::logio {

namespace {
void appendField(QByteArray& o, const QByteArray& text) {
    if (text.contains(',') || text.contains('"') || text.contains('\n') || text.contains('\r')) {
        QByteArray q = text;
        q.replace("\"", "\"\"");
        o += '"' + q + '"';
    } else {
        o += text;
    }
}
// Seconds with 6 decimals; sign, whole seconds and microseconds apart, so -1.5 s reads
// "-1.500000" (not "-2.500000").
void appendSeconds(QByteArray& o, int64_t ns) {
    char text[48];
    const uint64_t mag = ns < 0 ? uint64_t(0) - uint64_t(ns) : uint64_t(ns);
    std::snprintf(text, sizeof text, "%s%llu.%06llu", ns < 0 ? "-" : "",
                  static_cast<unsigned long long>(mag / 1000000000ULL),
                  static_cast<unsigned long long>(mag % 1000000000ULL / 1000));
    o += text;
}
}  // namespace

void CsvWriter::writeHeader(const CanFrame*) { out() += "number,time,bus,id,ext,rtr,fd,dir,len,data,summary\n"; }

void CsvWriter::writeGap(int64_t lostNs, int64_t backNs) {
    QByteArray& o = out();
    o += ',';
    appendSeconds(o, lostNs);
    o += ",,,,,,gap,,,";
    appendField(o, captureGapText(lostNs, backNs));
    o += '\n';
}

void CsvWriter::writeFrame(const CanFrame& f, const QString& summary) {
    QByteArray& o = out();
    o += QByteArray::number(qulonglong(frameNumber())) + ',';
    appendSeconds(o, f.timestampNs);
    o += ',';
    appendField(o, busName(f.bus).toUtf8());
    o += ",0x";
    appendHex(o, f.id, f.isExtended() ? 8 : 3);
    o += f.isExtended() ? ",1" : ",0";
    o += f.isRemote() ? ",1" : ",0";
    o += f.isFd() ? ",1," : ",0,";
    o += f.isError() ? "error" : f.isTx() ? "tx" : "rx";
    o += ',' + QByteArray::number(f.len) + ',';
    for (int i = 0; i < f.payloadSize(); ++i) {
        if (i) o += ' ';
        appendHex2(o, f.data[size_t(i)]);
    }
    o += ',';
    appendField(o, summary.toUtf8());
    o += '\n';
}

}  // namespace coscope::logio
