// SPDX-License-Identifier: GPL-3.0-or-later
#include "dissectors/PdoText.h"

#include "dissectors/DoubleText.h"

#include <algorithm>
#include <bit>
#include <iterator>

namespace coscope::dissect {

void writePdoHeader(SummaryBuffer::Cursor& w, bool tpdo, int number, int node) {
    struct Header {
        uint32_t key = 0;  // 0: empty
        uint8_t length = 0;
        char16_t text[31];
    };
    thread_local Header cache[64];
    const bool cacheable = number >= 0 && number <= 0xFFFF && node >= 0 && node <= 0xFF;
    const uint32_t key = (uint32_t(tpdo) << 24 | uint32_t(number & 0xFFFF) << 8 | uint32_t(node & 0xFF)) + 1;
    Header& h = cache[(uint32_t(number) * 7 + uint32_t(node) * 3 + uint32_t(tpdo)) & 63];
    if (!cacheable || h.key != key) {
        SummaryBuffer text;
        {
            SummaryBuffer::Cursor t(text);
            t.put(tpdo ? u"TPDO" : u"RPDO");
            t.putDecimal(static_cast<int64_t>(number));
            t.put(u" node ");
            t.putDecimal(static_cast<int64_t>(node));
            t.put(u':');
        }
        if (!cacheable || text.size() > std::size(h.text)) {
            w.put(text.data(), text.size());
            return;
        }
        h.key = key;
        h.length = static_cast<uint8_t>(text.size());
        std::copy_n(text.data(), text.size(), h.text);
    }
    w.put(h.text, h.length);
}

void writePdoValue(SummaryBuffer::Cursor& w, const PdoTextValue& v) {
    switch (v.form) {
    case PdoTextValue::Form::Hex:
        w.need(od::kHexTextRoom);
        w.advance(static_cast<size_t>(od::hexValueTextTo(w.at(), v.hexKind, v.raw, v.bits)));
        break;
    case PdoTextValue::Form::Signed: w.putDecimal(static_cast<int64_t>(v.raw)); break;
    case PdoTextValue::Form::Unsigned: w.putDecimal(v.raw, false); break;
    case PdoTextValue::Form::Real: {
        const double d = std::bit_cast<double>(v.raw);
        char text[kDoubleTextRoom];
        const int n = writeDoubleG(text, d, 9);  // as valueText() writes a Real
        if (n < 0) {
            w.put(QString::number(d, 'g', 9));
        } else {
            w.need(static_cast<size_t>(n));
            std::copy_n(text, n, w.at());
            w.advance(static_cast<size_t>(n));
        }
        break;
    }
    }
    if (v.unitLength) w.put(v.unit, v.unitLength);
    if (v.meaningLength) {
        w.put(u" (");
        w.put(v.meaning, v.meaningLength);
        w.put(u')');
    }
}

void writePdoSummary(SummaryBuffer::Cursor& w, const PdoTextRecord& r, const PdoTextValue* values) {
    writePdoHeader(w, r.tpdo, r.number, r.node);
    for (uint32_t i = 0; i < r.valueCount; ++i) {
        const PdoTextValue& v = values[i];
        if (i == 0) w.put(v.label + 1, v.labelLength - 1u);  // " name = "
        else w.put(v.label, v.labelLength);
        writePdoValue(w, v);
    }
}

}  // namespace coscope::dissect
