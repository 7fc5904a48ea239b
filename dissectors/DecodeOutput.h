// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/can/CanFrame.h"
#include "dissectors/Dissection.h"

#include <QByteArray>
#include <QString>

#include <string_view>

namespace coscope::dissect {

// Output formats of `coscope-cli decode` (UTF-8, one line per frame, '\n' ended).
//
// jsonl (DESIGN.md "Contracts"): {"t":1.234567,"bus":"can0","id":385,"ext":false,"rtr":false,
//   "fd":false,"len":6,"data":"371600881300","service":"TPDO1","node":1,"summary":"...",
//   "fields":{...},"warnings":[...]}  — "t" in seconds with 6 decimals, "data" lower-case hex,
//   "node" null when the service has none, "warnings" only when there are any; field value
//   formats are listed in Dissection.h. A completed or aborted SDO transfer adds a line
//   {"record":"sdo_transfer","t":..,"bus":..,"node":1,"object":"1008:00","index":4104,"sub":0,
//    "name":"...","direction":"upload"|"download","mode":"expedited"|"segmented"|"block",
//    "size":12,"data":"hex","value":"text","status":"ok"|"aborted"|"crc error"|"size mismatch",
//    "abort":<integer>,"abort_text":"..." (aborted only)}.
// text: "   12.345678  can0  181  [6]  37 16 00 88 13 00  TPDO1 node 1: ...  ! warning".
// csv: t,bus,id,ext,rtr,fd,len,data,service,node,summary,warnings (RFC 4180 quoting).
void appendJson(QByteArray& out, const CanFrame& f, const Dissection& d, const QString& bus);
void appendTransferJson(QByteArray& out, const CanFrame& f, const Dissection& d, const QString& bus);
void appendText(QByteArray& out, const CanFrame& f, const Dissection& d, const QString& bus);
// The same line from its parts (the summary as UTF-16, `warningCount` warnings), for a
// formatting thread that holds the texts in buffers of its own (app/cli/TextWriter).
void appendText(QByteArray& out, const CanFrame& f, std::u16string_view summary, const QString* warnings,
                qsizetype warningCount, const QString& bus);
// The same line written at `o`, which has room for textLineBound() bytes; returns its end.
qsizetype textLineBound(std::u16string_view summary, const QString* warnings, qsizetype warningCount,
                        const QString& bus);
char* writeTextLine(char* o, const CanFrame& f, std::u16string_view summary, const QString* warnings,
                    qsizetype warningCount, const QString& bus);
void appendCsv(QByteArray& out, const CanFrame& f, const Dissection& d, const QString& bus);
QByteArray csvHeader();
// The transfer record as a text line (for text/csv output).
void appendTransferText(QByteArray& out, const Dissection& d);

// JSON string escaping (RFC 8259) of UTF-8 text, with the quotes.
void appendJsonString(QByteArray& out, const QString& s);

}  // namespace coscope::dissect
