// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/can/CanFrame.h"

#include <array>
#include <cstdint>
#include <vector>

namespace coscope::sim {

class VirtualDevice;

// The PDO engine of a virtual device (CiA 301 §7.2.2), driven by the communication and mapping
// parameters in the device's dictionary (RPDO 1400h/1600h.., TPDO 1800h/1A00h.., up to 512 each).
// TPDO transmission types (§7.2.2.2 / 1800h sub 2): 0 synchronous acyclic (on SYNC after a change
// of the mapped data), 1-240 every n-th SYNC, 252 synchronous RTR-only, 253 asynchronous RTR-only,
// 254/255 event-driven (change of mapped data and the event timer sub 5, spaced by the inhibit
// time sub 3 in 100 µs). RPDOs of types 0-240 take effect at the next SYNC, 254/255 at once.
// The configuration is re-read when a 14xx..1Bxx entry changes.
// PDOs are exchanged only in OPERATIONAL (CiA 301 §7.3.2, NMT states and communication objects;
// extract-aimotor §3.1, extract-dexmart §3): RPDOs that arrive in another state are dropped, and
// synchronous RPDO data still waiting for a SYNC is discarded when the device leaves OPERATIONAL.
// An event-driven TPDO is sent once when the device enters OPERATIONAL and when it becomes
// valid again (COB-ID bit 31 cleared), then on change and on the event timer, which restarts at
// every transmission and is scheduled on the simulated clock (no drift across periods).
// The SYNC counter (CiA 301 §7.2.5) is processed only when the device's 1019h is 2..240: then
// the SYNC start value (1800h sub 6) picks the first SYNC of a cyclic TPDO; a SYNC whose length
// does not match 1019h raises EMCY 8240h (unexpected SYNC data length, CiA 301 Table 21).
// DEXMART's type FEh TPDO answers the RPDO of the same number instead (Personality).
class PdoEngine {
public:
    explicit PdoEngine(VirtualDevice& device);

    void invalidate() { dirty_ = true; }
    void reset();  // NMT reset communication
    // The device's NMT state changed (entering or leaving OPERATIONAL matters).
    void nmtStateChanged(bool operational, int64_t nowNs);
    // Returns true when the frame was a PDO/SYNC this engine consumed.
    bool onFrame(const CanFrame& frame, int64_t nowNs, bool operational);
    void tick(int64_t nowNs, bool operational);
    // Checks a mapping entry written to 16xx/1Axx (returns 0 or the abort code).
    uint32_t checkMappingEntry(bool tpdo, uint32_t entry) const;
    uint32_t checkMappingCount(uint16_t mappingIndex, uint8_t count) const;

private:
    struct Mapped {
        uint16_t index;
        uint8_t sub;
        uint8_t bits;
        bool operator==(const Mapped&) const = default;
    };
    struct Pdo {
        uint16_t commIndex = 0;
        uint32_t cobId = 0;
        bool valid = false;
        bool rtrAllowed = true;
        uint8_t type = 0;
        uint32_t inhibitNs = 0;
        uint32_t eventMs = 0;
        uint8_t syncStart = 0;
        std::vector<Mapped> map;
        int bytes = 0;
        // state
        int syncCount = 0;
        int64_t lastTxNs = -1;
        int64_t nextEventNs = 0;
        bool timerDue = false;  // the pending send comes from the event timer
        bool pending = false;   // event-driven: a send is due once the inhibit time allows
        bool rtrRequested = false;
        std::array<uint8_t, 8> lastData{};
        bool haveLast = false;
        std::array<uint8_t, 8> latched{};  // type 252: sampled at SYNC
        bool latchedValid = false;
        // RPDO: data waiting for SYNC
        std::array<uint8_t, 8> rxData{};
        int rxLen = -1;
    };

    void reload();
    void readPdo(Pdo& p, uint16_t comm, uint16_t mapping, bool tpdo);
    int encode(const Pdo& p, uint8_t* out) const;
    void apply(const Pdo& p, const uint8_t* data, int len);
    void sendTpdo(Pdo& p, const uint8_t* data, int len, int64_t nowNs);
    void onSync(int64_t nowNs, int counter);
    void enterOperational(int64_t nowNs);
    void leaveOperational();
    // Synchronous counter overflow value 1019h (0 when the device has no 1019h).
    int syncOverflow() const;

    VirtualDevice& dev_;
    bool dirty_ = true;
    bool operational_ = false;
    std::vector<Pdo> tpdos_;
    std::vector<Pdo> rpdos_;
    uint32_t syncCobId_ = 0x80;
};

}  // namespace coscope::sim
