// SPDX-License-Identifier: GPL-3.0-or-later
// Writes small ASAM MDF 4.11 files for tests, block by block as the MDF 4.1 block layout
// describes them (ID, HD, DG, CG, CN, CC, TX, DT, DZ, DL, HL, SD): a 24-byte header
// ("##XX", reserved, length, link count), the links, the data; blocks 8-byte aligned.
#pragma once

#include <QByteArray>
#include <QString>

#include <zlib.h>

#include <cstdint>
#include <cstring>
#include <vector>

namespace mdf4test {

inline void put(QByteArray& b, const void* p, size_t n) { b.append(static_cast<const char*>(p), qsizetype(n)); }
inline void u8(QByteArray& b, uint8_t v) { b.append(char(v)); }
inline void u16(QByteArray& b, uint16_t v) { put(b, &v, 2); }
inline void u32(QByteArray& b, uint32_t v) { put(b, &v, 4); }
inline void u64(QByteArray& b, uint64_t v) { put(b, &v, 8); }
inline void f64(QByteArray& b, double v) { put(b, &v, 8); }

// The record layout of the CAN groups these tests write (byte offsets after the record id).
// Data frame: time u64 ns (CC 1e-9 s) at 0, BusChannel u8 at 8, ID u32 at 9 (29 bits),
// flags at 13 (bit 0 IDE, 1 Dir, 2 EDL, 3 BRS, 4 ESI), DLC at 14 (4 bits), DataLength at 15,
// DataBytes at 16: 64 fixed bytes (record 80 bytes) or a VLSD offset u64 (record 24 bytes).
// Remote frame: the same up to byte 15 (record 16 bytes). Error frame: time, BusChannel at 8,
// ErrorType at 9 (record 10 bytes).
struct Frame {
    uint64_t ns = 0;
    uint8_t bus = 1;
    uint32_t id = 0;
    bool ide = false, dir = false, edl = false, brs = false, esi = false;
    uint8_t dlc = 0, len = 0;
    QByteArray bytes;
};

class File {
public:
    explicit File(bool unfinalised = false, uint16_t unfinFlags = 0) {
        out_ = unfinalised ? QByteArray("UnFinMF ") : QByteArray("MDF     ");
        out_ += "4.11    CoScope ";
        u32(out_, 0);
        u16(out_, 411);
        out_.append(30, '\0');
        u16(out_, unfinFlags);
        u16(out_, 0);
        hd_ = block("HD", {0, 0, 0, 0, 0, 0}, hdData(0));
    }

    // Appends a block; returns its offset.
    uint64_t block(const char* tag, const std::vector<uint64_t>& links, const QByteArray& data,
                   uint64_t lengthOverride = 0) {
        while (out_.size() % 8) out_.append('\0');
        const uint64_t at = uint64_t(out_.size());
        out_ += "##";
        out_.append(tag, 2);
        u32(out_, 0);
        u64(out_, lengthOverride ? lengthOverride : 24 + 8 * links.size() + uint64_t(data.size()));
        u64(out_, links.size());
        for (uint64_t l : links) u64(out_, l);
        out_ += data;
        return at;
    }
    void setLink(uint64_t blockAt, int index, uint64_t value) {
        std::memcpy(out_.data() + blockAt + 24 + 8 * index, &value, 8);
    }

    uint64_t text(const char* s) {
        QByteArray d(s);
        d.append('\0');
        return block("TX", {}, d);
    }
    uint64_t linear(double offset, double factor) {
        QByteArray d;
        u8(d, 1);
        u8(d, 0);
        u16(d, 0);
        u16(d, 0);
        u16(d, 2);
        f64(d, 0);
        f64(d, 0);
        f64(d, offset);
        f64(d, factor);
        return block("CC", {0, 0, 0, 0}, d);
    }
    // cn_type, data type, byte offset, bit offset, bit count.
    uint64_t channel(const char* name, uint8_t type, uint8_t dataType, uint32_t byte, uint8_t bit, uint32_t bits,
                     uint64_t cc = 0, uint64_t composition = 0, uint64_t data = 0) {
        QByteArray d;
        u8(d, type);
        u8(d, type == 2 ? 1 : 0);
        u8(d, dataType);
        u8(d, bit);
        u32(d, byte);
        u32(d, bits);
        u32(d, 0);
        u32(d, 0);
        u8(d, 0);
        u8(d, 0);
        u16(d, 0);
        for (int i = 0; i < 6; ++i) f64(d, 0);
        return block("CN", {0, composition, text(name), 0, cc, data, 0, 0}, d);
    }
    void chain(const std::vector<uint64_t>& blocks) {
        for (size_t i = 0; i + 1 < blocks.size(); ++i) setLink(blocks[i], 0, blocks[i + 1]);
    }
    uint64_t group(uint64_t recordId, uint64_t cycles, uint16_t flags, uint32_t dataBytes, uint64_t firstChannel,
                   const char* name = nullptr) {
        QByteArray d;
        u64(d, recordId);
        u64(d, cycles);
        u16(d, flags);
        u16(d, 0);
        u32(d, 0);
        u32(d, dataBytes);
        u32(d, 0);
        return block("CG", {0, firstChannel, name ? text(name) : 0, 0, 0, 0}, d);
    }
    uint64_t dataGroup(uint8_t idSize, uint64_t firstGroup, uint64_t data) {
        QByteArray d;
        u8(d, idSize);
        d.append(7, '\0');
        return block("DG", {0, firstGroup, data, 0}, d);
    }

    // The channels of a CAN group, as described above; returns the first channel.
    // `vlsdData`: DataBytes is a VLSD channel whose data is at that block (patched later when 0).
    uint64_t canChannels(const char* kind, bool vlsd = false, uint64_t vlsdData = 0) {
        const QByteArray k(kind);
        auto n = [&](const char* field) {
            names_.push_back(k + "." + field);
            return names_.back().constData();
        };
        std::vector<uint64_t> children;
        children.push_back(channel(n("BusChannel"), 0, 0, 8, 0, 8));
        if (k == "CAN_ErrorFrame") {
            children.push_back(channel(n("ErrorType"), 0, 0, 9, 0, 8));
        } else {
            children.push_back(channel(n("ID"), 0, 0, 9, 0, 29));
            children.push_back(channel(n("IDE"), 0, 0, 13, 0, 1));
            children.push_back(channel(n("Dir"), 0, 0, 13, 1, 1));
            children.push_back(channel(n("DLC"), 0, 0, 14, 0, 4));
            children.push_back(channel(n("DataLength"), 0, 0, 15, 0, 8));
            if (k == "CAN_DataFrame") {
                children.push_back(channel(n("EDL"), 0, 0, 13, 2, 1));
                children.push_back(channel(n("BRS"), 0, 0, 13, 3, 1));
                children.push_back(channel(n("ESI"), 0, 0, 13, 4, 1));
                dataBytes_ = vlsd ? channel(n("DataBytes"), 1, 10, 16, 0, 64, 0, 0, vlsdData)
                                  : channel(n("DataBytes"), 0, 10, 16, 0, 512);
                children.push_back(dataBytes_);
            }
        }
        chain(children);
        const uint32_t size = k == "CAN_ErrorFrame" ? 10 : k == "CAN_RemoteFrame" ? 16 : vlsd ? 24 : 80;
        const uint64_t composed = channel(kind, 0, 10, 8, 0, (size - 8) * 8, 0, children.front());
        const uint64_t time = channel("Timestamp", 2, 0, 0, 0, 64, linear(0, 1e-9));
        chain({time, composed});
        return time;
    }
    uint64_t lastDataBytes() const { return dataBytes_; }

    static uint32_t recordSize(const char* kind, bool vlsd = false) {
        const QByteArray k(kind);
        return k == "CAN_ErrorFrame" ? 10 : k == "CAN_RemoteFrame" ? 16 : vlsd ? 24 : 80;
    }
    // One record (with its record id of idSize bytes). vlsdOffset >= 0: DataBytes is VLSD.
    static QByteArray record(uint8_t idSize, uint64_t id, const Frame& f, int64_t vlsdOffset = -1,
                             bool remote = false) {
        QByteArray r;
        put(r, &id, idSize);
        u64(r, f.ns);
        u8(r, f.bus);
        u32(r, f.id);
        u8(r, uint8_t(f.ide | f.dir << 1 | f.edl << 2 | f.brs << 3 | f.esi << 4));
        u8(r, f.dlc);
        u8(r, f.len);
        if (remote) return r;
        if (vlsdOffset >= 0) {
            u64(r, uint64_t(vlsdOffset));
        } else {
            QByteArray b = f.bytes.left(64);
            b.append(64 - b.size(), '\0');
            r += b;
        }
        return r;
    }
    static QByteArray errorRecord(uint8_t idSize, uint64_t id, uint64_t ns, uint8_t bus, uint8_t type) {
        QByteArray r;
        put(r, &id, idSize);
        u64(r, ns);
        u8(r, bus);
        u8(r, type);
        return r;
    }

    uint64_t dt(const QByteArray& records, uint64_t lengthOverride = 0) {
        return block("DT", {}, records, lengthOverride);
    }
    uint64_t sd(const QByteArray& samples) { return block("SD", {}, samples); }
    // DZ of `plain` (deflate; transposed first when columns > 0).
    uint64_t dz(const QByteArray& plain, uint32_t columns = 0, const char* original = "DT") {
        QByteArray src = plain;
        if (columns > 1) {
            const qsizetype rows = plain.size() / columns;
            for (qsizetype c = 0; c < columns; ++c)
                for (qsizetype r = 0; r < rows; ++r) src[c * rows + r] = plain[r * columns + c];
        }
        uLongf len = compressBound(uLong(src.size()));
        QByteArray packed(qsizetype(len), '\0');
        compress(reinterpret_cast<Bytef*>(packed.data()), &len, reinterpret_cast<const Bytef*>(src.constData()),
                 uLong(src.size()));
        packed.resize(qsizetype(len));
        QByteArray d(original, 2);
        u8(d, columns > 1 ? 1 : 0);
        u8(d, 0);
        u32(d, columns);
        u64(d, uint64_t(plain.size()));
        u64(d, uint64_t(packed.size()));
        d += packed;
        return block("DZ", {}, d);
    }
    uint64_t dl(const std::vector<uint64_t>& data, uint64_t next = 0) {
        std::vector<uint64_t> links{next};
        links.insert(links.end(), data.begin(), data.end());
        QByteArray d;
        u8(d, 0);
        d.append(3, '\0');
        u32(d, uint32_t(data.size()));
        for (size_t i = 0; i < data.size(); ++i) u64(d, 0);  // offsets (not read)
        return block("DL", links, d);
    }
    uint64_t hl(uint64_t firstList) {
        QByteArray d;
        u16(d, 0);
        u8(d, 0);
        d.append(5, '\0');
        return block("HL", {firstList}, d);
    }

    // The file: HD start time and the first data group.
    QByteArray finish(uint64_t firstDataGroup, uint64_t startNs) {
        setLink(hd_, 0, firstDataGroup);
        const QByteArray d = hdData(startNs);
        std::memcpy(out_.data() + hd_ + 24 + 6 * 8, d.constData(), size_t(d.size()));
        return out_;
    }

private:
    static QByteArray hdData(uint64_t startNs) {
        QByteArray d;
        u64(d, startNs);
        u16(d, 0);
        u16(d, 0);
        u8(d, 2);  // offsets valid: the start time is UTC
        u8(d, 0);
        u8(d, 0);
        u8(d, 0);
        f64(d, 0);
        f64(d, 0);
        return d;
    }
    QByteArray out_;
    uint64_t hd_ = 0;
    uint64_t dataBytes_ = 0;
    std::vector<QByteArray> names_;
};

// A VLSD sample: length u32, bytes.
inline QByteArray vlsdSample(const QByteArray& bytes) {
    QByteArray s;
    u32(s, uint32_t(bytes.size()));
    return s + bytes;
}

}  // namespace mdf4test
