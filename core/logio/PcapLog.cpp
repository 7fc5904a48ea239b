// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/logio/PcapLog.h"

#include "core/logio/CaptureGapText.h"
#include "core/logio/TextScan.h"

#include <QFile>
#include <QIODevice>

#include <algorithm>
#include <limits>

#include <cstring>

namespace coscope::logio {

namespace {
constexpr uint32_t kLinkTypeSocketCan = 227;
constexpr uint32_t kShb = 0x0A0D0D0A, kIdb = 1, kObsoletePacket = 2, kSpb = 3, kEpb = 6;
constexpr uint32_t kByteOrderMagic = 0x1A2B3C4D;
constexpr uint32_t kCanEff = 0x80000000U, kCanRtr = 0x40000000U, kCanErr = 0x20000000U;
constexpr uint8_t kCanfdBrs = 0x01, kCanfdEsi = 0x02, kCanfdFdf = 0x04;
constexpr uint32_t kMaxBlock = 16 * 1024 * 1024;
// epb_flags (pcapng section 4.3.1, option 2): bits 0-1 direction, 01 inbound, 10 outbound.
// CoScope marks the frames it sent (CanFrame::Tx) outbound, as Wireshark shows them.
constexpr uint16_t kOptEpbFlags = 2;
constexpr uint32_t kEpbDirectionMask = 0x3, kEpbOutbound = 0x2;
}  // namespace

uint32_t PcapReader::u32(const unsigned char* p) const { return swapped_ ? be32(p) : le32(p); }
uint16_t PcapReader::u16(const unsigned char* p) const { return swapped_ ? be16(p) : le16(p); }

int64_t PcapReader::toNs(uint64_t ticks, uint64_t ups) const {
    if (ups == 1000000000ULL) return int64_t(ticks);
    if (ups == 1000000ULL) return int64_t(ticks * 1000ULL);  // the default resolution (µs)
    const uint64_t sec = ticks / ups, rem = ticks % ups;
    return int64_t(sec * 1000000000ULL + (unsigned __int128)rem * 1000000000ULL / ups);
}

namespace {
constexpr qsizetype kReadChunk = 1 << 20;  // read ahead 1 MiB at a time
}  // namespace

// The input is read in 1 MiB chunks and parsed in place from the buffer. (Mapping the file
// was no faster and dies with SIGBUS when another program truncates the file while it is read;
// a short read instead ends the file with a "truncated" diagnostic.)
const unsigned char* PcapReader::take(qint64 n, qint64* got) {
    if (end_ - pos_ < n && !eof_) {
        // Move what is left to the front and read more behind it, until n bytes or the end.
        const qsizetype keep = end_ - pos_;
        const qsizetype want = std::max<qsizetype>(qsizetype(n), kReadChunk);
        if (buf_.size() < want) buf_.resize(want);
        if (keep && pos_) std::memmove(buf_.data(), buf_.constData() + pos_, size_t(keep));
        pos_ = 0;
        end_ = keep;
        while (end_ < buf_.size() && !eof_) {
            const qint64 r = device()->read(buf_.data() + end_, buf_.size() - end_);
            if (r <= 0) eof_ = true;
            else end_ += qsizetype(r);
            if (end_ - pos_ >= n) break;
        }
        data_ = reinterpret_cast<const unsigned char*>(buf_.constData());
    }
    const qint64 avail = std::min<qint64>(n, end_ - pos_);
    const unsigned char* p = data_ + pos_;
    pos_ += qsizetype(avail);
    *got = avail;
    return p;
}

bool PcapReader::readExact(char* dst, qint64 n) {
    qint64 got = 0;
    const unsigned char* p = take(n, &got);
    if (got) std::memcpy(dst, p, size_t(got));
    return got == n;
}

bool PcapReader::readHeader() {
    unsigned char h[24];
    if (!readExact(reinterpret_cast<char*>(h), 8)) {
        fail(QStringLiteral("file too short for a pcap header"));
        return false;
    }
    const uint32_t magicLe = le32(h);
    if (magicLe == kShb) {
        ng_ = true;
        return parseSectionHeader(h);
    }
    if (!readExact(reinterpret_cast<char*>(h) + 8, 16)) {
        fail(QStringLiteral("file too short for a pcap header"));
        return false;
    }
    uint64_t ups = 0;
    if (magicLe == 0xA1B2C3D4) ups = 1000000;
    else if (magicLe == 0xA1B23C4D) ups = 1000000000;
    else if (be32(h) == 0xA1B2C3D4) {
        ups = 1000000;
        swapped_ = true;
    } else if (be32(h) == 0xA1B23C4D) {
        ups = 1000000000;
        swapped_ = true;
    } else {
        fail(QStringLiteral("not a pcap or pcapng file (magic %1)").arg(magicLe, 8, 16, QLatin1Char('0')));
        return false;
    }
    pcapItf_.unitsPerSecond = ups;
    pcapItf_.linkType = uint16_t(u32(h + 20) & 0xFFFF);
    if (pcapItf_.linkType != kLinkTypeSocketCan) {
        fail(QStringLiteral("pcap link type %1 is not SocketCAN (227)").arg(pcapItf_.linkType));
        return false;
    }
    pcapItf_.bus = busIndex("can0");
    return true;
}

bool PcapReader::parseSectionHeader(const unsigned char* first8) {
    unsigned char bom[4];
    if (!readExact(reinterpret_cast<char*>(bom), 4)) {
        fail(QStringLiteral("truncated pcapng section header"));
        return false;
    }
    if (le32(bom) == kByteOrderMagic) swapped_ = false;
    else if (be32(bom) == kByteOrderMagic) swapped_ = true;
    else {
        fail(QStringLiteral("pcapng section header has a bad byte-order magic"));
        return false;
    }
    const uint32_t total = u32(first8 + 4);
    if (total < 28 || total > kMaxBlock || total % 4) {
        fail(QStringLiteral("pcapng section header has a bad length %1").arg(total));
        return false;
    }
    qint64 got = 0;
    take(qint64(total) - 12, &got);
    if (got != qint64(total) - 12) {
        fail(QStringLiteral("truncated pcapng section header"));
        return false;
    }
    interfaces_.clear();  // interface ids restart in each section
    return true;
}

void PcapReader::parseInterface(const QByteArray& body) {
    Interface itf;
    const auto* p = reinterpret_cast<const unsigned char*>(body.constData());
    itf.linkType = u16(p);
    QByteArray name;
    // Options: code u16, length u16, value padded to 4.
    for (qsizetype off = 8; off + 4 <= body.size();) {
        const uint16_t code = u16(p + off), len = u16(p + off + 2);
        off += 4;
        if (code == 0 || off + len > body.size()) break;
        if (code == 2) name = QByteArray(body.constData() + off, len);  // if_name
        if (code == 9 && len >= 1) {                                    // if_tsresol
            const uint8_t v = p[off];
            const unsigned e = v & 0x7F;
            uint64_t ups = 1;
            for (unsigned i = 0; i < e && ups < (1ULL << 62) / 10; ++i) ups *= (v & 0x80) ? 2 : 10;
            itf.unitsPerSecond = ups;
        }
        off += (len + 3) & ~3;
    }
    if (name.isEmpty()) name = "can" + QByteArray::number(qsizetype(interfaces_.size()));
    while (name.endsWith('\0')) name.chop(1);
    itf.bus = busIndex(std::string_view(name.constData(), size_t(name.size())));
    interfaces_.push_back(itf);
}

bool PcapReader::decodePacket(const unsigned char* p, uint32_t capLen, const Interface& itf, CanFrame& f) {
    if (itf.linkType != kLinkTypeSocketCan) {
        warn(int64_t(packet_), QStringLiteral("packet with link type %1 is not SocketCAN; skipped").arg(itf.linkType));
        return false;
    }
    if (capLen < 8) {
        warn(int64_t(packet_),
             QStringLiteral("SocketCAN packet of %1 bytes is shorter than its 8-byte header").arg(capLen));
        return false;
    }
    const uint32_t canId = be32(p);
    const uint8_t len = p[4], fdFlags = p[5];
    const bool fd = (fdFlags & kCanfdFdf) || capLen >= 72 || len > 8;
    f.bus = itf.bus;
    if (canId & kCanErr) {
        f.flags |= CanFrame::Error;
        f.id = canId & 0x1FFFFFFF;
    } else {
        f.id = canId & ((canId & kCanEff) ? 0x1FFFFFFFU : 0x7FFU);
        if (canId & kCanEff) f.flags |= CanFrame::Extended;
        if (canId & kCanRtr) f.flags |= CanFrame::Remote;
    }
    if (fd && !f.isError()) {
        f.flags |= CanFrame::Fd;
        if (fdFlags & kCanfdBrs) f.flags |= CanFrame::BitRateSwitch;
        if (fdFlags & kCanfdEsi) f.flags |= CanFrame::ErrorState;
    }
    const uint32_t maxLen = f.isFd() ? 64 : 8;
    if (len > maxLen) {
        warn(int64_t(packet_),
             QStringLiteral("length %1 is too long for a %2 frame").arg(len).arg(f.isFd() ? "CAN FD" : "CAN"));
        return false;
    }
    f.len = len;
    if (f.isRemote()) return true;
    const uint32_t avail = capLen - 8;
    if (avail < len) {
        warn(int64_t(packet_), QStringLiteral("packet truncated: %1 of %2 data bytes captured").arg(avail).arg(len));
        f.len = uint8_t(avail);
    }
    std::memcpy(f.data.data(), p + 8, f.len);
    return true;
}

int PcapReader::readPcapRecord(CanFrame& f) {
    qint64 got = 0;
    const unsigned char* h = take(16, &got);
    if (got == 0) return -1;
    ++packet_;
    if (got < 16) {
        warn(int64_t(packet_), QStringLiteral("truncated packet header at the end of the file"));
        return -1;
    }
    const uint32_t capLen = u32(h + 8);
    if (capLen > kMaxBlock) {
        fail(QStringLiteral("packet %1: captured length %2 is implausible; file is damaged").arg(packet_).arg(capLen));
        return -1;
    }
    const int64_t ts = int64_t(u32(h)) * 1000000000LL + toNs(u32(h + 4), pcapItf_.unitsPerSecond);
    const unsigned char* pkt = take(capLen, &got);
    if (got != qint64(capLen)) {
        warn(int64_t(packet_), QStringLiteral("truncated packet at the end of the file"));
        return -1;
    }
    f.timestampNs = ts;
    return decodePacket(pkt, capLen, pcapItf_, f) ? 1 : 0;
}

int PcapReader::readPcapngBlock(CanFrame& f) {
    unsigned char h[8];
    qint64 got = 0;
    const unsigned char* hp = take(8, &got);
    if (got == 0) return -1;
    if (got < 8) {
        warn(int64_t(packet_ + 1), QStringLiteral("truncated block at the end of the file"));
        return -1;
    }
    std::memcpy(h, hp, 8);
    if (le32(h) == kShb) return parseSectionHeader(h) ? 0 : -1;
    const uint32_t type = u32(h), total = u32(h + 4);
    if (total < 12 || total % 4 || total > kMaxBlock) {
        fail(QStringLiteral("after packet %1: block of type %2 has a bad length %3; file is damaged")
                 .arg(packet_)
                 .arg(type)
                 .arg(total));
        return -1;
    }
    const unsigned char* b = take(qint64(total) - 8, &got);
    if (got != qint64(total) - 8) {
        warn(int64_t(packet_ + 1), QStringLiteral("truncated block at the end of the file"));
        return -1;
    }
    const uint32_t bodyLen = total - 12;
    if (type == kIdb) {
        if (bodyLen < 8) return 0;
        parseInterface(QByteArray(reinterpret_cast<const char*>(b), bodyLen));
        return 0;
    }
    if (type == kEpb || type == kObsoletePacket) {
        ++packet_;
        if (bodyLen < 20) {
            warn(int64_t(packet_), QStringLiteral("packet block too short"));
            return 0;
        }
        const uint32_t itfId = type == kEpb ? u32(b) : u16(b);
        const uint64_t ticks = (uint64_t(u32(b + 4)) << 32) | u32(b + 8);
        const uint32_t capLen = u32(b + 12);
        if (itfId >= interfaces_.size()) {
            warn(int64_t(packet_), QStringLiteral("packet refers to undefined interface %1").arg(itfId));
            return 0;
        }
        if (capLen > bodyLen - 20) {
            warn(int64_t(packet_), QStringLiteral("captured length exceeds the block"));
            return 0;
        }
        const Interface& itf = interfaces_[itfId];
        f.timestampNs = toNs(ticks, itf.unitsPerSecond);
        const uint32_t padded = (capLen + 3) & ~3U;
        uint32_t epbFlags = 0;
        if (type == kEpb && bodyLen > 20 + padded)
            epbFlags = parsePacketOptions(b + 20 + padded, bodyLen - 20 - padded);
        if (!decodePacket(b + 20, capLen, itf, f)) return 0;
        if ((epbFlags & kEpbDirectionMask) == kEpbOutbound) f.flags |= CanFrame::Tx;
        return 1;
    }
    if (type == kSpb) {
        ++packet_;
        if (interfaces_.empty() || bodyLen < 4) {
            warn(int64_t(packet_), QStringLiteral("simple packet without an interface"));
            return 0;
        }
        const uint32_t capLen = std::min(u32(b), bodyLen - 4);
        return decodePacket(b + 4, capLen, interfaces_[0], f) ? 1 : 0;
    }
    return 0;  // name resolution, statistics, custom blocks
}

size_t PcapReader::readFrames(CanFrame* out, size_t max) {
    size_t n = 0;
    while (n < max) {
        if ((n & 0x3FF) == 0x3FF && isCancelled()) break;
        CanFrame& f = out[n];
        f = CanFrame{};
        int r = -2;
        if (ng_ && end_ - pos_ >= 32) {
            // Fast path: a well-formed EPB of a known interface lying whole in the read-ahead
            // buffer is decoded in place; anything else takes the general path below.
            const unsigned char* h = data_ + pos_;
            const auto rd = [this](const unsigned char* q) { return swapped_ ? be32(q) : le32(q); };
            const uint32_t type = rd(h), total = rd(h + 4);
            if (type == kEpb && total >= 32 && total % 4 == 0 && total <= kMaxBlock && qint64(total) <= end_ - pos_) {
                const unsigned char* b = h + 8;
                const uint32_t itfId = rd(b), capLen = rd(b + 12);
                // Blocks with options other than a lone epb_flags (a packet comment) take the
                // general path, which reads them.
                const uint32_t padded = (capLen + 3) & ~3U;
                const uint32_t optLen = capLen <= total - 32 ? total - 32 - padded : 0;
                bool outbound = false;
                bool plain = optLen <= 4;
                if ((optLen == 8 || optLen == 12) && u16(b + 20 + padded) == kOptEpbFlags &&
                    u16(b + 22 + padded) == 4) {
                    plain = true;
                    outbound = (rd(b + 24 + padded) & kEpbDirectionMask) == kEpbOutbound;
                }
                if (itfId < interfaces_.size() && capLen <= total - 32 && plain) {
                    pos_ += qsizetype(total);
                    ++packet_;
                    const Interface& itf = interfaces_[itfId];
                    const uint64_t ticks = (uint64_t(rd(b + 4)) << 32) | rd(b + 8);
                    f.timestampNs = toNs(ticks, itf.unitsPerSecond);
                    const unsigned char* p = b + 20;
                    if (itf.linkType == kLinkTypeSocketCan && capLen >= 8 && capLen < 72 && !(p[5] & kCanfdFdf) &&
                        p[4] <= 8 && capLen - 8 >= p[4]) {
                        // A classic frame captured whole: what decodePacket() does for it.
                        const uint32_t canId = be32(p);
                        f.bus = itf.bus;
                        if (canId & kCanErr) {
                            f.flags |= CanFrame::Error;
                            f.id = canId & 0x1FFFFFFF;
                        } else {
                            f.id = canId & ((canId & kCanEff) ? 0x1FFFFFFFU : 0x7FFU);
                            if (canId & kCanEff) f.flags |= CanFrame::Extended;
                            if (canId & kCanRtr) f.flags |= CanFrame::Remote;
                        }
                        f.len = p[4];
                        if (!f.isRemote()) std::memcpy(f.data.data(), p + 8, f.len);
                        r = 1;
                    } else {
                        r = decodePacket(p, capLen, itf, f) ? 1 : 0;
                    }
                    if (outbound) f.flags |= CanFrame::Tx;
                }
            }
        }
        if (r == -2) r = ng_ ? readPcapngBlock(f) : readPcapRecord(f);
        if (r < 0) {
            finish();
            break;
        }
        if (r > 0) {
            for (CaptureGap& g : pendingGaps_) {
                g.frame = framesRead() + n;
                addGap(g);
            }
            pendingGaps_.clear();
            ++n;
        }
    }
    return n;
}

// Options: code u16, length u16, value padded to 4 (pcapng section 3.5); opt_comment is 1.
uint32_t PcapReader::parsePacketOptions(const unsigned char* p, uint32_t len) {
    uint32_t epbFlags = 0;
    for (uint32_t off = 0; off + 4 <= len;) {
        const uint16_t code = u16(p + off), n = u16(p + off + 2);
        off += 4;
        if (code == 0 || off + n > len) break;
        if (code == kOptEpbFlags && n == 4) epbFlags = u32(p + off);
        int64_t lost = 0, back = 0;
        if (code == 1 && parseCaptureGapText(std::string_view(reinterpret_cast<const char*>(p + off), n), &lost, &back))
            pendingGaps_.push_back({0, lost, back});  // one comment a gap, in the order written
        off += (uint32_t(n) + 3) & ~3U;
    }
    return epbFlags;
}

// ---- writer

namespace {
void put32(QByteArray& o, uint32_t v) {
    const char b[4] = {char(v), char(v >> 8), char(v >> 16), char(v >> 24)};
    o.append(b, 4);
}
void put16(QByteArray& o, uint16_t v) {
    const char b[2] = {char(v), char(v >> 8)};
    o.append(b, 2);
}
void pad4(QByteArray& o) {
    while (o.size() % 4) o.append('\0');
}
}  // namespace

// One comment a gap: gaps without a frame between them (the adapter lost twice in a row) are
// comments of the same packet, in order (pcapng allows an option more than once, section 3.5).
void PcapngWriter::writeGap(int64_t lostNs, int64_t backNs) {
    comments_.push_back(captureGapText(lostNs, backNs).left(0xFFFF));
}

void PcapngWriter::writeHeader(const CanFrame*) {
    QByteArray& o = out();
    const qsizetype start = o.size();
    put32(o, kShb);
    put32(o, 28);
    put32(o, kByteOrderMagic);
    put16(o, 1);
    put16(o, 0);
    put32(o, 0xFFFFFFFF);  // section length unknown
    put32(o, 0xFFFFFFFF);
    put32(o, 28);
    headerBlocks_.push_back({framesWritten(), o.mid(start)});
}

void PcapngWriter::writeInterface(uint8_t bus) {
    QByteArray body;
    put16(body, kLinkTypeSocketCan);
    put16(body, 0);
    put32(body, 72);  // snap length: a whole canfd_frame
    const QByteArray name = busName(bus).toUtf8();
    put16(body, 2);  // if_name
    put16(body, uint16_t(name.size()));
    body += name;
    pad4(body);
    put16(body, 9);  // if_tsresol: 10^-9
    put16(body, 1);
    body.append(char(9));
    pad4(body);
    put16(body, 0);  // opt_endofopt
    put16(body, 0);
    QByteArray& o = out();
    const qsizetype start = o.size();
    put32(o, kIdb);
    put32(o, uint32_t(body.size() + 12));
    o += body;
    put32(o, uint32_t(body.size() + 12));
    headerBlocks_.push_back({framesWritten(), o.mid(start), int(bus)});
    if (interfaceOfBus_.size() <= bus) interfaceOfBus_.resize(size_t(bus) + 1, -1);
    interfaceOfBus_[bus] = int(interfaces_++);
}

void PcapngWriter::writeFrame(const CanFrame& f, const QString&) {
    if (f.bus >= interfaceOfBus_.size() || interfaceOfBus_[f.bus] < 0) writeInterface(f.bus);
    const uint32_t capLen = f.isFd() ? 72 : 16;
    unsigned char pkt[72] = {};
    uint32_t canId = f.id;
    if (f.isError()) canId = (f.id & 0x1FFFFFFF) | kCanErr;
    else {
        if (f.isExtended()) canId |= kCanEff;
        if (f.isRemote()) canId |= kCanRtr;
    }
    pkt[0] = uint8_t(canId >> 24);
    pkt[1] = uint8_t(canId >> 16);
    pkt[2] = uint8_t(canId >> 8);
    pkt[3] = uint8_t(canId);
    pkt[4] = f.len;
    if (f.isFd()) {
        pkt[5] = kCanfdFdf;
        if (f.flags & CanFrame::BitRateSwitch) pkt[5] |= kCanfdBrs;
        if (f.flags & CanFrame::ErrorState) pkt[5] |= kCanfdEsi;
    }
    if (!f.isRemote()) std::memcpy(pkt + 8, f.data.data(), std::min<size_t>(f.len, capLen - 8));
    QByteArray& o = out();
    uint32_t options = 0;
    for (const QByteArray& c : comments_) options += 4 + ((uint32_t(c.size()) + 3) & ~3U);
    if (f.isTx()) options += 8;                             // epb_flags: outbound
    const uint32_t total = 12 + 20 + capLen + options + 4;  // capLen is a multiple of 4
    put32(o, kEpb);
    put32(o, total);
    put32(o, uint32_t(interfaceOfBus_[f.bus]));
    const uint64_t ts = uint64_t(std::max<int64_t>(0, f.timestampNs));
    put32(o, uint32_t(ts >> 32));
    put32(o, uint32_t(ts));
    put32(o, capLen);
    put32(o, capLen);
    o.append(reinterpret_cast<const char*>(pkt), capLen);
    for (const QByteArray& c : comments_) {
        put16(o, 1);  // opt_comment
        put16(o, uint16_t(c.size()));
        o.append(c);
        pad4(o);
    }
    comments_.clear();
    if (f.isTx()) {
        put16(o, kOptEpbFlags);
        put16(o, 4);
        put32(o, kEpbOutbound);
    }
    put16(o, 0);  // opt_endofopt
    put16(o, 0);
    put32(o, total);
}

}  // namespace coscope::logio
