// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer target for the dissectors and the network context. The input is a frame sequence:
// per frame 2 bytes identifier (11 bits + flag bits 0x8000 remote, 0x4000 29-bit, 0x2000 FD),
// 1 byte length, then that many data bytes (clamped to 8, 64 for FD). Frames run through one
// context at the Tree level, so SDO reassembly, PDO learning and identity matching are fuzzed
// across frames. Node 1 has the Delta dictionary (vendor tables, PDO defaults).
#include "dissectors/DecodeOutput.h"
#include "dissectors/NetworkContext.h"

#include <QCoreApplication>

#include <cstddef>
#include <cstdint>

using namespace coscope;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    static dissect::DictionaryPtr delta = eds::DictionaryLibrary::shared().loadShared(QStringLiteral("delta-asda-a2"));
    dissect::NetworkContext ctx;
    if (delta) ctx.assignDictionary(1, delta, QStringLiteral("delta-asda-a2"));
    dissect::Dissection d;
    QByteArray out;
    size_t i = 0;
    int64_t t = 0;
    while (i + 3 <= size) {
        CanFrame f;
        const uint16_t head = static_cast<uint16_t>(data[i] << 8 | data[i + 1]);
        f.id = head & 0x7FF;
        if (head & 0x4000) {
            f.flags |= CanFrame::Extended;
            f.id |= 0x1FFF0000u & (uint32_t(head) << 16);
        }
        if (head & 0x2000) f.flags |= CanFrame::Fd;
        const size_t maxLen = (head & 0x2000) ? 64 : 8;
        size_t len = data[i + 2] % (maxLen + 1);
        i += 3;
        if (head & 0x8000 && !(head & 0x2000)) {
            f.flags |= CanFrame::Remote;
            f.len = static_cast<uint8_t>(len);
        } else {
            len = std::min(len, size - i);
            f.len = static_cast<uint8_t>(len);
            for (size_t k = 0; k < len; ++k) f.data[k] = data[i + k];
            i += len;
        }
        f.timestampNs = (t += 1000);
        ctx.dissect(f, d, (i & 1) ? dissect::Dissection::Level::Tree : dissect::Dissection::Level::Flat);
        out.resize(0);
        dissect::appendJson(out, f, d, QStringLiteral("can0"));
        dissect::appendText(out, f, d, QStringLiteral("can0"));
        if (d.hasTransfer) dissect::appendTransferJson(out, f, d, QStringLiteral("can0"));
    }
    return 0;
}
