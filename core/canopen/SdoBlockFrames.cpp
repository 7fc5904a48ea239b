// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/canopen/SdoBlockFrames.h"

#include <cstring>

namespace coscope::canopen::sdo {

namespace {
CanFrame request(uint8_t node, uint8_t c0) {
    CanFrame f;
    f.id = 0x600u + node;
    f.len = 8;
    f.data[0] = c0;
    return f;
}
void putMux(CanFrame& f, uint16_t index, uint8_t sub) {
    f.data[1] = static_cast<uint8_t>(index);
    f.data[2] = static_cast<uint8_t>(index >> 8);
    f.data[3] = sub;
}
}  // namespace

CanFrame blockUploadInitiate(uint8_t node, uint16_t index, uint8_t sub, uint8_t blockSize, uint8_t protocolSwitch) {
    CanFrame f = request(node, 0xA4);  // ccs=5, cc=1, cs=0
    putMux(f, index, sub);
    f.data[4] = blockSize;
    f.data[5] = protocolSwitch;
    return f;
}

CanFrame blockUploadStart(uint8_t node) { return request(node, 0xA3); }

CanFrame blockUploadAck(uint8_t node, uint8_t ackSeq, uint8_t blockSize) {
    CanFrame f = request(node, 0xA2);
    f.data[1] = ackSeq;
    f.data[2] = blockSize;
    return f;
}

CanFrame blockUploadEndResponse(uint8_t node) { return request(node, 0xA1); }

CanFrame blockDownloadInitiate(uint8_t node, uint16_t index, uint8_t sub, uint32_t size) {
    CanFrame f = request(node, 0xC6);  // ccs=6, cc=1, s=1, cs=0
    putMux(f, index, sub);
    for (int i = 0; i < 4; ++i) f.data[4 + i] = static_cast<uint8_t>(size >> (8 * i));
    return f;
}

CanFrame blockSegment(uint8_t node, uint8_t seqno, bool last, const char* chunk, int len, bool fromServer) {
    CanFrame f = request(node, static_cast<uint8_t>((seqno & 0x7F) | (last ? 0x80 : 0)));
    if (fromServer) f.id = 0x580u + node;
    if (len > 0) std::memcpy(f.data.data() + 1, chunk, static_cast<size_t>(std::min(len, 7)));
    return f;
}

CanFrame blockDownloadEnd(uint8_t node, uint8_t unusedBytes, uint16_t crc) {
    CanFrame f = request(node, static_cast<uint8_t>(0xC1 | ((unusedBytes & 0x7) << 2)));
    f.data[1] = static_cast<uint8_t>(crc);
    f.data[2] = static_cast<uint8_t>(crc >> 8);
    return f;
}

}  // namespace coscope::canopen::sdo
