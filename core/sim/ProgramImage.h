// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QByteArray>
#include <QString>

#include <cstdint>
#include <optional>

namespace coscope::sim {

// The program image a virtual drive accepts through 1F50h (CiA 302-3 leaves the content of
// program data to the device; this is the simulator's own format). 32-byte header, then the
// payload; every number little-endian:
//   bytes  0-3   magic "CSPI" (CoScope program image)
//   bytes  4-7   payload length in bytes (UNSIGNED32)
//   bytes  8-11  CRC-32 of the payload (IEEE 802.3 / zlib polynomial, reflected, init and
//                final XOR FFFFFFFFh: the value of Python's zlib.crc32(payload))
//   bytes 12-27  software version, ASCII, padded with 00h: the drive's 100Ah after the start
//   bytes 28-31  reserved, 0
// After a good start the drive's 1F56h:01 software identification is the payload's CRC-32.
//
// The same in Python (documented in README):
//   import struct, zlib
//   payload = open('app.bin', 'rb').read()
//   head = b'CSPI' + struct.pack('<II16sI', len(payload), zlib.crc32(payload), b'2.0', 0)
//   open('app.img', 'wb').write(head + payload)
namespace programimage {
inline constexpr int kHeaderSize = 32;
inline constexpr int kVersionSize = 16;
}  // namespace programimage

// CRC-32 (IEEE 802.3, as zlib.crc32).
uint32_t crc32(const QByteArray& data);

struct ProgramImageHeader {
    uint32_t length = 0;
    uint32_t crc = 0;
    QString version;
};

// Wraps `payload` into an image with `version` (at most 16 ASCII characters).
QByteArray makeProgramImage(const QByteArray& payload, const QString& version);

// What a virtual drive's flash sees in an image, as CiA 302-3 flash status error codes
// (1F57h bits 1-7): 0 good, 2 data format unknown (no header), 3 data format error (length
// or CRC do not match). `header` gets the header when the magic is there.
int checkProgramImage(const QByteArray& image, ProgramImageHeader* header = nullptr);

}  // namespace coscope::sim
