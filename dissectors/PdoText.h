// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/od/NumberNotation.h"
#include "dissectors/SummaryBuffer.h"

#include <cstdint>
#include <vector>

namespace coscope::dissect {

// A PDO summary ("TPDO1 node 1: Statusword = 1637h (Operation enabled), Position actual
// value = 9397600 inc") as decoded values, before it is text. The PDO dissector decodes every
// frame of integer signals this way and writes the text with writePdoSummary(), at once or,
// through Dissection::pdoTextSink, later on another thread (the CLI's text writer): the texts
// it points to are permanent (od::permanentText), so a record outlives any change of mapping.
struct PdoTextValue {
    enum class Form : uint8_t { Hex, Signed, Unsigned, Real };  // Real: a scaled integer, `raw` its bits
    const char16_t* label = nullptr;    // ", " name " = " (PdoMapEntry::label; the first value drops the comma)
    const char16_t* unit = nullptr;     // " " unit (PdoMapEntry::unitText), or none
    const char16_t* meaning = nullptr;  // CiA 402 meaning ("Operation enabled"), or none
    uint16_t labelLength = 0, unitLength = 0, meaningLength = 0;
    Form form = Form::Unsigned;
    od::HexKind hexKind = od::HexKind::None;  // Form::Hex
    uint8_t bits = 0;
    uint64_t raw = 0;  // Signed: the value as int64_t
};

struct PdoTextRecord {
    bool tpdo = false;
    uint16_t number = 0;  // 1-based PDO number
    uint8_t node = 0;
    uint32_t valuesAt = 0, valueCount = 0;  // in PdoTextSink::values
};

// Where the dissector leaves its records instead of text (Dissection::pdoTextSink).
struct PdoTextSink {
    std::vector<PdoTextRecord> records;
    std::vector<PdoTextValue> values;
    void clear() {
        records.clear();
        values.clear();
    }
};

// "TPDO1 node 1:", from a small cache of the headers last written (the same few PDOs recur).
void writePdoHeader(SummaryBuffer::Cursor& w, bool tpdo, int number, int node);
// A value with its unit and meaning (not its label).
void writePdoValue(SummaryBuffer::Cursor& w, const PdoTextValue& v);
// The whole summary of a record.
void writePdoSummary(SummaryBuffer::Cursor& w, const PdoTextRecord& r, const PdoTextValue* values);

}  // namespace coscope::dissect
