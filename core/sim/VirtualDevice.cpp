// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/sim/VirtualDevice.h"

#include "core/canopen/Lss.h"
#include "core/canopen/SdoAbort.h"
#include "core/sim/DexmartMotor.h"
#include "core/sim/DictionaryProvider.h"
#include "core/sim/Ds402Drive.h"
#include "core/sim/HeartbeatConsumer.h"
#include "core/sim/LssSlave.h"
#include "core/sim/PdoEngine.h"
#include "core/sim/ProgramFlash.h"
#include "core/sim/SdoServer.h"

#include <spdlog/spdlog.h>

namespace coscope::sim {

using canopen::NmtState;
namespace abortcode = canopen::sdoabort;

namespace {
// Store/restore signatures "save" and "load" (CiA 301 §7.5.2.13, §7.5.2.14).
constexpr uint32_t kSaveSignature = 0x65766173;
constexpr uint32_t kLoadSignature = 0x64616F6C;

od::Value zeroValue(od::DataType t) {
    switch (od::typeClass(t)) {
    case od::TypeClass::Boolean: return od::Value::boolean(false);
    case od::TypeClass::Signed: return od::Value::signedInt(0);
    case od::TypeClass::Unsigned:
    case od::TypeClass::Time: return od::Value::unsignedInt(0);
    case od::TypeClass::Real: return od::Value::real(0.0);
    case od::TypeClass::VisibleString:
    case od::TypeClass::UnicodeString: return od::Value::text(QString());
    default: return od::Value::bytes(QByteArray());
    }
}

// Which store/restore sub-index covers an object (CiA 301 §7.5.2.13: 1 all, 2 communication,
// 3 application, 4 manufacturer).
bool inStoreGroup(uint8_t group, uint16_t index) {
    switch (group) {
    case 1: return true;
    case 2: return index >= 0x1000 && index <= 0x1FFF;
    case 3: return index >= 0x6000 && index <= 0x9FFF;
    case 4: return index >= 0x2000 && index <= 0x5FFF;
    default: return false;
    }
}

// Error register 1001h bits by error code class (CiA 301 §7.5.2.2).
uint8_t errorRegisterFor(uint16_t code) {
    uint8_t reg = 0x01;  // generic error
    switch (code >> 12) {
    case 0x2: reg |= 0x02; break;                               // current
    case 0x3: reg |= 0x04; break;                               // voltage
    case 0x4: reg |= 0x08; break;                               // temperature
    case 0x8: reg |= (code >> 8) == 0x81 ? 0x10 : 0x20; break;  // communication / profile (8xxx motion)
    case 0xF: reg |= 0x80; break;
    default: break;
    }
    return reg;
}
}  // namespace

std::unique_ptr<VirtualDevice> VirtualDevice::create(uint8_t nodeId, const QString& name, QString* error) {
    auto personality = personalityFor(name, error);
    if (!personality) return nullptr;
    QString why;
    auto dict = loadDictionary(name, &why);
    if (!dict) {
        if (error) *error = QStringLiteral("virtual drive '%1': %2").arg(name, why);
        return nullptr;
    }
    return std::make_unique<VirtualDevice>(nodeId, std::move(*dict), std::move(*personality));
}

VirtualDevice::VirtualDevice(uint8_t nodeId, od::ObjectDictionary dictionary, Personality personality)
    : nodeId_(nodeId), pendingNodeId_(nodeId), storedNodeId_(nodeId), dictionary_(std::move(dictionary)),
      personality_(std::move(personality)) {
    bitRate_ = pendingBitRate_ = storedBitRate_ = personality_.defaultBitRate;
    serial_ = 0x51000000u + nodeId;
    addTestDomain();
    program_ = std::make_unique<ProgramFlash>(*this);
    program_->addObjects(dictionary_);
    sdo_ = std::make_unique<SdoServer>(*this);
    pdo_ = std::make_unique<PdoEngine>(*this);
    lss_ = std::make_unique<LssSlave>(*this);
    heartbeat_ = std::make_unique<HeartbeatConsumer>(*this);
    if (personality_.cia402)
        for (int a = 0; a < personality_.axes; ++a) drives_.push_back(std::make_unique<Ds402Drive>(*this, a));
    if (personality_.vendor == Vendor::Dexmart)
        for (int m = 0; m < personality_.axes; ++m) motors_.push_back(std::make_unique<DexmartMotor>(*this, m));
    loadDefaults(false);
}

VirtualDevice::~VirtualDevice() = default;

void VirtualDevice::addTestDomain() {
    if (dictionary_.object(kTestDomainIndex)) return;
    od::Object o;
    o.index = kTestDomainIndex;
    o.name = QStringLiteral("Simulator test domain (64 KiB)");
    o.objectType = od::ObjectType::Var;
    o.dataType = od::DataType::Domain;
    od::SubObject s;
    s.index = kTestDomainIndex;
    s.sub = 0;
    s.name = o.name;
    s.dataType = od::DataType::Domain;
    s.access = od::Access::ReadWrite;
    o.subs.push_back(s);
    dictionary_.insert(std::move(o));
}

void VirtualDevice::loadDefaults(bool communicationOnly) {
    for (const auto& [index, obj] : dictionary_.objects()) {
        if (communicationOnly && (index < 0x1000 || index > 0x1FFF)) continue;
        for (const od::SubObject& s : obj.subs) {
            auto v = s.resolvedValue(nodeId_ == 0xFF ? 0 : nodeId_);
            values_[key(index, s.sub)] = v ? *v : zeroValue(s.dataType);
        }
    }
    if (!communicationOnly) {
        QByteArray domain(kTestDomainSize, Qt::Uninitialized);
        for (int i = 0; i < domain.size(); ++i) domain[i] = static_cast<char>(i & 0xFF);
        values_[key(kTestDomainIndex, 0)] = od::Value::bytes(domain);
        // A commissioned drive: the vendor's control-mode parameter selects CANopen control.
        if (personality_.controlModeIndex)
            if (auto* slot = valueSlot(personality_.controlModeIndex, personality_.controlModeSub)) {
                const auto* e = entry(personality_.controlModeIndex, personality_.controlModeSub);
                *slot = od::isSigned(e->dataType) ? od::Value::signedInt(personality_.controlModeValue)
                                                  : od::Value::unsignedInt(uint64_t(personality_.controlModeValue));
            }
        if (personality_.nodeIdIndex)
            if (auto* slot = valueSlot(personality_.nodeIdIndex, personality_.nodeIdSub)) {
                const auto* e = entry(personality_.nodeIdIndex, personality_.nodeIdSub);
                *slot = od::isSigned(e->dataType) ? od::Value::signedInt(nodeId_) : od::Value::unsignedInt(nodeId_);
            }
        for (int a = 0; a < std::max(1, personality_.axes); ++a) {
            auto* modes = valueSlot(static_cast<uint16_t>(0x6502 + a * 0x800), 0);
            if (modes && modes->toUInt64().value_or(0) == 0 && personality_.supportedModes)
                *modes = od::Value::unsignedInt(personality_.supportedModes);
        }
    }
    if (auto* serial = valueSlot(0x1018, 4); serial && serial->toUInt64().value_or(0) == 0)
        *serial = od::Value::unsignedInt(serial_);
    program_->publish();  // the program is in flash: no reset changes it
}

void VirtualDevice::setSerialNumber(uint32_t serial) {
    serial_ = serial;
    if (auto* slot = valueSlot(0x1018, 4)) *slot = od::Value::unsignedInt(serial);
}

void VirtualDevice::applyStored(bool communicationOnly) {
    for (const auto& [k, v] : stored_) {
        const auto index = static_cast<uint16_t>(k >> 8);
        if (communicationOnly && (index < 0x1000 || index > 0x1FFF)) continue;
        values_[k] = v;
    }
}

od::Value* VirtualDevice::valueSlot(uint16_t index, uint8_t sub) {
    auto it = values_.find(key(index, sub));
    return it == values_.end() ? nullptr : &it->second;
}

std::optional<od::Value> VirtualDevice::value(uint16_t index, uint8_t sub) const {
    auto it = values_.find(key(index, sub));
    if (it == values_.end()) return std::nullopt;
    return it->second;
}

bool VirtualDevice::setValue(uint16_t index, uint8_t sub, const od::Value& v, QString* error) {
    const od::SubObject* e = entry(index, sub);
    if (!e) {
        if (error)
            *error = QStringLiteral("no entry %1:%2").arg(index, 4, 16, QChar(u'0')).arg(sub, 2, 16, QChar(u'0'));
        return false;
    }
    const od::TypeClass tc = od::typeClass(e->dataType);
    if (tc != od::TypeClass::Domain && tc != od::TypeClass::OctetString && tc != od::TypeClass::VisibleString &&
        tc != od::TypeClass::UnicodeString) {
        QString why;
        if (v.encode(e->dataType, &why).isEmpty()) {
            if (error) *error = why;
            return false;
        }
    }
    values_[key(index, sub)] = v;
    afterWrite(index, sub);
    return true;
}

std::optional<QByteArray> VirtualDevice::readForSdo(uint16_t index, uint8_t sub, uint32_t* abortCode) {
    const od::Object* obj = dictionary_.object(index);
    if (!obj) {
        *abortCode = abortcode::NoObject;
        return std::nullopt;
    }
    const od::SubObject* e = obj->sub(sub);
    if (!e) {
        *abortCode = abortcode::NoSubIndex;
        return std::nullopt;
    }
    if (!od::isReadable(e->access)) {
        *abortCode = abortcode::WriteOnly;
        return std::nullopt;
    }
    // 1003h: entries beyond the number of errors hold no data (CiA 301 §7.5.2.4).
    if (index == 0x1003 && sub > 0) {
        const auto count = value(0x1003, 0).value_or(od::Value{}).toUInt64().value_or(0);
        if (sub > count) {
            *abortCode = abortcode::NoData;
            return std::nullopt;
        }
    }
    // Store/restore read back 1: the device saves/restores on command (CiA 301 §7.5.2.13).
    if ((index == 0x1010 || index == 0x1011) && sub > 0) return QByteArray("\x01\x00\x00\x00", 4);
    const od::Value* v = valueSlot(index, sub);
    const od::TypeClass tc = od::typeClass(e->dataType);
    if (tc == od::TypeClass::Domain || tc == od::TypeClass::OctetString) return v ? v->toBytes() : QByteArray();
    if (tc == od::TypeClass::VisibleString) return v ? v->toText().toLatin1() : QByteArray();
    QString why;
    QByteArray bytes = (v ? *v : zeroValue(e->dataType)).encode(e->dataType, &why);
    if (bytes.isEmpty()) {
        *abortCode = abortcode::GeneralError;
        return std::nullopt;
    }
    return bytes;
}

uint32_t VirtualDevice::writeFromSdo(uint16_t index, uint8_t sub, const QByteArray& bytes) {
    const od::Object* obj = dictionary_.object(index);
    if (!obj) return abortcode::NoObject;
    const od::SubObject* e = obj->sub(sub);
    if (!e) return abortcode::NoSubIndex;
    if (!od::isWritable(e->access)) return abortcode::ReadOnly;
    const int size = od::byteSize(e->dataType);
    if (size > 0 && bytes.size() > size) return abortcode::LengthTooHigh;
    if (size > 0 && bytes.size() < size) return abortcode::LengthTooLow;
    if (ProgramFlash::handles(index)) return program_->write(index, sub, bytes);
    od::ValueResult r = od::Value::decode(e->dataType, bytes);
    if (!r.ok()) return abortcode::TypeMismatch;
    const od::Limits limits = e->limits();
    if (!limits.empty()) {
        QString why;
        if (!od::withinLimits(e->dataType, r.value, limits, &why)) {
            if (why.contains(QLatin1String("High"), Qt::CaseInsensitive)) return abortcode::ValueTooHigh;
            if (why.contains(QLatin1String("Low"), Qt::CaseInsensitive)) return abortcode::ValueTooLow;
            return abortcode::InvalidValue;
        }
    }
    if (const uint32_t code = checkSpecialWrite(index, sub, r.value)) return code;
    // Store and restore act on the signature and keep nothing (§7.5.2.13-14).
    if (index == 0x1010 || index == 0x1011) return 0;
    od::Value v = r.value;
    if (personality_.vendor == Vendor::Delta && index == 0x2301) {
        // P3-01: only digit Z changes when written over CAN (extract-delta §2.4, note 1).
        const int64_t old = value(0x2301, 0).value_or(od::Value{}).toInt64().value_or(0);
        const int64_t z = v.toInt64().value_or(0) & 0x0F00;
        v = od::isSigned(e->dataType) ? od::Value::signedInt((old & ~0x0F00) | z)
                                      : od::Value::unsignedInt(uint64_t((old & ~0x0F00) | z));
    }
    values_[key(index, sub)] = v;
    afterWrite(index, sub);
    return 0;
}

uint32_t VirtualDevice::checkSpecialWrite(uint16_t index, uint8_t sub, const od::Value& v) {
    const uint64_t u = v.toUInt64().value_or(0);
    if (index == 0x1010 && sub > 0) {
        if (u != kSaveSignature) return abortcode::CannotStore;
        for (auto& [k, val] : values_) {
            const auto i = static_cast<uint16_t>(k >> 8);
            const auto s = static_cast<uint8_t>(k & 0xFF);
            if (!inStoreGroup(sub, i) || i == kTestDomainIndex) continue;
            const od::SubObject* en = entry(i, s);
            if (!en || !od::isWritable(en->access) || i == 0x1010 || i == 0x1011) continue;
            // COB-IDs still at their $NODEID default follow the node-ID; do not freeze them.
            if (en->defaultUsesNodeId()) {
                auto def = en->resolvedDefault(nodeId_);
                if (def && *def == val) {
                    stored_.erase(k);
                    continue;
                }
            }
            stored_[k] = val;
        }
        // A node-ID / bit rate set through a vendor parameter is saved with the parameters.
        if (!pendingFromLss_ && inStoreGroup(sub, personality_.nodeIdIndex ? personality_.nodeIdIndex : 0x2000)) {
            storedNodeId_ = pendingNodeId_;
            storedBitRate_ = pendingBitRate_;
        }
        return 0;
    }
    if (index == 0x1011 && sub > 0) {
        if (u != kLoadSignature) return abortcode::CannotStore;
        std::erase_if(stored_,
                      [sub](const auto& kv) { return inStoreGroup(sub, static_cast<uint16_t>(kv.first >> 8)); });
        return 0;  // takes effect at the next reset
    }
    if (index == 0x1016 && sub > 0) return heartbeat_->checkWrite(sub, static_cast<uint32_t>(u));
    if (index == 0x1003 && sub == 0 && u != 0) return abortcode::InvalidValue;  // only 0 clears the history
    if (index == 0x1019 && sub == 0) {
        // Synchronous counter overflow: 0 or 2..240, changed only while 1006h is 0 (CiA 301 §7.5.2.22).
        if (u == 1 || u > 240) return abortcode::InvalidValue;
        if (value(0x1006, 0).value_or(od::Value{}).toUInt64().value_or(0) != 0) return abortcode::DeviceState;
    }
    const bool pdoComm = (index >= 0x1400 && index <= 0x15FF) || (index >= 0x1800 && index <= 0x19FF);
    const bool pdoMap = (index >= 0x1600 && index <= 0x17FF) || (index >= 0x1A00 && index <= 0x1BFF);
    if (pdoComm && sub == 1) {
        // A valid PDO's COB-ID cannot change; set bit 31 first (CiA 301 §7.5.2.35).
        const uint64_t old = value(index, 1).value_or(od::Value{}).toUInt64().value_or(0);
        const bool oldValid = !(old & 0x80000000u), newValid = !(u & 0x80000000u);
        if (oldValid && newValid && (old & 0x1FFFFFFF) != (u & 0x1FFFFFFF)) return abortcode::InvalidValue;
    }
    if (pdoMap) {
        const bool tpdo = index >= 0x1A00;
        const uint16_t comm = static_cast<uint16_t>(index - 0x200);
        const uint64_t cob = value(comm, 1).value_or(od::Value{}).toUInt64().value_or(0x80000000u);
        // The mapping can only change while the PDO is invalid (CiA 301 §7.5.2.36, procedure),
        // except on a device whose COB-ID is read-only (DEXMART DEV: "after power-on the PDO
        // mapping can be changed via SDO", extract-dexmart §4.6): there sub0 = 0 is enough.
        const od::SubObject* cobEntry = dictionary_.entry(comm, 1);
        const bool cobFixed = cobEntry && !od::isWritable(cobEntry->access);
        if (!(cob & 0x80000000u) && !cobFixed) return abortcode::UnsupportedAccess;
        if (sub == 0) return pdo_->checkMappingCount(index, static_cast<uint8_t>(u));
        if (value(index, 0).value_or(od::Value{}).toUInt64().value_or(0) != 0) return abortcode::UnsupportedAccess;
        if (u != 0) return pdo_->checkMappingEntry(tpdo, static_cast<uint32_t>(u));
    }
    if (personality_.controlModeIndex && index >= 0x6000 && index <= 0x9FFF && personality_.cia402) {
        const int64_t mode = value(personality_.controlModeIndex, personality_.controlModeSub)
                                 .value_or(od::Value{})
                                 .toInt64()
                                 .value_or(0);
        // CiA 402 objects act only in the vendor's CANopen control mode (AIMOTOR H02-00 = 8,
        // Delta P1-01 = 0Ch): the drive is under local control otherwise.
        if (mode != personality_.controlModeValue && (index & 0x7FF) == 0x040) return abortcode::LocalControl;
    }
    if (personality_.nodeIdIndex == index && personality_.nodeIdSub == sub && (u < 1 || u > 127))
        return abortcode::InvalidValue;
    if (index >= 0x6000 && index <= 0x9FFF) {
        // The drive's own checks (modes of operation, homing method).
        const auto axis = static_cast<size_t>((index - 0x6000) / 0x800);
        if (axis < drives_.size())
            if (const uint32_t code = drives_[axis]->checkWrite(static_cast<uint16_t>(index - axis * 0x800), sub,
                                                                v.toInt64().value_or(0)))
                return code;
    }
    if (personality_.vendor == Vendor::Delta && index == 0x2301 && ((u >> 8) & 0xF) > 4) return abortcode::ValueTooHigh;
    return 0;
}

void VirtualDevice::afterWrite(uint16_t index, uint8_t sub) {
    if (index >= 0x1400 && index <= 0x1BFF) pdo_->invalidate();
    if (index == 0x1005) pdo_->invalidate();
    if (index == 0x1017)
        nextHeartbeatNs_ = nowNs_ + int64_t(value(0x1017, 0).value_or(od::Value{}).toUInt64().value_or(0)) * 1'000'000;
    if (index == 0x1003 && sub == 0)
        for (uint8_t s = 1; s < 255; ++s) {
            auto* slot = valueSlot(0x1003, s);
            if (!slot) break;
            *slot = od::Value::unsignedInt(0);
        }
    if (personality_.parametersStoredOnWrite && index >= 0x2000 && index <= 0x2FFF)
        stored_[key(index, sub)] = values_[key(index, sub)];  // Delta: P-parameters go to EEPROM at once
    const auto& ns = personality_.nodeSettings;
    if (ns && ns->nodeId && ns->nodeId->index == index && ns->nodeId->sub == sub) {
        // The node-ID parameter takes effect at the next power cycle / reset node (Delta P3-00 "●").
        pendingNodeId_ = static_cast<uint8_t>(value(index, sub).value_or(od::Value{}).toUInt64().value_or(nodeId_));
        pendingFromLss_ = false;
        if (ns->nodeId->storedOnWrite) storedNodeId_ = pendingNodeId_;
    }
    if (ns && ns->bitRate && ns->bitRate->index == index && ns->bitRate->sub == sub) {
        // Delta P3-01 digit Z (extract-delta §2.4); active after power cycle / reset node.
        const auto raw = static_cast<uint32_t>(value(index, sub).value_or(od::Value{}).toUInt64().value_or(0));
        if (const int rate = canopen::decodeVendorBitRate(*ns->bitRate, raw); rate > 0) {
            pendingBitRate_ = static_cast<uint32_t>(rate);
            if (ns->bitRate->storedOnWrite) storedBitRate_ = pendingBitRate_;
        }
    }
    if (index >= 0x6000 && index <= 0x9FFF) {
        const auto axis = static_cast<size_t>((index - 0x6000) / 0x800);
        if (axis < drives_.size()) drives_[axis]->onWrite(static_cast<uint16_t>(index - axis * 0x800), sub);
    }
    if (!motors_.empty())
        for (auto& m : motors_) m->onWrite(index, sub);
}

void VirtualDevice::powerOn(int64_t nowNs) {
    nowNs_ = nowNs;
    powered_ = true;
    if (nodeId_ == 0xFF) return;  // LSS-unconfigured: waits for a node-ID
    bootUp(nowNs);
}

void VirtualDevice::powerCycle() {
    nodeId_ = pendingNodeId_ = storedNodeId_;
    pendingFromLss_ = false;
    bitRate_ = pendingBitRate_ = storedBitRate_;
    values_.clear();
    loadDefaults(false);
    applyStored(false);
    for (auto& d : drives_) d->reset();
    for (auto& m : motors_) m->reset();
    sdo_->reset();
    pdo_->reset();
    if (powered_ && nodeId_ != 0xFF) bootUp(nowNs_);
}

void VirtualDevice::makeUnconfigured() {
    nodeId_ = pendingNodeId_ = 0xFF;
    setNmtState(NmtState::BootUp);
    sdo_->reset();
    pdo_->reset();
}

void VirtualDevice::bootUp(int64_t nowNs) {
    // Boot-up: 700h + node-ID, one byte 00h (CiA 301 §7.2.8.3.3); then PRE-OPERATIONAL.
    transmit(CanFrame::classic(0x700u + nodeId_, {0x00}));
    setNmtState(NmtState::PreOperational);
    const auto hb = int64_t(value(0x1017, 0).value_or(od::Value{}).toUInt64().value_or(0));
    nextHeartbeatNs_ = nowNs + hb * 1'000'000;
    guardToggle_ = false;
    guardingStarted_ = false;
    heartbeat_->reset();
}

void VirtualDevice::setNmtState(NmtState s) {
    nmtState_ = s;
    if (pdo_) pdo_->nmtStateChanged(s == NmtState::Operational, nowNs_);
}

void VirtualDevice::resetCommunication(int64_t nowNs) {
    if (pendingFromLss_) nodeId_ = pendingNodeId_;
    pendingFromLss_ = false;
    bitRate_ = pendingBitRate_;
    loadDefaults(true);
    applyStored(true);
    sdo_->reset();
    pdo_->reset();
    if (nodeId_ != 0xFF) bootUp(nowNs);
}

void VirtualDevice::resetNode(int64_t nowNs) {
    nodeId_ = pendingNodeId_;
    pendingFromLss_ = false;
    bitRate_ = pendingBitRate_;
    values_.clear();
    loadDefaults(false);
    applyStored(false);
    for (auto& d : drives_) d->reset();
    for (auto& m : motors_) m->reset();
    sdo_->reset();
    pdo_->reset();
    if (nodeId_ != 0xFF) bootUp(nowNs);
}

void VirtualDevice::handleNmt(const CanFrame& f, int64_t nowNs) {
    // NMT node control: byte 0 command specifier, byte 1 node-ID, 0 = all (CiA 301 §7.2.8.3.1).
    if (f.len != 2 || (f.data[1] != 0 && f.data[1] != nodeId_)) return;
    // An LSS-unconfigured node only takes a reset, which activates a node-ID configured by LSS.
    if (nodeId_ == 0xFF && f.data[0] != 0x81 && f.data[0] != 0x82) return;
    switch (f.data[0]) {
    case 0x01: setNmtState(NmtState::Operational); break;
    case 0x02: setNmtState(NmtState::Stopped); break;
    case 0x80: setNmtState(NmtState::PreOperational); break;
    case 0x81: {
        if (personality_.alarmOnResetWhileEnabled) {
            for (int a = 0; a < axisCount(); ++a)
                if (drives_[a]->enabled()) {
                    // Delta: Reset Node while the servo is on raises AL401 and the drive stays
                    // as it is, faulted (extract-delta §1 and §6.3: EMCY 8100h, alarm 0401h).
                    injectDriveFault(DriveFault{0x8100, 0x0401, a});
                    return;
                }
        }
        resetNode(nowNs);
        break;
    }
    case 0x82: resetCommunication(nowNs); break;
    default: break;
    }
}

void VirtualDevice::handleGuarding(int64_t nowNs) {
    // Node guarding: the master's RTR on 700h + node-ID is answered with the state and a toggle
    // bit 7 that starts at 0 and alternates (CiA 301 §7.2.8.3.2.1).
    const uint8_t state = static_cast<uint8_t>(nmtState_) | (guardToggle_ ? 0x80 : 0);
    guardToggle_ = !guardToggle_;
    guardingStarted_ = true;
    lastGuardNs_ = nowNs;
    transmit(CanFrame::classic(0x700u + nodeId_, {state}));
}

void VirtualDevice::onFrame(const CanFrame& f, int64_t nowNs) {
    if (f.isExtended() || f.isError() || !powered_) return;
    nowNs_ = nowNs;
    if (f.id == 0x000) {
        if (!f.isRemote()) handleNmt(f, nowNs);
        return;
    }
    if (f.id == canopen::lss::kMasterToSlave) {
        if (!f.isRemote()) lss_->onFrame(f);
        return;
    }
    if (nodeId_ == 0xFF) return;
    if (f.id == 0x700u + nodeId_) {
        if (f.isRemote()) handleGuarding(nowNs);
        return;
    }
    if (f.id > 0x700 && f.id < 0x780 && !f.isRemote())
        heartbeat_->onHeartbeat(static_cast<uint8_t>(f.id - 0x700), nowNs);
    if (nmtState_ == NmtState::Stopped) return;
    if (f.id == 0x600u + nodeId_ && !f.isRemote()) {
        ++sdoRequests_;
        sdo_->onRequest(f, nowNs);
        return;
    }
    pdo_->onFrame(f, nowNs, nmtState_ == NmtState::Operational);
}

void VirtualDevice::tick(int64_t nowNs) {
    if (!powered_) return;
    const int64_t dt = nowNs_ ? nowNs - nowNs_ : 1'000'000;
    nowNs_ = nowNs;
    lss_->tick(nowNs);
    if (nodeId_ == 0xFF) return;
    sdo_->tick(nowNs);
    if (program_->takeResetRequest()) {
        resetNode(nowNs);  // into the program just started (CiA 302-3): boot-up follows
        return;
    }
    heartbeat_->tick(nowNs);
    const auto hbMs = int64_t(value(0x1017, 0).value_or(od::Value{}).toUInt64().value_or(0));
    if (hbMs > 0 && nowNs >= nextHeartbeatNs_) {
        sendHeartbeat();
        nextHeartbeatNs_ += hbMs * 1'000'000;
        if (nextHeartbeatNs_ < nowNs) nextHeartbeatNs_ = nowNs + hbMs * 1'000'000;
    }
    if (hbMs == 0 && guardingStarted_) {
        // Life guarding: no guard request within guard time x life time factor (100Ch x 100Dh).
        const auto guard = int64_t(value(0x100C, 0).value_or(od::Value{}).toUInt64().value_or(0));
        const auto factor = int64_t(value(0x100D, 0).value_or(od::Value{}).toUInt64().value_or(0));
        if (guard > 0 && factor > 0 && nowNs - lastGuardNs_ > guard * factor * 1'000'000) {
            guardingStarted_ = false;
            heartbeat_->masterLost(0);  // life guarding event
        }
    }
    for (auto& d : drives_) d->step(dt > 0 && dt < 100'000'000 ? dt : 1'000'000);
    for (auto& m : motors_) m->step(dt > 0 && dt < 100'000'000 ? dt : 1'000'000);
    pdo_->tick(nowNs, nmtState_ == NmtState::Operational);
}

void VirtualDevice::sendHeartbeat() {
    transmit(CanFrame::classic(0x700u + nodeId_, {static_cast<uint8_t>(nmtState_)}));
}

void VirtualDevice::sendEmcy(uint16_t code, const uint8_t vendor[5]) {
    // EMCY is produced in PRE-OPERATIONAL and OPERATIONAL (CiA 301 §7.3.2, Table 60).
    if (nmtState_ != NmtState::Operational && nmtState_ != NmtState::PreOperational) return;
    const uint64_t cob =
        value(0x1014, 0).value_or(od::Value::unsignedInt(0x80u + nodeId_)).toUInt64().value_or(0x80u + nodeId_);
    if (cob & 0x80000000u) return;  // EMCY not valid
    const uint8_t reg = static_cast<uint8_t>(value(0x1001, 0).value_or(od::Value{}).toUInt64().value_or(0));
    CanFrame f = CanFrame::classic(static_cast<uint32_t>(cob & 0x7FF),
                                   {static_cast<uint8_t>(code), static_cast<uint8_t>(code >> 8), reg, vendor[0],
                                    vendor[1], vendor[2], vendor[3], vendor[4]});
    transmit(f);
}

void VirtualDevice::recordError(uint16_t code, uint16_t vendor) {
    if (auto* reg = valueSlot(0x1001, 0))
        *reg = od::Value::unsignedInt(reg->toUInt64().value_or(0) | errorRegisterFor(code));
    // Pre-defined error field 1003h: newest at sub 1, (vendor code << 16) | error code.
    if (auto* count = valueSlot(0x1003, 0)) {
        int max = 0;
        while (max < 254 && valueSlot(0x1003, static_cast<uint8_t>(max + 1))) ++max;
        if (max == 0) return;
        for (int s = max; s > 1; --s)
            *valueSlot(0x1003, static_cast<uint8_t>(s)) = *valueSlot(0x1003, static_cast<uint8_t>(s - 1));
        *valueSlot(0x1003, 1) = od::Value::unsignedInt((uint32_t(vendor) << 16) | code);
        *count = od::Value::unsignedInt(std::min<uint64_t>(count->toUInt64().value_or(0) + 1, uint64_t(max)));
    }
}

void VirtualDevice::injectDriveFault(DriveFault fault) {
    if (fault.emcyCode == 0) {
        fault.emcyCode = personality_.typicalFault.emcyCode;
        fault.alarmNumber = personality_.typicalFault.number;
    }
    const int axis = std::clamp(fault.axis, 0, std::max(0, personality_.axes - 1));
    uint8_t vendor[5] = {};
    if (personality_.alarmU8PerMotor) {
        vendor[3 + std::min(axis, 1)] = static_cast<uint8_t>(fault.alarmNumber);  // DEXMART: byte 6 M1, byte 7 M2
    } else {
        vendor[0] = static_cast<uint8_t>(fault.alarmNumber);  // bytes 3-4 u16le (Delta, AIMOTOR)
        vendor[1] = static_cast<uint8_t>(fault.alarmNumber >> 8);
    }
    recordError(fault.emcyCode, fault.alarmNumber);
    if (auto* e = valueSlot(static_cast<uint16_t>(0x603F + axis * 0x800), 0))
        *e = od::Value::unsignedInt(fault.emcyCode);
    if (axis < axisCount()) drives_[axis]->raiseFault(fault.emcyCode);
    if (axis < static_cast<int>(motors_.size())) motors_[axis]->raiseAlarm(static_cast<uint8_t>(fault.alarmNumber));
    sendEmcy(fault.emcyCode, vendor);
}

bool VirtualDevice::injectDriveFault(const QString& alarmName, int axis) {
    auto a = personality_.alarm(alarmName);
    if (!a) return false;
    injectDriveFault(DriveFault{a->emcyCode, a->number, axis});
    return true;
}

void VirtualDevice::faultCleared(int axis) {
    if (auto* e = valueSlot(static_cast<uint16_t>(0x603F + axis * 0x800), 0)) *e = od::Value::unsignedInt(0);
    bool anyFault = false;
    for (auto& d : drives_) anyFault |= d->faulted();
    for (auto& m : motors_) anyFault |= m->alarmed();
    if (anyFault) return;
    if (auto* reg = valueSlot(0x1001, 0)) *reg = od::Value::unsignedInt(0);
    const uint8_t none[5] = {};
    sendEmcy(0x0000, none);
}

Ds402Drive* VirtualDevice::drive(int axis) {
    return axis >= 0 && axis < axisCount() ? drives_[static_cast<size_t>(axis)].get() : nullptr;
}

DexmartMotor* VirtualDevice::motor(int m) {
    return m >= 0 && m < static_cast<int>(motors_.size()) ? motors_[static_cast<size_t>(m)].get() : nullptr;
}

}  // namespace coscope::sim
