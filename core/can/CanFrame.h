// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QString>
#include <QStringView>

#include <array>
#include <cstdint>
#include <optional>

namespace coscope {

// One frame type for everything that travels on or is read from a CAN bus: classic CAN, CAN FD
// (up to 64 bytes, BRS/ESI), remote frames, 11/29-bit identifiers and error frames.
// For an error frame `id` carries the SocketCAN error class bits (linux/can/error.h) and `data`
// the 8 error detail bytes, as candump writes them.
struct CanFrame {
    enum Flag : uint8_t {
        Extended = 0x01,       // 29-bit identifier
        Remote = 0x02,         // RTR: `len` is the requested DLC, no payload
        Fd = 0x04,             // CAN FD frame
        BitRateSwitch = 0x08,  // FD: BRS
        ErrorState = 0x10,     // FD: ESI
        Error = 0x20,          // error frame
        Tx = 0x40,             // transmitted by us (direction), otherwise received
    };

    int64_t timestampNs = 0;  // nanoseconds; live: since the Unix epoch, logs: as the log says
    uint32_t id = 0;
    uint8_t len = 0;  // payload length in bytes (0..8 classic, 0..64 FD)
    uint8_t flags = 0;
    uint8_t bus = 0;  // index of the bus the frame came from (multi-bus traces)
    std::array<uint8_t, 64> data{};

    bool isExtended() const { return flags & Extended; }
    bool isRemote() const { return flags & Remote; }
    bool isFd() const { return flags & Fd; }
    bool isError() const { return flags & Error; }
    bool isTx() const { return flags & Tx; }
    // Bytes actually carried (0 for remote frames).
    uint8_t payloadSize() const { return isRemote() ? 0 : len; }

    static CanFrame classic(uint32_t id, std::initializer_list<uint8_t> bytes, bool extended = false);

    friend bool operator==(const CanFrame& a, const CanFrame& b);
};

// CANopen puts multi-byte values little-endian (CiA 301 §7.1.2): bytes at..at+3 of the payload.
inline void putLe32(CanFrame& f, int at, uint32_t v) {
    for (int i = 0; i < 4; ++i) f.data[at + i] = static_cast<uint8_t>(v >> (8 * i));
}
inline uint32_t le32At(const CanFrame& f, int at) {
    return uint32_t(f.data[at]) | (uint32_t(f.data[at + 1]) << 8) | (uint32_t(f.data[at + 2]) << 16) |
           (uint32_t(f.data[at + 3]) << 24);
}

// CAN FD data length codes (ISO 11898-1): the lengths an FD frame can have.
bool isValidFdLength(int len);
// Smallest valid FD length >= len (payloads are padded up to it).
int roundUpFdLength(int len);
// Payload length of a data length code (ISO 11898-1: 0..8, then 12..64 for FD); -1 outside 0..15.
int fdDlcToLength(int dlc);
// Data length code of a payload length, rounded up to the next FD length (15 for > 64).
int fdLengthToDlc(int len);

// cansend syntax (can-utils lib.c): "123#DEADBEEF", "1F334455#11.22", "123#R", "123#R4",
// "123##1AABBCC" (FD, first hex digit = flags: 1 BRS, 2 ESI), "20000080#..." is not accepted.
std::optional<CanFrame> parseCansend(QStringView text, QString* error);

// candump -L payload part: "123#DEADBEEF", "12345678#R", "123##3AABB"; error frames as
// 8-digit ids with the CAN_ERR_FLAG (0x20000000) set, like candump.
QString formatCansend(const CanFrame& frame);

// One candump -L line: "(1700000000.123456) can0 123#DEADBEEF".
QString formatCandumpL(const CanFrame& frame, QStringView interfaceName);

}  // namespace coscope
