// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/canopen/DriveDisable.h"
#include "core/canopen/HeartbeatGuard.h"

#include <QObject>
#include <QString>

#include <map>
#include <memory>
#include <utility>
#include <vector>

namespace coscope::canopen {

class EnabledDrives;
class HeartbeatProducer;
class MasterContext;
class SdoClient;

// The drives CoScope enabled on one bus, each watching CoScope's heartbeat (HeartbeatGuard:
// 1016h and 6007h) while it stays enabled, so that it stops by itself when CoScope dies or the
// cable is pulled (issue 35 "Safety edges"). Ties the bus's record of enabled drives
// (EnabledDrives) to one HeartbeatGuard per drive:
//  - poll() (a timer of the owner) sees a drive newly in the record and asks, once per node and
//    connection, for the user's consent (consentNeeded; the answer comes back as consent());
//  - with consent, CoScope's heartbeat (HeartbeatProducer) is started if it is not running and
//    the guard armed; a drive that leaves the record (disabled) gets its old values back, and
//    the heartbeat this service started stops once no guard is left;
//  - when the bus closes: takePutBack() before the SDO client goes, the drives disabled
//    (DriveDisable.h), then putBackDirect(), then the heartbeat stops, then the bus closes.
// Listen-only never transmits: no heartbeat, no guard (the drive's text says why). Lives on the SDO
// client's thread; writes through the guards, each reported to the send observer.
class GuardedDrives : public QObject {
    Q_OBJECT
public:
    enum class State {
        Undecided,
        Declined,
        Arming,
        Armed,
        Releasing,
        Released,
        Failed
    };  // Released: put back, then forgotten
    struct Drive {
        uint8_t node = 0;
        int axis = 0;
        State state = State::Undecided;
        QString text;  // what the guard did (its summary) or why it did not (its error)
    };
    // What to put back for one drive when the bus closes (HeartbeatGuard::putBackWrites()).
    struct PutBack {
        uint8_t node = 0;
        int axis = 0;
        std::vector<DirectDownload> writes;
    };

    GuardedDrives(MasterContext& context, SdoClient& sdo, HeartbeatProducer& heartbeat, QObject* parent = nullptr);
    ~GuardedDrives() override;  // writes nothing: takePutBack() and putBackDirect() first

    // CoScope's heartbeat when this service has to start it: node-ID and period (default 127,
    // 100 ms). A heartbeat already running is used as it is.
    void setHeartbeat(uint8_t node, uint16_t periodMs);
    // 6007h written (default quick stop).
    void setAbortOption(int16_t code) { abortOption_ = code; }
    void setSendObserver(std::function<void(const QString&)> observer) { onSend_ = std::move(observer); }

    // The period the heartbeat runs with, or will run with once started; the drive reacts
    // within the consumer time, 3 x that (HeartbeatGuard::consumerTimeFor()).
    uint16_t heartbeatPeriodMs() const;
    uint8_t heartbeatNode() const;

    // Compares the record with the guards: cheap, for a timer. Emits consentNeeded for a drive
    // newly enabled whose node has no answer yet this connection, arms one whose node was
    // answered yes, releases a guarded drive that left the record.
    void poll();
    // The user's answer for `node` (all its axes), kept for the connection.
    void consent(uint8_t node, bool yes);

    std::vector<Drive> drives() const;
    std::vector<uint8_t> guardedNodes() const;  // whose guard is armed (also one whose put-back failed)
    // A guard is armed or being armed or released: CoScope's heartbeat must go on.
    bool holdsHeartbeat() const;

    // The bus is about to close: no more arming or releasing. What each guard that changed
    // something would write to put the old values back; the guards forget they are armed.
    std::vector<PutBack> takePutBack();

signals:
    void consentNeeded(int node, int axis);
    // A drive's state changed (armed, put back, failed): drives() has its text.
    void changed(int node, int axis, coscope::canopen::GuardedDrives::State state, const QString& text);

private:
    struct Entry {
        State state = State::Undecided;
        QString text;
        std::unique_ptr<HeartbeatGuard> guard;
    };
    using Key = std::pair<uint8_t, int>;
    void arm(const Key& key);
    void release(const Key& key);
    void set(const Key& key, State state, const QString& text);
    void stopHeartbeatWhenFree();

    MasterContext& context_;
    SdoClient& sdo_;
    HeartbeatProducer& heartbeat_;
    uint8_t heartbeatNode_ = 127;
    uint16_t heartbeatMs_ = 100;
    int16_t abortOption_ = HeartbeatGuard::kQuickStop;
    std::function<void(const QString&)> onSend_;
    std::map<Key, Entry> entries_;
    std::map<uint8_t, bool> answers_;  // consent per node, this connection
    bool startedHeartbeat_ = false;
    bool closing_ = false;
};

// What putBackDirect() did for one drive.
struct PutBackOutcome {
    uint8_t node = 0;
    int axis = 0;
    bool putBack = false;    // the old 1016h (and 6007h) were written and confirmed
    bool keptArmed = false;  // not put back on purpose: the drive may still be enabled
    QString text;            // one line, English
};

// While the bus closes, after disableEnabledDrives(): the old 1016h/6007h values straight on
// the bus (SdoDirect.h) for every drive that is off - its Disable voltage confirmed, or it was
// disabled before. A drive whose Disable voltage was not confirmed keeps watching: when the
// heartbeat stops next, it stops by itself (the outcome says so). Blocks up to `timeoutMs`.
std::vector<PutBackOutcome> putBackDirect(MasterContext& context, std::vector<GuardedDrives::PutBack> putBack,
                                          const DriveDisableOutcome& disabled, int timeoutMs = 500);

}  // namespace coscope::canopen
