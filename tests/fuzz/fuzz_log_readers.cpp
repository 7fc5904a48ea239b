// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer target: the format sniffer and every log reader on arbitrary bytes. Readers must
// never crash, hang or read out of bounds; they report problems as diagnostics.
// COSCOPE_FUZZ_FORMAT=NAME (e.g. busmaster) limits a run to one reader.
#include "core/logio/LogFormats.h"

#include <QBuffer>

#include <cstddef>
#include <cstdint>
#include <cstdlib>

using namespace coscope;
using namespace coscope::logio;

namespace {
QStringList formats() {
    static const QStringList list = [] {
        const QString only = qEnvironmentVariable("COSCOPE_FUZZ_FORMAT");
        if (!only.isEmpty()) return QStringList{only};
        QStringList all;
        for (const auto& f : LogFormats::all())
            if (f.canRead) all << f.name;
        return all;
    }();
    return list;
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const QByteArray bytes(reinterpret_cast<const char*>(data), qsizetype(size));
    (void)LogFormats::detectContent(bytes);
    for (const QString& format : formats()) {
        QBuffer buf;
        buf.setData(bytes);
        buf.open(QIODevice::ReadOnly);
        auto reader = LogFormats::createReader(format);
        if (!reader) __builtin_trap();
        if (!reader->open(&buf)) continue;
        CanFrame batch[64];
        size_t total = 0;
        while (size_t n = reader->read(batch, 64)) {
            for (size_t i = 0; i < n; ++i)
                if (batch[i].len > 64 || (!batch[i].isFd() && batch[i].len > 8 && !batch[i].isError()))
                    __builtin_trap();
            total += n;
        }
        (void)total;
    }
    return 0;
}
