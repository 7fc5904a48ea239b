// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/logio/Mdf4Log.h"

#include "core/logio/TextScan.h"

#include <QIODevice>
#include <QTimeZone>

#include <linux/can/error.h>

#include <algorithm>
#include <cstring>
#include <unordered_set>

namespace coscope::logio {

using namespace mdf4;

namespace {
// DG block: links dg_next, dg_cg_first, dg_data, dg_md_comment; data: dg_rec_id_size (u8).
// CG block: links cg_next, cg_cn_first, cg_tx_acq_name, ...; data: cg_record_id (u64),
// cg_cycle_count (u64), cg_flags (u16, bit 0 VLSD), cg_path_separator (u16), reserved (u32),
// cg_data_bytes (u32), cg_inval_bytes (u32).
constexpr uint16_t kCgVlsd = 0x0001;
constexpr uint16_t kUnfinCycleCounts = 0x0001;  // id_unfin_flags bit 0: cycle counts not updated
constexpr size_t kMaxPendingVlsd = 1 << 16;     // VLSD samples waiting for their record
constexpr uint32_t kMaxVlsdLength = 16 << 20;
constexpr size_t kReorderFrames = 1 << 16;  // 5.8 MB of frames

// CAN_ErrorFrame.ErrorType (ASAM MDF bus logging, as asammdf names the values): 1 bit error,
// 2 form error, 3 bit stuffing error, 4 CRC error, 5 acknowledgment error; 0 and others:
// unknown. Put into SocketCAN's error frame layout (linux/can/error.h), as CanErrorFrame.h
// decodes it.
void setErrorClass(CanFrame& f, uint64_t type, bool tx) {
    f.flags |= CanFrame::Error;
    f.len = CAN_ERR_DLC;
    switch (type) {
    case 1: f.data[2] = CAN_ERR_PROT_BIT; break;
    case 2: f.data[2] = CAN_ERR_PROT_FORM; break;
    case 3: f.data[2] = CAN_ERR_PROT_STUFF; break;
    case 4: f.data[3] = CAN_ERR_PROT_LOC_CRC_SEQ; break;
    case 5: f.id = CAN_ERR_ACK; return;
    default: f.data[2] = CAN_ERR_PROT_UNSPEC; break;
    }
    f.id = CAN_ERR_PROT;
    if (tx) f.data[2] |= CAN_ERR_PROT_TX;
}
}  // namespace

struct Mdf4Reader::Group {
    uint64_t at = 0;  // CG block
    uint64_t recordId = 0;
    uint64_t cycles = 0;
    uint32_t size = 0;  // cg_data_bytes + cg_inval_bytes
    bool vlsd = false;
    bool can = false;
    CanLayout layout;
    uint64_t index = 0;                      // records read so far (the index of virtual channels)
    uint64_t vlsdOffset = 0;                 // VLSD group: offset of the next sample
    std::map<uint64_t, QByteArray> pending;  // VLSD group: samples by offset, not used yet
    int vlsdGroup = -1;                      // CAN group: the VLSD group of its DataBytes
    std::shared_ptr<DataStream> signal;      // CAN group: the SD data of its DataBytes
};

struct Mdf4Reader::DataGroup {
    int number = 0;
    uint64_t at = 0;
    uint8_t idSize = 0;
    std::vector<Group> groups;
    DataStream data;
    QByteArray buf;
    qsizetype pos = 0;
    uint64_t consumed = 0;  // stream offset of buf[0]
    bool end = false;
    CanFrame next;
    bool hasNext = false;
    bool checkCycles = false;

    uint64_t offset() const { return consumed + uint64_t(pos); }
    // The record id at the read position (idSize bytes must be there).
    uint64_t recordId() const {
        const auto* p = reinterpret_cast<const unsigned char*>(buf.constData()) + pos;
        switch (idSize) {
        case 1: return p[0];
        case 2: return le16(p);
        case 4: return le32(p);
        case 8: return le64(p);
        default: return 0;
        }
    }
    bool ensure(qsizetype n) {
        while (buf.size() - pos < n) {
            if (pos > 0) {
                buf.remove(0, pos);
                consumed += uint64_t(pos);
                pos = 0;
            }
            if (!data.next(buf)) return false;
        }
        return true;
    }
};

Mdf4Reader::Mdf4Reader() = default;
Mdf4Reader::~Mdf4Reader() = default;

bool Mdf4Reader::readHeader() {
    if (device()->isSequential()) {
        fail(QStringLiteral("MDF4 needs a file it can seek in, not a stream"));
        return false;
    }
    file_ = std::make_unique<BlockFile>(device());
    unsigned char id[kIdSize];
    if (!file_->readRaw(0, reinterpret_cast<char*>(id), kIdSize)) {
        fail(QStringLiteral("file too short for an MDF identification block (64 bytes)"));
        return false;
    }
    const bool finalisedTag = std::memcmp(id, "MDF     ", 8) == 0;
    if (!finalisedTag && std::memcmp(id, "UnFinMF ", 8) != 0) {
        fail(QStringLiteral("not an MDF file (no \"MDF\" identification at byte 0)"));
        return false;
    }
    const uint16_t version = le16(id + 28);
    if (version < 400 || version >= 500) {
        fail(QStringLiteral("MDF version %1.%2 is not MDF 4 (only MDF 4.x bus logging is read)")
                 .arg(version / 100)
                 .arg(version % 100, 2, 10, QLatin1Char('0')));
        return false;
    }
    const uint16_t unfin = le16(id + 60);
    const bool staleLastDt = !finalisedTag && (unfin & kUnfinLastDtLength);
    // HD block: links hd_dg_first, hd_fh_first, hd_ch_first, hd_at_first, hd_ev_first,
    // hd_md_comment; data: hd_start_time_ns (u64), hd_tz_offset_min, hd_dst_offset_min (i16),
    // hd_time_flags (u8: bit 0 local time, bit 1 offsets valid).
    Block hd;
    QString err;
    if (!file_->read(kIdSize, hd, &err, "HD", 64) || hd.data.size() < 13) {
        fail(err.isEmpty() ? QStringLiteral("HD block at byte 64 is too short") : err);
        return false;
    }
    const auto* h = reinterpret_cast<const unsigned char*>(hd.data.constData());
    startNs_ = int64_t(le64(h));
    if (h[12] & 1) {  // local time: the wall clock of the logger's computer
        const QDateTime local = QDateTime::fromMSecsSinceEpoch(startNs_ / 1000000, QTimeZone::utc());
        startNs_ -= int64_t(QTimeZone::systemTimeZone().offsetFromUtc(local)) * 1000000000LL;
    }
    // The data groups; an unfinalised file's stale DT is the last block of the file, so only
    // the data group whose data comes last runs to the end of the file.
    std::vector<std::pair<uint64_t, uint64_t>> dgs;  // DG block, its data block
    std::unordered_set<uint64_t> seen;
    for (uint64_t at = hd.link(0); at && seen.insert(at).second;) {
        Block dg;
        if (!file_->read(at, dg, &err, "DG", 8)) {
            warn(0, QStringLiteral("%1; the data groups after it are lost").arg(err));
            break;
        }
        dgs.emplace_back(at, dg.link(2));
        at = dg.link(0);
    }
    uint64_t lastData = 0;
    for (const auto& d : dgs) lastData = std::max(lastData, d.second);
    for (size_t i = 0; i < dgs.size(); ++i)
        readDataGroup(dgs[i].first, int(i + 1), staleLastDt && dgs[i].second == lastData);
    for (auto& g : groups_) g->checkCycles = !(unfin & kUnfinCycleCounts) && finalisedTag;
    if (groups_.empty()) {
        // Why: the first problem met, else there is no CAN group at all.
        fail(diagnostics().empty()
                 ? QStringLiteral(
                       "no CAN bus-logging channel group (CAN_DataFrame, CAN_RemoteFrame, CAN_ErrorFrame) in the file")
                 : diagnostics().front().message);
        return false;
    }
    for (auto& g : groups_) advance(*g);
    return true;
}

bool Mdf4Reader::readDataGroup(uint64_t at, int number, bool unfinalisedData) {
    auto dg = std::make_unique<DataGroup>();
    dg->number = number;
    dg->at = at;
    Block b;
    QString err;
    if (!file_->read(at, b, &err, "DG", 8) || b.data.isEmpty()) {
        warn(0, err);
        return false;
    }
    dg->idSize = uint8_t(b.data[0]);
    if (dg->idSize != 0 && dg->idSize != 1 && dg->idSize != 2 && dg->idSize != 4 && dg->idSize != 8) {
        warn(0, QStringLiteral("DG block at byte %1 (data group %2): record id size %3 is not 0, 1, 2, 4 or 8; skipped")
                    .arg(at)
                    .arg(number)
                    .arg(dg->idSize));
        return false;
    }
    bool anyCan = false;
    std::unordered_set<uint64_t> seen;
    for (uint64_t cg = b.link(1); cg && seen.insert(cg).second;) {
        Block c;
        if (!file_->read(cg, c, &err, "CG", 40) || c.data.size() < 32) {
            warn(0, QStringLiteral("%1; data group %2 is skipped")
                        .arg(err.isEmpty() ? QStringLiteral("CG block at byte %1 is too short").arg(cg) : err)
                        .arg(number));
            return false;
        }
        const auto* p = reinterpret_cast<const unsigned char*>(c.data.constData());
        Group g;
        g.at = cg;
        g.recordId = le64(p);
        g.cycles = le64(p + 8);
        g.vlsd = le16(p + 16) & kCgVlsd;
        g.size = le32(p + 24) + le32(p + 28);
        if (!g.vlsd) {
            QString why;
            g.can = readCanLayout(*file_, c.link(1), le32(p + 24), g.layout, &why);
            if (!why.isEmpty())
                warn(0, QStringLiteral("data group %1, CG block at byte %2: %3; its frames are skipped")
                            .arg(number)
                            .arg(cg)
                            .arg(why));
            anyCan = anyCan || g.can;
        }
        dg->groups.push_back(std::move(g));
        cg = c.link(0);
    }
    if (!anyCan) return false;
    for (const auto& g : dg->groups)
        if (dg->idSize == 0 && g.size == 0) {
            warn(
                0,
                QStringLiteral("DG block at byte %1 (data group %2): records of 0 bytes; skipped").arg(at).arg(number));
            return false;
        }
    if (dg->idSize == 0 && dg->groups.size() != 1) {
        warn(0, QStringLiteral("DG block at byte %1 (data group %2) has %3 channel groups but no record ids; skipped")
                    .arg(at)
                    .arg(number)
                    .arg(dg->groups.size()));
        return false;
    }
    QString warning;
    if (!dg->data.open(*file_, b.link(2), unfinalisedData, &err, &warning)) {
        warn(0, QStringLiteral("data group %1: %2; skipped").arg(number).arg(err));
        return false;
    }
    if (!warning.isEmpty()) warn(0, QStringLiteral("data group %1: %2").arg(number).arg(warning));
    // Where each CAN group's VLSD data bytes are: a VLSD channel group of this data group, or
    // signal data (SD, DL, DZ, HL) of their own.
    for (auto& g : dg->groups) {
        if (!g.can || !g.layout.dataBytes.present || !g.layout.dataBytes.isVlsd()) continue;
        const uint64_t link = g.layout.dataBytes.dataLink;
        Block target;
        if (!link || !file_->read(link, target, &err, nullptr, 0)) {
            warn(0,
                 QStringLiteral(
                     "data group %1, CG block at byte %2: its DataBytes point to no data (%3); its frames are skipped")
                     .arg(number)
                     .arg(g.at)
                     .arg(err));
            g.can = false;
            continue;
        }
        if (target.is("CG")) {
            for (size_t i = 0; i < dg->groups.size(); ++i)
                if (dg->groups[i].at == link && dg->groups[i].vlsd) g.vlsdGroup = int(i);
            if (g.vlsdGroup < 0) {
                warn(0, QStringLiteral("data group %1, CG block at byte %2: its DataBytes name CG block %3, which is "
                                       "not a VLSD group of this data group; its frames are skipped")
                            .arg(number)
                            .arg(g.at)
                            .arg(link));
                g.can = false;
            }
            continue;
        }
        g.signal = std::make_shared<DataStream>();
        QString sdWarning;
        if (!g.signal->open(*file_, link, false, &err, &sdWarning)) {
            warn(0, QStringLiteral("data group %1: %2; its frames are skipped").arg(number).arg(err));
            g.can = false;
        } else if (!sdWarning.isEmpty()) {
            warn(0, QStringLiteral("data group %1: %2").arg(number).arg(sdWarning));
        }
    }
    groups_.push_back(std::move(dg));
    return true;
}

void Mdf4Reader::endGroup(DataGroup& dg, const QString& why) {
    if (!why.isEmpty()) warn(int64_t(record_), why);
    dg.end = true;
    dg.hasNext = false;
}

bool Mdf4Reader::advance(DataGroup& dg) {
    dg.hasNext = false;
    while (!dg.end) {
        const uint64_t start = dg.offset();
        auto endOfData = [&](qsizetype need) {
            const qsizetype left = dg.buf.size() - dg.pos;
            QString why = dg.data.error();
            if (why.isEmpty() && left > 0)
                why =
                    QStringLiteral(
                        "data group %1: the last record (at %2, %3 of %4 bytes) is cut short; the file ends inside it")
                        .arg(dg.number)
                        .arg(dg.data.where(start))
                        .arg(left)
                        .arg(need);
            if (dg.checkCycles && why.isEmpty()) {
                for (const auto& g : dg.groups)
                    if (!g.vlsd && g.index != g.cycles)
                        why = QStringLiteral("data group %1: CG block at byte %2 declares %3 records, %4 were read")
                                  .arg(dg.number)
                                  .arg(g.at)
                                  .arg(g.cycles)
                                  .arg(g.index);
            }
            endGroup(dg, why);
            return false;
        };
        if (!dg.ensure(dg.idSize)) return endOfData(dg.idSize);
        const uint64_t rid = dg.recordId();
        Group* g = nullptr;
        if (dg.idSize == 0) g = &dg.groups.front();
        else
            for (auto& c : dg.groups)
                if (c.recordId == rid) g = &c;
        ++record_;
        if (!g) {
            endGroup(dg, QStringLiteral("data group %1: record id %2 at %3 belongs to no channel group; the rest of "
                                        "this data group cannot be read")
                             .arg(dg.number)
                             .arg(rid)
                             .arg(dg.data.where(start)));
            return false;
        }
        if (g->vlsd) {
            const qsizetype missing = storeVlsd(dg, *g);
            if (missing < 0) return false;
            if (missing > 0) return endOfData(missing);
            continue;
        }
        const qsizetype need = dg.idSize + qsizetype(g->size);
        if (!dg.ensure(need)) return endOfData(need);
        const auto* rec = reinterpret_cast<const unsigned char*>(dg.buf.constData()) + dg.pos + dg.idSize;
        QByteArray held;
        bool past = false;  // the read position is already after this record
        if (g->can && g->vlsdGroup >= 0) {
            // CANedge writes a frame's VLSD record right after the frame's record: read on
            // to it (the record is copied first, reading on may move the buffer).
            Group& v = dg.groups[size_t(g->vlsdGroup)];
            const uint64_t wanted = g->layout.dataBytes.raw(rec, g->index);
            if (!v.pending.count(wanted)) {
                held = dg.buf.mid(dg.pos + dg.idSize, qsizetype(g->size));
                dg.pos += need;
                past = true;
                while (!v.pending.count(wanted) && dg.ensure(dg.idSize) && dg.recordId() == v.recordId &&
                       storeVlsd(dg, v) == 0)
                    ++record_;
                rec = reinterpret_cast<const unsigned char*>(held.constData());
            }
        }
        bool got = false;
        if (g->can) {
            dg.next = CanFrame{};
            got = decode(dg, *g, rec, dg.next);
        }
        ++g->index;
        if (!past) dg.pos += need;
        if (got) {
            dg.hasNext = true;
            return true;
        }
    }
    return false;
}

qsizetype Mdf4Reader::storeVlsd(DataGroup& dg, Group& g) {
    if (!dg.ensure(dg.idSize + 4)) return dg.idSize + 4;
    const uint32_t len = le32(reinterpret_cast<const unsigned char*>(dg.buf.constData()) + dg.pos + dg.idSize);
    if (len > kMaxVlsdLength) {
        endGroup(dg, QStringLiteral(
                         "data group %1: VLSD record at %2 claims %3 bytes; the rest of this data group cannot be read")
                         .arg(dg.number)
                         .arg(dg.data.where(dg.offset()))
                         .arg(len));
        return -1;
    }
    const qsizetype need = dg.idSize + 4 + qsizetype(len);
    if (!dg.ensure(need)) return need;
    g.pending[g.vlsdOffset] = dg.buf.mid(dg.pos + dg.idSize + 4, len);
    if (g.pending.size() > kMaxPendingVlsd) g.pending.erase(g.pending.begin());
    g.vlsdOffset += 4 + uint64_t(len);
    ++g.index;
    dg.pos += need;
    return 0;
}

bool Mdf4Reader::decode(DataGroup& dg, Group& g, const unsigned char* rec, CanFrame& f) {
    const CanLayout& l = g.layout;
    const uint64_t i = g.index;
    f.timestampNs = addNs(startNs_, timeNs(l.time, rec, i));
    f.bus = busChannel(l.bus.present ? uint32_t(std::min<uint64_t>(l.bus.integer(rec, i), 256)) : 1);
    const bool tx = l.dir.present && l.dir.integer(rec, i) != 0;
    if (l.kind == FrameKind::Error) {
        setErrorClass(f, l.errorType.present ? l.errorType.integer(rec, i) : 0, tx);
        return true;
    }
    if (tx) f.flags |= CanFrame::Tx;
    const uint64_t rawId = l.id.integer(rec, i);
    f.id = uint32_t(rawId & 0x1FFFFFFF);
    const bool ext = l.ide.present ? l.ide.integer(rec, i) != 0 : (rawId & 0x80000000U) != 0;
    if (ext || f.id > 0x7FF) f.flags |= CanFrame::Extended;
    const int dlc = l.dlc.present ? int(l.dlc.integer(rec, i) & 15) : -1;
    if (l.kind == FrameKind::Remote) {
        f.flags |= CanFrame::Remote;
        // The requested length: the DLC (a remote frame's DataLength may say 0 bytes carried).
        f.len = uint8_t(dlc >= 0               ? std::min(dlc, 8)
                        : l.dataLength.present ? int(std::min<uint64_t>(l.dataLength.integer(rec, i), 8))
                                               : 0);
        return true;
    }
    bool fd = l.edl.present && l.edl.integer(rec, i) != 0;
    if (fd) {
        f.flags |= CanFrame::Fd;
        if (l.brs.present && l.brs.integer(rec, i)) f.flags |= CanFrame::BitRateSwitch;
        if (l.esi.present && l.esi.integer(rec, i)) f.flags |= CanFrame::ErrorState;
    }
    // The data bytes: in the record, or (VLSD) in a VLSD group or signal data.
    const unsigned char* bytes = nullptr;
    size_t avail = 0;
    QByteArray vlsd;
    if (l.dataBytes.isVlsd()) {
        const uint64_t offset = l.dataBytes.raw(rec, i);
        bool found = false;
        if (g.vlsdGroup >= 0) {
            auto& pending = dg.groups[size_t(g.vlsdGroup)].pending;
            auto it = pending.find(offset);
            if (it != pending.end()) {
                vlsd = std::move(it->second);
                found = true;
                pending.erase(pending.begin(), std::next(it));
            }
        } else if (g.signal) {
            QByteArray len;
            found = g.signal->readAt(offset, 4, len) &&
                    le32(reinterpret_cast<const unsigned char*>(len.constData())) <= kMaxVlsdLength &&
                    g.signal->readAt(offset + 4, le32(reinterpret_cast<const unsigned char*>(len.constData())), vlsd);
        }
        if (!found) {
            warn(int64_t(record_),
                 QStringLiteral(
                     "data group %1: the data bytes of the frame %2 at %3 (VLSD offset %4) are missing; frame skipped")
                     .arg(dg.number)
                     .arg(QString::number(f.id, 16).toUpper())
                     .arg(double(f.timestampNs - startNs_) / 1e9, 0, 'f', 6)
                     .arg(offset));
            return false;
        }
        bytes = reinterpret_cast<const unsigned char*>(vlsd.constData());
        avail = size_t(vlsd.size());
    } else if (l.dataBytes.present) {
        bytes = rec + l.dataBytes.byteOffset;
        avail = l.dataBytes.bitCount / 8;
    }
    size_t len = avail;
    if (l.dataLength.present) len = size_t(std::min<uint64_t>(l.dataLength.integer(rec, i), 64));
    else if (dlc >= 0) len = size_t(fd ? fdDlcToLength(dlc) : std::min(dlc, 8));
    len = std::min({len, avail, size_t(64)});
    if (!fd && len > 8) {
        if (l.edl.present) {
            len = 8;
        } else {  // no EDL channel: the length says FD
            fd = true;
            f.flags |= CanFrame::Fd;
        }
    }
    if (fd && !isValidFdLength(int(len))) len = size_t(roundUpFdLength(int(len)));  // zero padded
    f.len = uint8_t(len);
    if (bytes) std::memcpy(f.data.data(), bytes, std::min(len, avail));
    return true;
}

// The data groups merged by time, then through a window of kReorderFrames frames ordered by
// time (equal times keep their order): one data group's channel groups are written in blocks
// (CANedge writes its Tx and Rx groups apart, up to a second out of step).
size_t Mdf4Reader::readFrames(CanFrame* out, size_t max) {
    auto later = [](const Pending& a, const Pending& b) {
        return a.frame.timestampNs != b.frame.timestampNs ? a.frame.timestampNs > b.frame.timestampNs
                                                          : a.sequence > b.sequence;
    };
    size_t n = 0;
    while (n < max) {
        if ((n & 0x3FF) == 0x3FF && isCancelled()) break;
        DataGroup* best = nullptr;
        for (auto& g : groups_)
            if (g->hasNext && (!best || g->next.timestampNs < best->next.timestampNs)) best = g.get();
        if (best) {
            window_.push_back({best->next, sequence_++});
            std::push_heap(window_.begin(), window_.end(), later);
            advance(*best);
            if (window_.size() < kReorderFrames) continue;
        }
        if (window_.empty()) {
            finish();
            break;
        }
        std::pop_heap(window_.begin(), window_.end(), later);
        out[n++] = window_.back().frame;
        window_.pop_back();
    }
    return n;
}

}  // namespace coscope::logio
