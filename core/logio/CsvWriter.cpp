// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/logio/CsvWriter.h"

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
}  // namespace

void CsvWriter::writeHeader(const CanFrame*) { out() += "number,time,bus,id,ext,rtr,fd,dir,len,data,summary\n"; }

void CsvWriter::writeFrame(const CanFrame& f, const QString& summary) {
    QByteArray& o = out();
    char head[64];
    const int64_t ns = f.timestampNs;
    const long long sec = static_cast<long long>(ns >= 0 ? ns / 1000000000 : -((-ns + 999999999) / 1000000000));
    const long long usec = static_cast<long long>((ns - sec * 1000000000LL) / 1000);
    std::snprintf(head, sizeof head, "%llu,%lld.%06lld,", static_cast<unsigned long long>(frameNumber()), sec, usec);
    o += head;
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
