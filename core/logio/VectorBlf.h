// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/logio/LogReader.h"

namespace coscope::logio {

// Vector Binary Logging Format (.blf). Layout facts from python-can's can/io/blf.py (read for
// facts, own code): a "LOGG" file header (start time as a Windows SYSTEMTIME, local time), then
// "LOBJ" objects (base header: signature, header size, header version, object size, type),
// padded to 4 bytes; LOG_CONTAINER (10) holds further objects, zlib-compressed (method 2) or
// stored (method 0), and an object may continue in the next container. Object header v1/v2;
// timestamp unit 10 us (flag 1) or 1 ns (flag 2). Frames: CAN_MESSAGE (1), CAN_MESSAGE2 (86),
// CAN_FD_MESSAGE (100), CAN_FD_MESSAGE_64 (101), CAN_ERROR_EXT (73). Channels count from 1.
// Diagnostics count objects from 1.
class BlfReader : public LogReader {
public:
    QString formatName() const override { return QStringLiteral("blf"); }

protected:
    bool readHeader() override;
    size_t readFrames(CanFrame* out, size_t max) override;

private:
    bool readExact(char* dst, qint64 n);
    bool readTopObject();  // fills pending_ with the objects of the next container
    // Parses the object at `p` (size bytes); returns true when it produced a frame.
    bool decodeObject(const unsigned char* p, size_t size, CanFrame& frame);

    int64_t startNs_ = 0;
    uint64_t object_ = 0;
    QByteArray pending_;  // uncompressed object bytes not parsed yet
    qsizetype pendingPos_ = 0;
    bool eof_ = false;
};

}  // namespace coscope::logio
