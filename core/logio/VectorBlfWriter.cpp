// SPDX-License-Identifier: GPL-3.0-or-later
// BlfWriter (core/logio/VectorBlf.h): the layout the BlfReader reads, written back.
#include "core/logio/VectorBlf.h"

#include "core/logio/VectorBlfFormat.h"

#include <QDateTime>
#include <QIODevice>

#include <zlib.h>

#include <algorithm>

namespace coscope::logio {

namespace {
using namespace blf;
constexpr uint32_t kFileHeaderSize = 144;
constexpr qsizetype kContainerMax = 128 * 1024;

void blfPut16(QByteArray& b, uint16_t v) {
    b.append(char(v & 0xFF));
    b.append(char(v >> 8));
}
void blfPut32(QByteArray& b, uint32_t v) {
    blfPut16(b, uint16_t(v & 0xFFFF));
    blfPut16(b, uint16_t(v >> 16));
}
void blfPut64(QByteArray& b, uint64_t v) {
    blfPut32(b, uint32_t(v & 0xFFFFFFFFU));
    blfPut32(b, uint32_t(v >> 32));
}
// Windows SYSTEMTIME: year, month, day of week (0 = Sunday), day, hour, minute, second, ms.
void putSystemTime(QByteArray& b, int64_t ns) {
    const QDateTime t = QDateTime::fromMSecsSinceEpoch(ns / 1000000);
    const QDate d = t.date();
    const QTime c = t.time();
    for (int v : {d.year(), d.month(), d.dayOfWeek() % 7, d.day(), c.hour(), c.minute(), c.second(), c.msec()})
        blfPut16(b, uint16_t(v));
}
// "LOBJ" base header + object header v1 (flags 2 = 1 ns timestamps).
void putObjectHeader(QByteArray& b, uint32_t type, uint32_t bodySize, uint64_t ts) {
    b.append("LOBJ", 4);
    blfPut16(b, 32);  // header size
    blfPut16(b, 1);   // header version
    blfPut32(b, 32 + bodySize);
    blfPut32(b, type);
    blfPut32(b, 2);  // timestamp unit: 1 ns
    blfPut16(b, 0);  // client index
    blfPut16(b, 0);  // object version
    blfPut64(b, ts);
}
}  // namespace

QByteArray BlfWriter::header() const {
    QByteArray h;
    h.append("LOGG", 4);
    blfPut32(h, kFileHeaderSize);
    h.append(char(0));                // application ID
    h.append("\x01\x00\x00", 3);      // application version
    h.append("\x02\x06\x08\x01", 4);  // binary log version
    blfPut64(h, fileSize_);
    blfPut64(h, uncompressed_);
    blfPut32(h, objects_);
    blfPut32(h, objects_);  // objects read
    putSystemTime(h, startNs_);
    putSystemTime(h, lastNs_);
    h.append(QByteArray(int(kFileHeaderSize) - int(h.size()), '\0'));
    return h;
}

void BlfWriter::writeHeader(const CanFrame* first) {
    startNs_ = first ? first->timestampNs / 1000000 * 1000000
                     : QDateTime::currentMSecsSinceEpoch() * 1000000;  // SYSTEMTIME has ms
    lastNs_ = startNs_;
    out() += header();
    fileSize_ = kFileHeaderSize;
}

void BlfWriter::writeFrame(const CanFrame& f, const QString&) {
    const uint64_t ts = uint64_t(std::max<int64_t>(0, f.timestampNs - startNs_));
    lastNs_ = std::max(lastNs_, f.timestampNs);
    const uint16_t channel = uint16_t(f.bus + 1);
    const uint32_t id = f.id | (f.isExtended() ? kMsgExt : 0);
    const uint8_t flags = uint8_t((f.isTx() ? kDirTx : 0) | (f.isRemote() ? kRemote : 0));
    QByteArray& c = container_;
    if (f.isError()) {
        putObjectHeader(c, kCanError, 4, ts);
        blfPut16(c, channel);
        blfPut16(c, 0);
    } else if (f.isFd()) {
        putObjectHeader(c, kCanFdMessage, 84, ts);
        blfPut16(c, channel);
        c.append(char(flags));
        c.append(char(fdLengthToDlc(f.len)));
        blfPut32(c, id);
        blfPut32(c, 0);     // frame length in ns: unknown
        c.append(char(0));  // bit count
        c.append(
            char(0x1 | (f.flags & CanFrame::BitRateSwitch ? 0x2 : 0) | (f.flags & CanFrame::ErrorState ? 0x4 : 0)));
        c.append(char(f.payloadSize()));
        c.append(QByteArray(5, '\0'));
        c.append(reinterpret_cast<const char*>(f.data.data()), 64);
    } else {
        putObjectHeader(c, kCanMessage, 16, ts);
        blfPut16(c, channel);
        c.append(char(flags));
        c.append(char(f.len));
        blfPut32(c, id);
        c.append(reinterpret_cast<const char*>(f.data.data()), 8);
    }
    ++objects_;
    if (c.size() >= kContainerMax) closeContainer();
}

void BlfWriter::closeContainer() {
    if (container_.isEmpty()) return;
    uLongf packedLen = compressBound(uLong(container_.size()));
    QByteArray packed(qsizetype(packedLen), '\0');
    const bool zipped =
        compress2(reinterpret_cast<Bytef*>(packed.data()), &packedLen,
                  reinterpret_cast<const Bytef*>(container_.constData()), uLong(container_.size()), 6) == Z_OK;
    if (zipped) packed.truncate(qsizetype(packedLen));
    else packed = container_;  // stored (method 0)
    QByteArray& o = out();
    const qsizetype at = o.size();
    o.append("LOBJ", 4);
    blfPut16(o, 16);  // base header only
    blfPut16(o, 1);
    blfPut32(o, uint32_t(16 + 16 + packed.size()));
    blfPut32(o, kLogContainer);
    blfPut16(o, zipped ? 2 : 0);  // compression: 0 stored, 2 zlib
    o.append(QByteArray(6, '\0'));
    blfPut32(o, uint32_t(container_.size()));
    o.append(QByteArray(4, '\0'));
    o.append(packed);
    // Padding after a container is objectSize % 4 bytes (not up to the next multiple of 4): what
    // Vector's files carry and python-can's BLF reader and writer expect; ours skips either.
    o.append(QByteArray(packed.size() % 4, '\0'));
    fileSize_ += uint64_t(o.size() - at);
    uncompressed_ += uint64_t(container_.size());
    container_.clear();
}

void BlfWriter::beforeFlush() { closeContainer(); }

void BlfWriter::patchHeader(QIODevice& device) {
    const qint64 end = device.pos();
    if (device.seek(0)) {
        device.write(header());
        device.seek(end);
    }
}

}  // namespace coscope::logio
