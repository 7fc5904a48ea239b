// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/canopen/MasterContext.h"
#include "core/canopen/PeriodicSender.h"

#include <QObject>

#include <functional>

namespace coscope::canopen {

class SdoClient;
struct SdoResult;

// SYNC producer (CiA 301 §7.2.5): a SYNC frame every communication cycle period on the COB-ID of
// 1005h (default 80h), with an optional counter 1..overflow (1019h synchronous counter overflow
// value, §7.5.2.22: 0 = no counter, DLC 0; 2..240 = one data byte counting 1..value, then 1
// again). Sent by the bus's PeriodicSender (its own thread, µs resolution), so the period is kept
// whatever the GUI thread does.
//
// Thread-safety: configure, start and stop from one thread (the owner's); sent(), isRunning() and
// lastError() may be polled from that thread at any rate.
class SyncProducer : public QObject {
    Q_OBJECT
public:
    // Uses the bus's scheduler, context.periodic().
    explicit SyncProducer(MasterContext& context, QObject* parent = nullptr);
    ~SyncProducer() override;  // stops

    // 1005h value: bits 0..10 the 11-bit CAN-ID, or with bit 29 (frame) set bits 0..28 a 29-bit
    // CAN-ID; bits 30 (gen) and 31 are ignored. False (nothing changed) when bits 11..28 are set
    // without bit 29. While running, the next frames use the new COB-ID.
    bool setCobId(uint32_t cobId1005h);
    uint32_t cobId() const { return cobId_; }  // as 1005h: with bit 29 for a 29-bit CAN-ID

    // Communication cycle period in µs (1006h). While running, applied from the next frame on.
    void setPeriodUs(uint32_t us);
    uint32_t periodUs() const { return periodUs_; }

    // 0 = no counter; 2..240 otherwise (CiA 301 §7.5.2.22). False for other values. While
    // running, the counter restarts at 1 with the next frame.
    bool setCounterOverflow(uint8_t overflow);
    uint8_t counterOverflow() const { return overflow_; }

    // Starts sending: the first SYNC at once (counter 1), `count` frames in all (0 = until
    // stopped). False with *error when the period is 0 or the first frame was refused
    // (listen-only bus, bus not open). Restarts when running.
    bool start(QString* error = nullptr, uint64_t count = 0);
    void stop();
    bool isRunning() const;
    // SYNC frames sent since construction (all runs).
    uint64_t sent() const;
    // Why the last run stopped by itself (a send failed); empty otherwise.
    QString lastError() const;

    // Runs `hook` on the sender thread right after each SYNC went out (things sent "with each
    // SYNC": synchronous RPDOs of the process data panel); empty = none. May be set at any time
    // from the owner's thread; the hook must not block on that thread.
    void setOnEachSync(PeriodicSender::AfterSend hook);

    // The frame sent as SYNC with the given counter value (0 = no counter byte): for tests and
    // for showing what will be sent.
    CanFrame frame(uint8_t counter) const;

    // Writes the period to a node's 1006h (communication cycle period, µs) when asked.
    void writeCommunicationCyclePeriod(SdoClient& sdo, uint8_t node, std::function<void(const SdoResult&)> done) const;

signals:
    // Emitted on this object's thread when a run stopped because a send failed.
    void stoppedOnError(const QString& message);

private:
    void stopJob();
    struct Shared;

    MasterContext& context_;
    PeriodicSender::JobId job_ = 0;
    std::shared_ptr<Shared> shared_;  // read by the maker on the sender thread
    uint32_t cobId_ = 0x80;
    uint32_t periodUs_ = 0;
    uint8_t overflow_ = 0;
    uint64_t sentBefore_ = 0;  // frames of finished runs
    QString lastError_;        // of the last finished run
};

}  // namespace coscope::canopen
