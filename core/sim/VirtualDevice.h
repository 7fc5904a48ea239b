// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/canopen/Nmt.h"
#include "core/od/ObjectDictionary.h"
#include "core/od/Value.h"
#include "core/sim/LssFaults.h"
#include "core/sim/Personality.h"
#include "core/sim/SdoFaults.h"
#include "core/sim/SimNode.h"

#include <QString>

#include <cstdint>
#include <memory>
#include <optional>
#include <unordered_map>
#include <vector>

namespace coscope::sim {

class SdoServer;
class PdoEngine;
class LssSlave;
class HeartbeatConsumer;
class Ds402Drive;
class DexmartMotor;
class ProgramFlash;

// A fault injected into a drive: EMCY error code (also put in 603Fh) and vendor alarm number
// (EMCY manufacturer bytes per the vendor's layout). axis: 0 = first axis/motor M1, 1 = M2.
struct DriveFault {
    uint16_t emcyCode = 0;
    uint16_t alarmNumber = 0;
    int axis = 0;
};

// A virtual CANopen device built from an object dictionary and a vendor personality:
// SDO server (expedited, segmented, block; CiA 301 §7.2.4), NMT slave with boot-up, heartbeat
// producer, heartbeat consumer (HeartbeatConsumer) and node guarding (§7.2.8), SYNC consumer and PDO engine driven by the mapping in
// its dictionary (§7.2.2), EMCY producer (§7.2.7), LSS slave (CiA 305), store/restore
// (1010h/1011h, §7.5.2.13-14) and, for CiA 402 personalities, the drive model (Ds402Drive).
//
// Everything runs on the network thread. Tests reach a device with
// network->runOnNetworkThread([&]{ network->device(1)->... }).
//
// Documented simulator conventions:
//  - kTestDomainIndex (5FFFh:00) is a read-write DOMAIN of kTestDomainSize (64 KiB) bytes,
//    added to every device whose dictionary has no such object, for SDO transfer tests and
//    benchmarks. Its content is byte i = i & 0xFF until written.
//  - The device's CAN controller runs at bitRate() (bit/s): the network passes frames only
//    between participants at the same rate. A rate configured through LSS or a vendor parameter
//    (canopen::vendorNodeSettings) takes effect on activate bit timing / reset / power cycle.
//  - Node-ID changes (LSS configure + store, Delta P3-00, AIMOTOR H0C-00, DEXMART 09-19) are
//    pending until NMT Reset Node or Reset Communication (LSS) / Reset Node or power cycle
//    (vendor parameter; the manuals ask for a power cycle, the sim also accepts Reset Node).
//    A vendor parameter survives a power cycle when the vendor saves it on write or after a
//    1010h "save". A node that was LSS-unconfigured boots with its new node-ID when switched
//    back to LSS waiting state (CiA 305 §6.3.2).
//  - Program download (CiA 302-3): 1F50h/1F51h/1F56h/1F57h and 100Ah as ProgramFlash.h says,
//    with the image format of ProgramImage.h; a started program resets the node.
//  - 1018h:04 serial number is 0 in the bundled dictionaries; a virtual device uses
//    0x51000000 + its first node-ID so LSS can tell devices apart.
class VirtualDevice : public SimNode {
public:
    static constexpr uint16_t kTestDomainIndex = 0x5FFF;
    static constexpr int kTestDomainSize = 64 * 1024;

    // Builds a device from a dictionary loaded through sim::loadDictionary(dictionaryName).
    static std::unique_ptr<VirtualDevice> create(uint8_t nodeId, const QString& dictionaryName, QString* error);
    VirtualDevice(uint8_t nodeId, od::ObjectDictionary dictionary, Personality personality);
    ~VirtualDevice() override;

    // --- SimNode
    uint8_t nodeId() const override { return nodeId_; }
    void powerOn(int64_t nowNs) override;
    void onFrame(const CanFrame& frame, int64_t nowNs) override;
    void tick(int64_t nowNs) override;

    // --- identity and state
    const QString& dictionaryName() const { return personality_.dictionaryName; }
    const Personality& personality() const { return personality_; }
    canopen::NmtState nmtState() const { return nmtState_; }
    bool lssConfigured() const { return nodeId_ != 0xFF; }
    // Node-ID that becomes active at the next reset (== nodeId() when nothing is pending).
    uint8_t pendingNodeId() const { return pendingNodeId_; }
    // Configured bit rate in bit/s (see class comment).
    uint32_t bitRate() const override { return bitRate_; }
    uint32_t pendingBitRate() const { return pendingBitRate_; }
    // Power cycle: stored values and stored node-ID/bit rate come back, boot-up is sent.
    void powerCycle();
    // Makes the device an LSS-unconfigured node (node-ID FFh): silent except for LSS.
    void makeUnconfigured();

    // --- object dictionary
    od::ObjectDictionary& dictionary() { return dictionary_; }
    const od::ObjectDictionary& dictionary() const { return dictionary_; }
    // Current value of an entry; nullopt if the entry does not exist.
    std::optional<od::Value> value(uint16_t index, uint8_t sub) const;
    // Sets an entry's value locally (no access check, no SDO): like the device's own firmware
    // changing it. Runs the same side effects as an SDO write. False if the entry is missing
    // or the value does not fit its type (*error says why).
    bool setValue(uint16_t index, uint8_t sub, const od::Value& value, QString* error = nullptr);
    // The value an SDO upload sends, encoded. nullopt + abort code when refused.
    std::optional<QByteArray> readForSdo(uint16_t index, uint8_t sub, uint32_t* abortCode);
    // Writes bytes from an SDO download with every CiA 301 check (exists, access, length, limits,
    // PDO rules, store/restore signatures). Returns 0 or the abort code.
    uint32_t writeFromSdo(uint16_t index, uint8_t sub, const QByteArray& bytes);

    // --- fault injection (tests)
    SdoFaults& sdoFaults() { return sdoFaults_; }
    LssFaults& lssFaults() { return lssFaults_; }
    // Raises a vendor alarm: EMCY with the vendor's layout, 603Fh, 1001h, 1003h history and the
    // statusword fault bit (the drive goes through fault reaction to FAULT). A default DriveFault
    // raises the personality's typical fault.
    void injectDriveFault(DriveFault fault = {});
    // The same by vendor alarm name ("AL011" for Delta); false if the name is not known.
    bool injectDriveFault(const QString& alarmName, int axis = 0);
    // Sends an EMCY frame (error code, register 1001h, manufacturer bytes).
    void sendEmcy(uint16_t code, const uint8_t vendor[5]);
    // Called by the drive model when a fault reset cleared the fault of `axis`: clears 603Fh and
    // 1001h and sends the error-reset EMCY (code 0000h, CiA 301 §7.2.7.1).
    void faultCleared(int axis);

    // CiA 402 axis (nullptr for non-402 devices / axis out of range).
    Ds402Drive* drive(int axis = 0);
    int axisCount() const { return static_cast<int>(drives_.size()); }
    // DEXMART DEV motor M1 (0) / M2 (1) driven by the Multi-Drive objects (nullptr otherwise).
    DexmartMotor* motor(int m);

    // The program download objects (CiA 302-3) and the running program.
    ProgramFlash& programFlash() { return *program_; }

    uint32_t serialNumber() const { return serial_; }
    // Another serial number in 1018h:04 (a drive of the same type that replaced this one).
    void setSerialNumber(uint32_t serial);
    HeartbeatConsumer& heartbeatConsumer() { return *heartbeat_; }

    // Counters for tests.
    uint64_t sdoRequests() const { return sdoRequests_; }

    // Internal, used by the SDO server / PDO engine / LSS slave / drive model.
    void send(const CanFrame& frame) { transmit(frame); }
    int64_t now() const { return nowNs_; }
    // Fast access for the PDO engine and the drive model (nullptr if missing).
    od::Value* valueSlot(uint16_t index, uint8_t sub);
    const od::SubObject* entry(uint16_t index, uint8_t sub) const { return dictionary_.entry(index, sub); }

private:
    friend class LssSlave;
    friend class HeartbeatConsumer;
    static uint32_t key(uint16_t index, uint8_t sub) { return (uint32_t(index) << 8) | sub; }
    void loadDefaults(bool communicationOnly);  // factory values for nodeId_
    void applyStored(bool communicationOnly);
    void resetCommunication(int64_t nowNs);
    void resetNode(int64_t nowNs);
    void bootUp(int64_t nowNs);
    void setNmtState(canopen::NmtState s);
    void handleNmt(const CanFrame& f, int64_t nowNs);
    void handleGuarding(int64_t nowNs);
    void afterWrite(uint16_t index, uint8_t sub);
    uint32_t checkSpecialWrite(uint16_t index, uint8_t sub, const od::Value& v);
    void sendHeartbeat();
    void addTestDomain();
    void recordError(uint16_t code, uint16_t vendor);

    uint8_t nodeId_;
    uint8_t pendingNodeId_;
    uint8_t storedNodeId_;
    bool pendingFromLss_ = false;  // pending node-ID also applies on Reset Communication
    uint32_t bitRate_ = 500000;
    uint32_t pendingBitRate_ = 500000;
    uint32_t storedBitRate_ = 500000;
    uint32_t serial_ = 0;
    od::ObjectDictionary dictionary_;
    Personality personality_;
    std::unordered_map<uint32_t, od::Value> values_;
    std::unordered_map<uint32_t, od::Value> stored_;  // saved with 1010h (survive resets)
    canopen::NmtState nmtState_ = canopen::NmtState::BootUp;
    bool powered_ = false;
    int64_t nowNs_ = 0;
    int64_t nextHeartbeatNs_ = 0;
    int64_t lastGuardNs_ = 0;
    bool guardToggle_ = false;
    bool guardingStarted_ = false;
    SdoFaults sdoFaults_;
    LssFaults lssFaults_;
    uint64_t sdoRequests_ = 0;
    std::unique_ptr<SdoServer> sdo_;
    std::unique_ptr<PdoEngine> pdo_;
    std::unique_ptr<LssSlave> lss_;
    std::unique_ptr<HeartbeatConsumer> heartbeat_;  // 1016h
    std::unique_ptr<ProgramFlash> program_;         // 1F50h-1F57h
    std::vector<std::unique_ptr<Ds402Drive>> drives_;
    std::vector<std::unique_ptr<DexmartMotor>> motors_;
};

}  // namespace coscope::sim
