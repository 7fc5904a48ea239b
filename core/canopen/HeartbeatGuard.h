// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/canopen/HeartbeatProducer.h"
#include "core/canopen/SdoClient.h"
#include "core/canopen/SdoDirect.h"

#include <QObject>
#include <QString>

#include <functional>
#include <memory>
#include <optional>
#include <vector>

namespace coscope::canopen {

// Outcome of arming or releasing a HeartbeatGuard.
struct HeartbeatGuardResult {
    bool ok = false;
    QString error;                       // one line; "nothing changed" or what was put back when arming failed
    QString summary;                     // what the node now does when CoScope's heartbeat stops (or was put back)
    uint8_t consumerSub = 0;             // the 1016h sub-index used
    uint32_t consumerEntry = 0;          // the value written there (node-ID << 16 | time ms)
    std::optional<int16_t> abortOption;  // 6007h written; nullopt when the node has none
};
using HeartbeatGuardCallback = std::function<void(const HeartbeatGuardResult&)>;

// Makes a drive stop by itself when CoScope can no longer send (the app dies, the cable is
// pulled): the node's heartbeat consumer (1016h, CiA 301 §7.5.2.18: bits 16..23 producer node-ID,
// bits 0..15 time in ms) watches CoScope's own heartbeat (HeartbeatProducer), and its abort
// connection option code (6007h, CiA 402-2: 0 no action, 1 fault signal, 2 disable voltage,
// 3 quick stop) says what the drive does when that heartbeat stops.
//
// arm() reads 1016h (all entries) and 6007h, then writes 6007h (quick stop unless told otherwise)
// and one 1016h entry for CoScope's node-ID: the one already watching that node-ID, else a free
// one (time 0 or no node-ID); time = 3 x the heartbeat period unless set. The old values are
// kept; release() puts them back (the 1016h entry first, so the drive stops watching before its
// reaction changes). Release before stopping the heartbeat, or the drive reacts to the stop.
//
// A node without 1016h (DEXMART DEV, extract-dexmart §2.5) cannot watch: arm() fails and writes
// nothing. A node without 6007h (Delta ASDA-A2, AIMOTOR) is armed with 1016h only and reacts as
// its maker defines (the summary says how where the manual tells: Delta AL170, AIMOTOR Er.D03).
// If a write fails while arming, what was already written is put back.
//
// Lives on the SDO client's thread and never blocks it; every SDO write is reported through the
// send observer first. One guard per node (1016h is the node's, 6007h the axis's).
class HeartbeatGuard : public QObject {
    Q_OBJECT
public:
    static constexpr int16_t kQuickStop = 3;

    HeartbeatGuard(SdoClient& sdo, uint8_t node, int axis = 0, QObject* parent = nullptr);
    ~HeartbeatGuard() override;  // writes nothing: release() first

    // 6007h to write (default 3, quick stop).
    void setAbortOption(int16_t code) { abortOption_ = code; }
    int16_t abortOption() const { return abortOption_; }
    // Consumer heartbeat time in ms; 0 (default) = 3 x the producer's period.
    void setConsumerTimeMs(uint16_t ms) { consumerTimeMs_ = ms; }
    void setSendObserver(std::function<void(const QString&)> observer) { onSend_ = std::move(observer); }

    uint8_t node() const { return node_; }
    int axis() const { return axis_; }
    bool armed() const { return armed_; }
    bool busy() const { return busy_; }

    // `producer` must be running (its node-ID and period are used). Fails at once (through
    // `done`, later) when busy, already armed, or the producer is stopped.
    void arm(const HeartbeatProducer& producer, HeartbeatGuardCallback done);
    // Puts the old values back; ok at once when not armed. On a failed write the guard stays
    // armed (release() may be called again; nothing is retried by itself).
    void release(HeartbeatGuardCallback done);

    // What release() writes, for putting the old values back straight on the bus while it closes
    // (SdoDirect.h, GuardedDrives): the 1016h entry first, then 6007h. Also while arming, once
    // the old values are read (writing them back is harmless if the new ones never went out).
    // Empty when nothing was or is being changed.
    std::vector<DirectDownload> putBackWrites() const;
    // The old values were put back by other means (putBackWrites() confirmed): no longer armed.
    void markPutBack() { armed_ = changing_ = false; }

    // "quick stop" for 3, and so on (CiA 402-2 6007h value names).
    static QString abortOptionName(int16_t code);
    // The consumer time used for a producer period (3 x, at most 65535 ms); 0 when it does not fit.
    static uint16_t consumerTimeFor(uint16_t periodMs);

private:
    struct Arming;
    void readEntries(std::shared_ptr<Arming> a, uint8_t sub);
    void readAbortOption(std::shared_ptr<Arming> a);
    void writeAll(std::shared_ptr<Arming> a);
    void write(uint16_t index, uint8_t sub, const QByteArray& data, const QString& what, SdoCallback then);
    void finish(const HeartbeatGuardCallback& done, HeartbeatGuardResult r);
    QString prefix() const;
    uint16_t abortIndex() const { return static_cast<uint16_t>(0x6007 + axis_ * 0x800); }

    SdoClient& sdo_;
    uint8_t node_;
    int axis_;
    int16_t abortOption_ = kQuickStop;
    uint16_t consumerTimeMs_ = 0;
    std::function<void(const QString&)> onSend_;
    bool busy_ = false;
    bool armed_ = false;
    bool changing_ = false;  // arming's writes are under way (the old values below are known)
    // What arm() changed, for release().
    uint8_t sub_ = 0;
    uint32_t oldEntry_ = 0;
    uint32_t newEntry_ = 0;
    std::optional<int16_t> oldAbortOption_;  // nullopt: the node has no 6007h
};

}  // namespace coscope::canopen
