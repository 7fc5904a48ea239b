// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/logio/LogReader.h"
#include "core/logio/LogWriter.h"

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
    bool decodeObject(const unsigned char* o, size_t size, CanFrame& frame);

    int64_t startNs_ = 0;
    uint64_t object_ = 0;
    QByteArray pending_;  // uncompressed object bytes not parsed yet
    qsizetype pendingPos_ = 0;
    bool eof_ = false;
};

// Writes BLF as the reader above reads it: the 144-byte "LOGG" header (start time of the first
// frame, local time, ms; file size, object count and stop time patched in at close when the
// device is seekable), then zlib-compressed LOG_CONTAINERs of at most 128 KiB holding
// CAN_MESSAGE (1) for classic frames, CAN_FD_MESSAGE (100) for FD frames and CAN_ERROR (2) for
// error frames, object header v1 with 1 ns timestamps relative to the start. Channels from 1.
class BlfWriter : public LogWriter {
public:
    QString formatName() const override { return QStringLiteral("blf"); }

protected:
    void writeHeader(const CanFrame* first) override;
    void writeFrame(const CanFrame& frame, const QString& summary) override;
    void beforeFlush() override;
    void patchHeader(QIODevice& device) override;

private:
    QByteArray header() const;
    void closeContainer();

    int64_t startNs_ = 0;
    int64_t lastNs_ = 0;
    QByteArray container_;  // uncompressed objects of the open container
    uint64_t fileSize_ = 0, uncompressed_ = 0;
    uint32_t objects_ = 0;
};

}  // namespace coscope::logio
