// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstdint>
#include <map>

namespace coscope::sim {

class VirtualDevice;

// The heartbeat consumer of a virtual device (CiA 301 §7.2.8.3.2.2, object 1016h) and what the
// device does when it loses its master, by a heartbeat event or a life guarding event:
//  - 1016h:n = bits 16..23 producer node-ID, bits 0..15 consumer time in ms (0 = entry unused,
//    §7.5.2.18). The time runs from the first heartbeat received from that producer; when no
//    heartbeat follows within it, a heartbeat event: once, then monitoring waits for the next
//    heartbeat. Two entries for one node-ID with a time are refused (abort 06040043h).
//  - The event: EMCY 8130h "life guard error or heartbeat error" (CiA 301 Table 21), 1001h
//    communication bit, then the NMT reaction of 1029h:01 (§7.5.2.32: 0 pre-operational when
//    operational, 1 no change, 2 stopped), then each CiA 402 axis reacts:
//      * Delta ASDA-A2: alarm AL170 with the servo on, AL180 with it off (EMCY 8130h, alarm
//        0170h/0180h; extract-delta §1 and §6.3); the drive has no 6007h.
//      * AIMOTOR: alarm Er.D03 "CAN communication interrupted" (0D03h, EMCY 8130h;
//        extract-aimotor §3.2 and resources/alarms/aimotor.json); no 6007h.
//      * A drive with 6007h (generic CiA 402): its abort connection option code (CiA 402-2
//        §6.5.1): 0 no action, 1 fault signal (fault, 603Fh = 8130h), 2 disable voltage,
//        3 quick stop; negative codes are the maker's (no action here).
// Runs on the network thread, as the device does.
class HeartbeatConsumer {
public:
    explicit HeartbeatConsumer(VirtualDevice& device);

    // Boot-up / reset: every entry waits for a first heartbeat again.
    void reset();
    // A frame on 700h + producer (heartbeat, boot-up or guarding reply of another node).
    void onHeartbeat(uint8_t producer, int64_t nowNs);
    // Once per millisecond: raises a heartbeat event for an entry whose time ran out.
    void tick(int64_t nowNs);
    // SDO write of 1016h:sub: 0 or the abort code.
    uint32_t checkWrite(uint8_t sub, uint32_t value) const;

    // The master is lost: `producer` timed out (heartbeat event) or 0 (life guarding event).
    void masterLost(uint8_t producer);
    // Heartbeat and life guarding events so far (tests).
    uint64_t events() const { return events_; }

private:
    struct Watch {
        uint32_t armedWith = 0;  // the 1016h value the watch started with
        int64_t lastNs = 0;      // last heartbeat of the producer
    };
    uint32_t entry(uint8_t sub) const;
    int64_t abortOption(int axis) const;  // 6007h of the axis, 0 when absent
    void reactOnAxes();

    VirtualDevice& dev_;
    std::map<uint8_t, Watch> watching_;  // by 1016h sub-index, only entries that saw a heartbeat
    uint64_t events_ = 0;
};

}  // namespace coscope::sim
