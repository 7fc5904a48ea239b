// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer target for the dictionary readers (EDS/DCF via the INI layer, XDD when the input
// looks like XML), plus the DCF writer on whatever was read and every value's typed views.
#include "eds/DcfWriter.h"
#include "eds/EdsReader.h"

#include <cstddef>
#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace coscope;
    const QByteArray bytes(reinterpret_cast<const char*>(data), static_cast<qsizetype>(size));
    const eds::ReadResult r = eds::readDictionary(bytes, QStringLiteral("fuzz.eds"));
    for (const auto& [index, obj] : r.dictionary.objects()) {
        for (const auto& s : obj.subs) {
            if (r.dictionary.entry(index, s.sub) != &s) __builtin_trap();
            if (const auto v = s.resolvedValue(7)) {
                QString err;
                const QByteArray wire = v->encode(s.dataType, &err);
                if (err.isEmpty()) (void)od::Value::decode(s.dataType, wire);
                (void)v->format(s.dataType);
            }
            (void)s.limits();
        }
    }
    if (r.usable && size < 4096) {
        const auto back = eds::EdsReader::read(eds::DcfWriter::write(r.dictionary), QStringLiteral("fuzz.dcf"));
        if (back.dictionary.objectCount() != r.dictionary.objectCount()) __builtin_trap();
    }
    return 0;
}
