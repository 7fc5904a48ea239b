// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/logio/Mdf4Channels.h"

#include "core/logio/TextScan.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <unordered_set>

namespace coscope::logio::mdf4 {

namespace {
double f64(const unsigned char* p) { return std::bit_cast<double>(le64(p)); }

// CN block links: cn_next, cn_composition, cn_tx_name, cn_si_source, cn_cc_conversion,
// cn_data, cn_md_unit, cn_md_comment. Data: cn_type, cn_sync_type, cn_data_type,
// cn_bit_offset (u8 each), cn_byte_offset, cn_bit_count, cn_flags (u32), ...
enum CnLink { kCnNext = 0, kCnComposition = 1, kCnName = 2, kCnConversion = 4, kCnData = 5 };
constexpr qint64 kCnDataMin = 16;
constexpr int kMaxChannels = 4096;
}  // namespace

double Conversion::apply(double x) const {
    const auto& v = values;
    switch (type) {
    case 1: return v.size() >= 2 ? v[0] + v[1] * x : x;
    case 2:
        if (v.size() >= 6) {
            const double d = v[3] * x * x + v[4] * x + v[5];
            return d != 0 ? (v[0] * x * x + v[1] * x + v[2]) / d : x;
        }
        return x;
    case 4:
    case 5: {
        const size_t n = v.size() / 2;
        if (n == 0) return x;
        if (x <= v[0]) return v[1];
        if (x >= v[2 * (n - 1)]) return v[2 * n - 1];
        size_t i = 1;
        while (i < n && v[2 * i] < x) ++i;
        const double k0 = v[2 * (i - 1)], k1 = v[2 * i];
        if (type == 4)
            return k1 == k0 ? v[2 * i + 1] : v[2 * i - 1] + (v[2 * i + 1] - v[2 * i - 1]) * (x - k0) / (k1 - k0);
        return (x - k0) < (k1 - x) ? v[2 * i - 1] : v[2 * i + 1];  // nearest key
    }
    default: return x;
    }
}

// CC block: links cc_tx_name, cc_md_unit, cc_md_comment, cc_cc_inverse, cc_ref[]; data
// cc_type, cc_precision (u8), cc_flags, cc_ref_count, cc_val_count (u16), phy range (2 f64),
// then cc_val_count f64 values.
Conversion Conversion::read(BlockFile& file, uint64_t at) {
    Conversion c;
    Block b;
    if (!at || !file.read(at, b, nullptr, "CC") || b.data.size() < 24) return c;
    const auto* p = reinterpret_cast<const unsigned char*>(b.data.constData());
    const uint16_t count = le16(p + 6);
    if (24 + 8 * qsizetype(count) > b.data.size()) return c;
    c.type = p[0];
    for (uint16_t i = 0; i < count; ++i) c.values.push_back(f64(p + 24 + 8 * i));
    return c;
}

bool Channel::fits(uint32_t recordBytes) const {
    if (isVirtual()) return true;
    if (bitCount == 0 || bitCount > 64 * 8) return false;
    const uint64_t bytes = (uint64_t(bitOffset) + bitCount + 7) / 8;
    return uint64_t(byteOffset) + bytes <= recordBytes;
}

uint64_t Channel::raw(const unsigned char* rec, uint64_t index) const {
    if (isVirtual()) return index;
    const uint32_t bits = std::min<uint32_t>(bitCount, 64);
    const unsigned bytes = unsigned((bitOffset + bits + 7) / 8);  // at most 9
    unsigned char b[9] = {};
    std::memcpy(b, rec + byteOffset, bytes);
    const bool bigEndian = dataType == 1 || dataType == 3 || dataType == 5;
    if (bigEndian) std::reverse(b, b + bytes);
    unsigned __int128 v = 0;
    for (unsigned i = 0; i < bytes; ++i) v |= static_cast<unsigned __int128>(b[i]) << (8 * i);
    v >>= bitOffset;
    const uint64_t mask = bits >= 64 ? ~0ULL : ((1ULL << bits) - 1);
    return uint64_t(v) & mask;
}

double Channel::value(const unsigned char* rec, uint64_t index) const {
    const uint64_t r = raw(rec, index);
    double x = double(r);
    if (!isVirtual()) {
        if ((dataType == 4 || dataType == 5) && bitCount == 64) x = std::bit_cast<double>(r);
        else if ((dataType == 4 || dataType == 5) && bitCount == 32) x = double(std::bit_cast<float>(uint32_t(r)));
        else if ((dataType == 2 || dataType == 3) && bitCount > 0 && bitCount < 64 && (r >> (bitCount - 1)) & 1)
            x = double(int64_t(r | (~0ULL << bitCount)));
        else if ((dataType == 2 || dataType == 3) && bitCount == 64) x = double(int64_t(r));
    }
    return cc.apply(x);
}

uint64_t Channel::integer(const unsigned char* rec, uint64_t index) const {
    if (cc.type == 0 && !isVirtual() && dataType <= 1) return raw(rec, index);
    const double v = value(rec, index);
    return std::isfinite(v) && v > 0 ? uint64_t(std::llround(std::min(v, 1.8e19))) : 0;
}

int64_t timeNs(const Channel& t, const unsigned char* rec, uint64_t index) {
    const bool integral = t.isVirtual() || t.dataType <= 1;
    if (integral && (t.cc.type == 0 || (t.cc.type == 1 && t.cc.values.size() >= 2 && t.cc.values[0] == 0))) {
        const double perUnit = t.cc.type == 0 ? 1e9 : t.cc.values[1] * 1e9;
        const double whole = std::round(perUnit);
        if (whole >= 1 && std::abs(perUnit - whole) < 1e-6 * whole) return int64_t(t.raw(rec, index) * uint64_t(whole));
    }
    const double s = t.value(rec, index);
    return std::isfinite(s) && std::abs(s) < 9e9 ? int64_t(std::llround(s * 1e9)) : 0;
}

namespace {
bool readChannel(BlockFile& file, const Block& b, Channel& c) {
    if (b.data.size() < kCnDataMin) return false;
    const auto* p = reinterpret_cast<const unsigned char*>(b.data.constData());
    c.present = true;
    c.type = p[0];
    c.dataType = p[2];
    c.bitOffset = p[3] & 7;
    c.byteOffset = le32(p + 4) + p[3] / 8;
    c.bitCount = le32(p + 8);
    c.dataLink = b.link(kCnData);
    c.cc = Conversion::read(file, b.link(kCnConversion));
    return true;
}

Channel* childSlot(CanLayout& l, QStringView field) {
    if (field == u"BusChannel") return &l.bus;
    if (field == u"ID") return &l.id;
    if (field == u"IDE") return &l.ide;
    if (field == u"DLC") return &l.dlc;
    if (field == u"DataLength") return &l.dataLength;
    if (field == u"DataBytes") return &l.dataBytes;
    if (field == u"Dir") return &l.dir;
    if (field == u"EDL") return &l.edl;
    if (field == u"BRS") return &l.brs;
    if (field == u"ESI") return &l.esi;
    if (field == u"ErrorType") return &l.errorType;
    return nullptr;
}

bool frameKind(QStringView name, FrameKind& kind) {
    if (name == u"CAN_DataFrame") kind = FrameKind::Data;
    else if (name == u"CAN_RemoteFrame") kind = FrameKind::Remote;
    else if (name == u"CAN_ErrorFrame") kind = FrameKind::Error;
    else return false;
    return true;
}
}  // namespace

bool readCanLayout(BlockFile& file, uint64_t first, uint32_t recordBytes, CanLayout& l, QString* error) {
    l = CanLayout{};
    bool isCan = false;
    std::unordered_set<uint64_t> seen;
    // Depth-first over the channels and their compositions.
    std::vector<uint64_t> todo{first};
    while (!todo.empty()) {
        const uint64_t at = todo.back();
        todo.pop_back();
        if (!at || !seen.insert(at).second) continue;
        if (seen.size() > kMaxChannels) break;
        Block b;
        QString err;
        if (!file.read(at, b, &err, "CN", 256)) {
            if (isCan && error) *error = err;
            return false;
        }
        todo.push_back(b.link(kCnNext));
        if (b.link(kCnComposition)) todo.push_back(b.link(kCnComposition));
        const QString name = file.text(b.link(kCnName));
        Channel c;
        if (!readChannel(file, b, c)) continue;
        if (c.type == 2 || c.type == 3) {
            if (!l.time.present) l.time = c;
            continue;
        }
        const qsizetype dot = name.lastIndexOf(u'.');
        FrameKind kind;
        if (frameKind(dot < 0 ? QStringView(name) : QStringView(name).left(dot), kind)) {
            isCan = true;
            l.kind = kind;
        } else {
            continue;
        }
        if (dot < 0) continue;  // the composed channel itself
        Channel* slot = childSlot(l, QStringView(name).mid(dot + 1));
        if (!slot) continue;
        const bool bytes = slot == &l.dataBytes && !c.isVlsd();
        if (!c.fits(recordBytes)) {
            if (error)
                *error = QStringLiteral("CN block at byte %1 (%2) lies outside the %3-byte record")
                             .arg(at)
                             .arg(name)
                             .arg(recordBytes);
            return false;
        }
        if (!bytes && c.bitCount > 64) continue;
        *slot = c;
    }
    if (!isCan) return false;
    if (!l.time.present || (l.kind != FrameKind::Error && !l.id.present)) {
        if (error)
            *error = QStringLiteral("CAN channel group without %1")
                         .arg(l.time.present ? QStringLiteral("an ID channel") : QStringLiteral("a time channel"));
        return false;
    }
    if (!l.time.fits(recordBytes)) {
        if (error) *error = QStringLiteral("the time channel lies outside the %1-byte record").arg(recordBytes);
        return false;
    }
    return true;
}

}  // namespace coscope::logio::mdf4
