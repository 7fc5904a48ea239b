// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/logio/VectorBlf.h"

#include "core/logio/TextScan.h"
#include "core/logio/VectorBlfFormat.h"

#include <QDateTime>
#include <QIODevice>

#include <zlib.h>

#include <algorithm>
#include <cstring>

namespace coscope::logio {

namespace {
using namespace blf;
constexpr uint32_t kMaxObject = 64 * 1024 * 1024;

bool isLobj(const unsigned char* p) { return std::memcmp(p, "LOBJ", 4) == 0; }

}  // namespace

bool BlfReader::readExact(char* dst, qint64 n) {
    qint64 got = 0;
    while (got < n) {
        const qint64 r = device()->read(dst + got, n - got);
        if (r <= 0) return false;
        got += r;
    }
    return true;
}

bool BlfReader::readHeader() {
    unsigned char h[72];
    if (!readExact(reinterpret_cast<char*>(h), 8) || std::memcmp(h, "LOGG", 4) != 0) {
        fail(QStringLiteral("not a BLF file (no LOGG signature)"));
        return false;
    }
    const uint32_t headerSize = le32(h + 4);
    if (headerSize < 72 || headerSize > 65536) {
        fail(QStringLiteral("BLF header size %1 is implausible").arg(headerSize));
        return false;
    }
    if (!readExact(reinterpret_cast<char*>(h) + 8, 64)) {
        fail(QStringLiteral("truncated BLF header"));
        return false;
    }
    QByteArray skip(qsizetype(headerSize - 72), '\0');
    if (!readExact(skip.data(), skip.size())) {
        fail(QStringLiteral("truncated BLF header"));
        return false;
    }
    // Start of measurement, SYSTEMTIME: year, month, day of week, day, hour, minute, s, ms.
    const unsigned char* st = h + 40;
    const QDate date(le16(st), le16(st + 2), le16(st + 6));
    const QTime time(le16(st + 8), le16(st + 10), le16(st + 12), le16(st + 14));
    if (date.isValid() && time.isValid() && date.year() >= 1900 && date.year() <= 2200)
        startNs_ = QDateTime(date, time).toMSecsSinceEpoch() * 1000000;
    return true;
}

bool BlfReader::readTopObject() {
    // Top-level objects are 4-byte aligned: skip up to 3 padding bytes before "LOBJ".
    unsigned char h[16];
    qint64 got = device()->read(reinterpret_cast<char*>(h), 16);
    if (got <= 0) return false;
    int shift = 0;
    while (got == 16 && !isLobj(h) && shift < 3) {
        std::memmove(h, h + 1, 15);
        if (device()->read(reinterpret_cast<char*>(h) + 15, 1) != 1) return false;
        ++shift;
    }
    if (got < 16 && std::all_of(h, h + got, [](unsigned char c) { return c == 0; })) return false;  // padding
    ++object_;
    if (got < 16 || !isLobj(h)) {
        if (got < 16) warn(int64_t(object_), QStringLiteral("truncated object at the end of the file"));
        else fail(QStringLiteral("object %1: no LOBJ signature; the rest of the file cannot be read").arg(object_));
        return false;
    }
    const uint16_t headerSize = le16(h + 4);
    const uint32_t size = le32(h + 8), type = le32(h + 12);
    if (size < 16 || size > kMaxObject || headerSize < 16 || headerSize > size) {
        fail(QStringLiteral("object %1: size %2 is implausible; the rest of the file cannot be read")
                 .arg(object_)
                 .arg(size));
        return false;
    }
    QByteArray obj(qsizetype(size), '\0');
    std::memcpy(obj.data(), h, 16);
    if (!readExact(obj.data() + 16, size - 16)) {
        warn(int64_t(object_), QStringLiteral("truncated object at the end of the file"));
        return false;
    }
    // Drop the parsed part of pending_, keep the tail (an object may span containers).
    pending_.remove(0, pendingPos_);
    pendingPos_ = 0;
    if (type != kLogContainer) {  // uncompressed file: objects at the top level
        pending_ += obj;
        return true;
    }
    const auto* p = reinterpret_cast<const unsigned char*>(obj.constData()) + headerSize;
    const size_t avail = size - headerSize;
    if (avail < 16) {
        warn(int64_t(object_), QStringLiteral("container too short"));
        return true;
    }
    const uint16_t method = le16(p);
    const uint32_t unpacked = le32(p + 8);
    if (method == 0) {
        pending_.append(reinterpret_cast<const char*>(p + 16), qsizetype(avail - 16));
    } else if (method == 2) {
        if (unpacked > kMaxObject) {
            warn(int64_t(object_), QStringLiteral("container claims %1 bytes; skipped").arg(unpacked));
            return true;
        }
        const qsizetype at = pending_.size();
        pending_.resize(at + qsizetype(unpacked));
        uLongf outLen = unpacked;
        const int rc = uncompress(reinterpret_cast<Bytef*>(pending_.data() + at), &outLen, p + 16, uLong(avail - 16));
        if (rc != Z_OK) {
            pending_.resize(at);
            warn(int64_t(object_), QStringLiteral("container does not decompress (zlib error %1); skipped").arg(rc));
        } else {
            pending_.resize(at + qsizetype(outLen));
        }
    } else {
        warn(int64_t(object_), QStringLiteral("container uses unknown compression %1; skipped").arg(method));
    }
    return true;
}

bool BlfReader::decodeObject(const unsigned char* o, size_t size, CanFrame& f) {
    const uint16_t headerSize = le16(o + 4), headerVersion = le16(o + 6);
    const uint32_t type = le32(o + 12);
    if (headerVersion != 1 && headerVersion != 2) {
        warn(int64_t(object_), QStringLiteral("object header version %1 unknown; skipped").arg(headerVersion));
        return false;
    }
    if (size < 32 || headerSize > size) return false;
    const uint32_t tsFlags = le32(o + 16);
    const uint64_t ts = le64(o + 24);
    const int64_t rel = tsFlags == 1 ? int64_t(ts * 10000ULL) : int64_t(ts);  // 10 us or 1 ns
    f.timestampNs = addNs(startNs_, rel);
    const unsigned char* d = o + headerSize;
    const size_t n = size - headerSize;
    auto tooShort = [&] {
        warn(int64_t(object_), QStringLiteral("object of type %1 too short (%2 bytes)").arg(type).arg(n));
        return false;
    };
    auto setId = [&](uint32_t raw) {
        f.id = raw & 0x1FFFFFFF;
        if (raw & kMsgExt) f.flags |= CanFrame::Extended;
        else if (f.id > 0x7FF) f.flags |= CanFrame::Extended;
    };
    switch (type) {
    case kCanMessage:
    case kCanMessage2: {
        if (n < 16) return tooShort();
        f.bus = busChannel(le16(d));
        if (d[2] & kDirTx) f.flags |= CanFrame::Tx;
        if (d[2] & kRemote) f.flags |= CanFrame::Remote;
        setId(le32(d + 4));
        f.len = uint8_t(std::min<int>(d[3], 8));  // DLC 9..15 still means 8 bytes on classic CAN
        std::memcpy(f.data.data(), d + 8, 8);
        return true;
    }
    case kCanFdMessage: {
        if (n < 84) return tooShort();
        f.bus = busChannel(le16(d));
        if (d[2] & kDirTx) f.flags |= CanFrame::Tx;
        if (d[2] & kRemote) f.flags |= CanFrame::Remote;
        setId(le32(d + 4));
        const uint8_t fdFlags = d[13];
        if (fdFlags & 0x1) f.flags |= CanFrame::Fd;
        if (fdFlags & 0x2) f.flags |= CanFrame::BitRateSwitch;
        if (fdFlags & 0x4) f.flags |= CanFrame::ErrorState;
        const int len = f.isFd() ? fdDlcToLength(d[3] & 15) : std::min<int>(d[3], 8);
        f.len = uint8_t(f.isRemote() ? len : std::min<int>(len, std::min<int>(d[14], 64)));
        std::memcpy(f.data.data(), d + 20, f.len);
        return true;
    }
    case kCanFdMessage64: {
        if (n < 40) return tooShort();
        f.bus = busChannel(d[0]);
        setId(le32(d + 4));
        const uint32_t flags = le32(d + 12);
        if (flags & 0x1000) f.flags |= CanFrame::Fd;
        if (flags & 0x2000) f.flags |= CanFrame::BitRateSwitch;
        if (flags & 0x4000) f.flags |= CanFrame::ErrorState;
        if (flags & 0x0010) f.flags |= CanFrame::Remote;
        if (d[34]) f.flags |= CanFrame::Tx;
        const size_t valid = std::min<size_t>({d[2], 64, n - 40});
        f.len = uint8_t(f.isRemote() ? std::min<int>(d[1], 8) : int(valid));
        if (!f.isFd() && f.len > 8) f.len = 8;
        if (!f.isRemote()) std::memcpy(f.data.data(), d + 40, f.len);
        return true;
    }
    case kCanErrorExt:
    case kCanError: {
        if (n < 2) return tooShort();
        f.bus = busChannel(le16(d));
        f.flags |= CanFrame::Error;
        return true;
    }
    default: return false;  // markers, statistics, other buses
    }
}

size_t BlfReader::readFrames(CanFrame* out, size_t max) {
    size_t count = 0;
    while (count < max) {
        if ((count & 0x3FF) == 0x3FF && isCancelled()) break;
        const qsizetype left = pending_.size() - pendingPos_;
        const auto* p = reinterpret_cast<const unsigned char*>(pending_.constData()) + pendingPos_;
        // Skip padding between objects inside a container (up to 7 bytes).
        if (left >= 4 && !isLobj(p)) {
            qsizetype skip = 1;
            while (skip < 8 && skip + 4 <= left && !isLobj(p + skip)) ++skip;
            if (skip + 4 <= left && isLobj(p + skip)) {
                pendingPos_ += skip;
                continue;
            }
            if (left >= 12) {
                warn(int64_t(object_),
                     QStringLiteral("lost object alignment inside a container; rest of the container skipped"));
                pendingPos_ = pending_.size();
                continue;
            }
        }
        if (left >= 16 && isLobj(p)) {
            const uint32_t size = le32(p + 8);
            if (size < 16 || size > kMaxObject) {
                warn(int64_t(object_),
                     QStringLiteral("object with size %1 inside a container; rest skipped").arg(size));
                pendingPos_ = pending_.size();
                continue;
            }
            if (qsizetype(size) <= left) {
                CanFrame& f = out[count];
                f = CanFrame{};
                if (decodeObject(p, size, f)) ++count;
                pendingPos_ += size;
                continue;
            }
        }
        if (eof_ || !readTopObject()) {
            eof_ = true;
            if (pending_.size() - pendingPos_ >= 16)
                warn(int64_t(object_), QStringLiteral("the last object is incomplete"));
            finish();
            break;
        }
    }
    return count;
}

}  // namespace coscope::logio
