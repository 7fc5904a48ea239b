// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/can/CanFrame.h"
#include "core/logio/PcapLog.h"

#include <QIODevice>

#include <QString>

#include <cstdint>
#include <functional>

namespace coscope::testgen {

// A synthetic CANopen trace for benchmarks and tests: two CiA 402 drives (nodes 1 and 2),
// boot-up and PDO mapping by SDO at the start, then SYNC at 1 kHz, after each SYNC an RPDO1
// (controlword + target position) to and a TPDO1 (statusword + position actual) from each
// drive, heartbeats every 100 ms, an SDO read of 6041h every 10 ms, and an EMCY every 10 s.
// Calls `sink` for each frame, `count` frames in all.
inline void generateCanopenTrace(uint64_t count, const std::function<void(const CanFrame&)>& sink) {
    uint64_t emitted = 0;
    int64_t t = 1700000000LL * 1000000000LL;
    auto put = [&](uint32_t id, std::initializer_list<uint8_t> bytes, int64_t dt = 20000) {
        if (emitted >= count) return;
        CanFrame f = CanFrame::classic(id, bytes);
        t += dt;
        f.timestampNs = t;
        sink(f);
        ++emitted;
    };
    for (uint8_t n = 1; n <= 2; ++n) {
        put(0x700 + n, {0x00});
        // TPDO1 = 6041h (16 bit) + 6064h (32 bit); RPDO1 = 6040h + 607Ah (CiA 301 §7.5.2.36).
        const uint8_t cfg[][8] = {
            {0x23, 0x00, 0x1A, 0x01, 0x10, 0x00, 0x41, 0x60}, {0x23, 0x00, 0x1A, 0x02, 0x20, 0x00, 0x64, 0x60},
            {0x2F, 0x00, 0x1A, 0x00, 0x02, 0, 0, 0},          {0x23, 0x00, 0x16, 0x01, 0x10, 0x00, 0x40, 0x60},
            {0x23, 0x00, 0x16, 0x02, 0x20, 0x00, 0x7A, 0x60}, {0x2F, 0x00, 0x16, 0x00, 0x02, 0, 0, 0}};
        for (const auto& c : cfg) {
            put(0x600 + n, {c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7]});
            put(0x580 + n, {0x60, c[1], c[2], c[3], 0, 0, 0, 0});
        }
    }
    put(0x000, {0x01, 0x00});
    uint8_t syncCounter = 0;
    for (uint64_t ms = 0; emitted < count; ++ms) {
        const int64_t slot = t;
        put(0x080, {}, 0);
        syncCounter = static_cast<uint8_t>(syncCounter % 240 + 1);
        (void)syncCounter;
        for (uint8_t n = 1; n <= 2; ++n) {
            const auto pos = static_cast<int32_t>(ms * 100 * n);
            const auto p = static_cast<uint32_t>(pos);
            put(0x200 + n, {0x0F, 0x00, uint8_t(p), uint8_t(p >> 8), uint8_t(p >> 16), uint8_t(p >> 24)});
            put(0x180 + n, {0x37, 0x16, uint8_t(p), uint8_t(p >> 8), uint8_t(p >> 16), uint8_t(p >> 24)});
        }
        if (ms % 100 == 0)
            for (uint8_t n = 1; n <= 2; ++n) put(0x700 + n, {0x05});
        if (ms % 10 == 5) {
            const uint8_t n = static_cast<uint8_t>(1 + (ms / 10) % 2);
            put(0x600 + n, {0x40, 0x41, 0x60, 0x00, 0, 0, 0, 0});
            put(0x580 + n, {0x4B, 0x41, 0x60, 0x00, 0x37, 0x16, 0, 0});
        }
        if (ms % 10000 == 7777) put(0x081, {0x05, 0x73, 0x01, 0x11, 0x00, 0x00, 0x00, 0x00});
        t = slot + 1000000;  // next SYNC 1 ms after this one
    }
}

// Writes the trace as pcapng (SocketCAN link type, as tshark reads it). Returns false on error.
inline bool writeCanopenTracePcapng(const QString& path, uint64_t count, QString* error = nullptr) {
    logio::PcapngWriter w;
    if (!w.open(path)) {
        if (error) *error = w.errorString();
        return false;
    }
    w.setBusNames({QStringLiteral("can0")});
    generateCanopenTrace(count, [&](const CanFrame& f) { w.write(f); });
    const bool ok = w.close();
    if (!ok && error) *error = w.errorString();
    return ok;
}

}  // namespace coscope::testgen
