// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/sim/PdoEngine.h"

#include "core/canopen/SdoAbort.h"
#include "core/sim/VirtualDevice.h"

#include <cstring>

namespace coscope::sim {

namespace abortcode = canopen::sdoabort;

namespace {
uint64_t u64(const VirtualDevice& d, uint16_t index, uint8_t sub, uint64_t fallback = 0) {
    return d.value(index, sub).value_or(od::Value{}).toUInt64().value_or(fallback);
}

// Raw little-endian bits of a value for PDO packing.
uint64_t rawBits(const od::Value& v, od::DataType t) {
    switch (od::typeClass(t)) {
    case od::TypeClass::Real: {
        const double d = v.toDouble().value_or(0);
        if (t == od::DataType::Real32) {
            const float f = static_cast<float>(d);
            uint32_t b;
            std::memcpy(&b, &f, 4);
            return b;
        }
        uint64_t b;
        std::memcpy(&b, &d, 8);
        return b;
    }
    case od::TypeClass::Signed: return static_cast<uint64_t>(v.toInt64().value_or(0));
    case od::TypeClass::VisibleString:
    case od::TypeClass::OctetString:
    case od::TypeClass::Domain: {
        uint64_t b = 0;
        const QByteArray bytes = v.toBytes();
        std::memcpy(&b, bytes.constData(), size_t(std::min<qsizetype>(8, bytes.size())));
        return b;
    }
    default: return v.toUInt64().value_or(0);
    }
}

od::Value fromBits(uint64_t raw, int bits, od::DataType t) {
    switch (od::typeClass(t)) {
    case od::TypeClass::Boolean: return od::Value::boolean(raw != 0);
    case od::TypeClass::Signed: {
        if (bits < 64 && (raw & (uint64_t(1) << (bits - 1)))) raw |= ~uint64_t(0) << bits;  // sign-extend
        return od::Value::signedInt(static_cast<int64_t>(raw));
    }
    case od::TypeClass::Real: {
        if (t == od::DataType::Real32) {
            const auto b = static_cast<uint32_t>(raw);
            float f;
            std::memcpy(&f, &b, 4);
            return od::Value::real(f);
        }
        double d;
        std::memcpy(&d, &raw, 8);
        return od::Value::real(d);
    }
    case od::TypeClass::OctetString:
    case od::TypeClass::Domain: return od::Value::bytes(QByteArray(reinterpret_cast<const char*>(&raw), bits / 8));
    default: return od::Value::unsignedInt(raw);
    }
}
}  // namespace

PdoEngine::PdoEngine(VirtualDevice& device) : dev_(device) {}

void PdoEngine::reset() {
    dirty_ = true;
    operational_ = false;
    tpdos_.clear();
    rpdos_.clear();
}

void PdoEngine::readPdo(Pdo& p, uint16_t comm, uint16_t mapping, bool tpdo) {
    p.commIndex = comm;
    const uint64_t cob = u64(dev_, comm, 1, 0x80000000u);
    p.cobId = static_cast<uint32_t>(cob & 0x1FFFFFFF);
    p.valid = !(cob & 0x80000000u);
    p.rtrAllowed = !(cob & 0x40000000u);  // bit 30: no RTR allowed (CiA 301 §7.5.2.35)
    p.type = static_cast<uint8_t>(u64(dev_, comm, 2, 255));
    if (tpdo) {
        p.inhibitNs = static_cast<uint32_t>(u64(dev_, comm, 3)) * 100'000;  // 100 µs units
        p.eventMs = static_cast<uint32_t>(u64(dev_, comm, 5));
        p.syncStart = static_cast<uint8_t>(u64(dev_, comm, 6));
    }
    p.map.clear();
    int bits = 0;
    const auto count = static_cast<int>(u64(dev_, mapping, 0));
    for (int i = 1; i <= count && i <= 64; ++i) {
        const auto e = static_cast<uint32_t>(u64(dev_, mapping, static_cast<uint8_t>(i)));
        Mapped m{static_cast<uint16_t>(e >> 16), static_cast<uint8_t>(e >> 8), static_cast<uint8_t>(e)};
        if (m.bits == 0) continue;
        bits += m.bits;
        p.map.push_back(m);
    }
    p.bytes = (bits + 7) / 8;
    // No mapped object (sub 0 = 0) disables the PDO; more than 8 bytes cannot go on classic CAN.
    if (p.map.empty() || p.bytes > 8) p.valid = false;
}

void PdoEngine::reload() {
    dirty_ = false;
    const auto sync = u64(dev_, 0x1005, 0, 0x80);
    syncCobId_ = static_cast<uint32_t>(sync & 0x7FF);
    std::vector<Pdo> t, r;
    for (int n = 0; n < 512; ++n) {
        const auto comm = static_cast<uint16_t>(0x1800 + n);
        if (!dev_.dictionary().object(comm)) continue;
        Pdo p;
        readPdo(p, comm, static_cast<uint16_t>(0x1A00 + n), true);
        // Keep the running state of a PDO whose configuration did not move; a PDO that is
        // valid again (or has a new mapping) starts afresh and, event-driven, is sent once.
        for (const Pdo& old : tpdos_)
            if (old.commIndex == comm && old.cobId == p.cobId && old.type == p.type && old.valid == p.valid &&
                old.map == p.map) {
                p.syncCount = old.syncCount;
                p.lastTxNs = old.lastTxNs;
                p.nextEventNs = old.nextEventNs;
                p.pending = old.pending;
                p.timerDue = old.timerDue;
                p.lastData = old.lastData;
                p.haveLast = old.haveLast;
                p.latched = old.latched;
                p.latchedValid = old.latchedValid;
            }
        if (p.eventMs && !p.haveLast) p.nextEventNs = dev_.now() + int64_t(p.eventMs) * 1'000'000;
        t.push_back(std::move(p));
    }
    for (int n = 0; n < 512; ++n) {
        const auto comm = static_cast<uint16_t>(0x1400 + n);
        if (!dev_.dictionary().object(comm)) continue;
        Pdo p;
        readPdo(p, comm, static_cast<uint16_t>(0x1600 + n), false);
        r.push_back(std::move(p));
    }
    tpdos_ = std::move(t);
    rpdos_ = std::move(r);
}

int PdoEngine::encode(const Pdo& p, uint8_t* out) const {
    std::memset(out, 0, 8);
    int pos = 0;
    for (const Mapped& m : p.map) {
        uint64_t raw = 0;
        if (m.index >= 8) {  // 0001h-0007h are dummy entries (zeros)
            const od::SubObject* e = dev_.entry(m.index, m.sub);
            const auto v = dev_.value(m.index, m.sub);
            if (e && v) raw = rawBits(*v, e->dataType);
        }
        for (int b = 0; b < m.bits && pos < 64; ++b, ++pos)
            if (raw & (uint64_t(1) << b)) out[pos / 8] |= static_cast<uint8_t>(1u << (pos % 8));
    }
    return p.bytes;
}

void PdoEngine::apply(const Pdo& p, const uint8_t* data, int len) {
    if (len < p.bytes) {
        // PDO not processed due to length error (CiA 301 §7.2.7.1, Table 21).
        const uint8_t none[5] = {};
        dev_.sendEmcy(0x8210, none);
        return;
    }
    int pos = 0;
    for (const Mapped& m : p.map) {
        uint64_t raw = 0;
        for (int b = 0; b < m.bits && pos < 64; ++b, ++pos)
            if (data[pos / 8] & (1u << (pos % 8))) raw |= uint64_t(1) << b;
        if (m.index < 8) continue;
        const od::SubObject* e = dev_.entry(m.index, m.sub);
        if (!e) continue;
        dev_.setValue(m.index, m.sub, fromBits(raw, m.bits, e->dataType));
    }
}

void PdoEngine::sendTpdo(Pdo& p, const uint8_t* data, int len, int64_t nowNs) {
    CanFrame f;
    f.id = p.cobId & (p.cobId & 0x20000000u ? 0x1FFFFFFFu : 0x7FFu);
    if (p.cobId & 0x20000000u) f.flags |= CanFrame::Extended;
    f.len = static_cast<uint8_t>(len);
    std::memcpy(f.data.data(), data, size_t(len));
    dev_.send(f);
    std::memcpy(p.lastData.data(), data, 8);
    p.haveLast = true;
    p.lastTxNs = nowNs;
    p.pending = false;
    if (p.eventMs) {
        // The event timer restarts at every transmission (extract-aimotor §3.6). A send the
        // timer triggered counts from the time the timer expired (within one tick of the
        // simulated clock), so the period does not drift with the tick.
        const int64_t base = p.timerDue && nowNs - p.nextEventNs < 1'000'000 ? p.nextEventNs : nowNs;
        p.nextEventNs = base + int64_t(p.eventMs) * 1'000'000;
    }
    p.timerDue = false;
}

void PdoEngine::onSync(int64_t nowNs, int counter) {
    // RPDOs of synchronous types take effect at the SYNC after their reception (§7.2.2.2).
    for (Pdo& r : rpdos_)
        if (r.rxLen >= 0) {
            apply(r, r.rxData.data(), r.rxLen);
            r.rxLen = -1;
        }
    uint8_t buf[8];
    for (Pdo& p : tpdos_) {
        if (!p.valid) continue;
        if (p.type == 0) {
            // Synchronous acyclic: sent at the SYNC when the mapped data changed.
            const int n = encode(p, buf);
            if (!p.haveLast || std::memcmp(buf, p.lastData.data(), 8) != 0) sendTpdo(p, buf, n, nowNs);
        } else if (p.type <= 240) {
            // Every n-th SYNC; with a SYNC start value, the first one when the counter equals it.
            if (p.syncStart && counter >= 0 && p.syncCount == 0 && !p.haveLast) {
                if (counter != p.syncStart) continue;
                p.syncCount = p.type;
            } else {
                ++p.syncCount;
            }
            if (p.syncCount >= p.type) {
                p.syncCount = 0;
                sendTpdo(p, buf, encode(p, buf), nowNs);
            }
        } else if (p.type == 252) {
            encode(p, p.latched.data());
            p.latchedValid = true;
        }
    }
}

int PdoEngine::syncOverflow() const {
    const od::SubObject* e = dev_.entry(0x1019, 0);
    return e ? static_cast<int>(u64(dev_, 0x1019, 0)) : 0;
}

void PdoEngine::enterOperational(int64_t nowNs) {
    operational_ = true;
    for (Pdo& p : tpdos_) {
        // Event-driven TPDOs go out once on entering OPERATIONAL; cyclic ones count SYNCs anew.
        p.haveLast = false;
        p.syncCount = 0;
        p.latchedValid = false;
        p.timerDue = false;
        if (p.eventMs) p.nextEventNs = nowNs + int64_t(p.eventMs) * 1'000'000;
    }
}

void PdoEngine::nmtStateChanged(bool operational, int64_t nowNs) {
    if (dirty_) reload();
    if (operational != operational_) operational ? enterOperational(nowNs) : leaveOperational();
}

void PdoEngine::leaveOperational() {
    operational_ = false;
    for (Pdo& r : rpdos_) r.rxLen = -1;  // synchronous RPDO data waiting for a SYNC is dropped
    for (Pdo& p : tpdos_) p.pending = false;
}

bool PdoEngine::onFrame(const CanFrame& f, int64_t nowNs, bool operational) {
    nmtStateChanged(operational, nowNs);
    if (f.id == syncCobId_ && !f.isRemote()) {
        // 1019h = 0: SYNC without data, counter not processed; 2..240: one byte, the counter
        // (CiA 301 §7.5.2.22). Another length is an unexpected SYNC length (EMCY 8240h).
        const int overflow = dev_.entry(0x1019, 0) ? syncOverflow() : -1;
        if (overflow >= 0 && f.len != (overflow > 1 ? 1 : 0)) {
            const uint8_t none[5] = {};
            dev_.sendEmcy(0x8240, none);
        }
        if (operational) onSync(nowNs, overflow > 1 && f.len >= 1 ? f.data[0] : -1);
        return true;
    }
    if (!operational) return false;
    if (f.isRemote()) {
        // Remote request of a TPDO (RTR allowed unless bit 30 of its COB-ID).
        for (Pdo& p : tpdos_) {
            if (!p.valid || !p.rtrAllowed || (p.cobId & 0x7FF) != f.id) continue;
            uint8_t buf[8];
            if (p.type == 252) {
                if (p.latchedValid) sendTpdo(p, p.latched.data(), p.bytes, nowNs);
            } else {
                sendTpdo(p, buf, encode(p, buf), nowNs);
            }
            return true;
        }
        return false;
    }
    for (Pdo& r : rpdos_) {
        if (!r.valid || (r.cobId & 0x7FF) != f.id) continue;
        if (dev_.personality().tpdoFeAnswersRpdo)
            for (Pdo& t : tpdos_)
                if (t.type == 254 && t.commIndex - 0x1800 == r.commIndex - 0x1400) t.pending = true;
        if (r.type >= 254) {
            apply(r, f.data.data(), f.len);
        } else {
            std::memcpy(r.rxData.data(), f.data.data(), 8);
            r.rxLen = f.len;
        }
        return true;
    }
    return false;
}

void PdoEngine::tick(int64_t nowNs, bool operational) {
    nmtStateChanged(operational, nowNs);
    if (!operational) return;
    uint8_t buf[8];
    for (Pdo& p : tpdos_) {
        if (!p.valid || p.type < 254) continue;
        const int n = encode(p, buf);
        const bool answersRpdo = p.type == 254 && dev_.personality().tpdoFeAnswersRpdo;
        // Event-driven: change of the mapped data, or the event timer (sub 5) expiring.
        if (!answersRpdo && (!p.haveLast || std::memcmp(buf, p.lastData.data(), 8) != 0)) p.pending = true;
        if (!answersRpdo && p.eventMs && nowNs >= p.nextEventNs && !p.pending) p.pending = p.timerDue = true;
        if (p.pending && (p.lastTxNs < 0 || nowNs - p.lastTxNs >= int64_t(p.inhibitNs))) sendTpdo(p, buf, n, nowNs);
    }
}

uint32_t PdoEngine::checkMappingEntry(bool tpdo, uint32_t entry) const {
    const auto index = static_cast<uint16_t>(entry >> 16);
    const auto sub = static_cast<uint8_t>(entry >> 8);
    const auto bits = static_cast<uint8_t>(entry);
    if (bits == 0) return abortcode::NotMappable;
    if (index >= 1 && index <= 7) return tpdo ? abortcode::NotMappable : 0;  // dummy entries: RPDO only
    const od::Object* obj = dev_.dictionary().object(index);
    if (!obj) return abortcode::NoObject;
    const od::SubObject* e = obj->sub(sub);
    if (!e) return abortcode::NoSubIndex;
    if (!e->pdoMappable) return abortcode::NotMappable;
    if (tpdo ? !od::isReadable(e->access) : !od::isWritable(e->access)) return abortcode::NotMappable;
    const int typeBits = od::bitSize(e->dataType);
    if (typeBits > 0 && bits > typeBits) return abortcode::NotMappable;
    return 0;
}

uint32_t PdoEngine::checkMappingCount(uint16_t mappingIndex, uint8_t count) const {
    const od::Object* obj = dev_.dictionary().object(mappingIndex);
    if (!obj) return abortcode::NoObject;
    int bits = 0;
    for (int i = 1; i <= count; ++i) {
        if (!obj->sub(static_cast<uint8_t>(i))) return abortcode::ValueTooHigh;
        const auto e = static_cast<uint32_t>(u64(dev_, mappingIndex, static_cast<uint8_t>(i)));
        if (const uint32_t code = checkMappingEntry(mappingIndex >= 0x1A00, e)) return code;
        bits += static_cast<uint8_t>(e);
    }
    if (bits > 64) return abortcode::PdoLengthExceeded;
    return 0;
}

}  // namespace coscope::sim
