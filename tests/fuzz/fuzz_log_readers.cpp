// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer target: the format sniffer and every log reader on arbitrary bytes. Readers must
// never crash, hang or read out of bounds; they report problems as diagnostics.
#include "core/logio/LogFormats.h"

#include <QBuffer>

#include <cstddef>
#include <cstdint>

using namespace coscope;
using namespace coscope::logio;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const QByteArray bytes(reinterpret_cast<const char*>(data), qsizetype(size));
    (void)LogFormats::detectContent(bytes);
    for (const char* format : {"candump", "asc", "blf", "trc", "pcap"}) {
        QBuffer buf;
        buf.setData(bytes);
        buf.open(QIODevice::ReadOnly);
        auto reader = LogFormats::createReader(QString::fromLatin1(format));
        if (!reader->open(&buf)) continue;
        CanFrame batch[64];
        size_t total = 0;
        while (size_t n = reader->read(batch, 64)) {
            for (size_t i = 0; i < n; ++i)
                if (batch[i].len > 64) __builtin_trap();
            total += n;
        }
        (void)total;
    }
    return 0;
}
