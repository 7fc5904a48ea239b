// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/canopen/CommandScript.h"
#include "core/canopen/Ds402.h"
#include "core/canopen/SdoClient.h"

#include <QElapsedTimer>
#include <QObject>
#include <QString>

#include <functional>
#include <memory>
#include <optional>
#include <vector>

class QTimer;

namespace coscope::canopen {

// Outcome of a CiA 402 request.
struct Ds402Result {
    bool ok = false;
    uint16_t statusword = 0;
    ds402::State state = ds402::State::Unknown;
    int8_t mode = 0;                              // setMode: 6061h read back
    QString error;                                // one line: what failed and, for a transition, the missing bits
    ds402::State target = ds402::State::Unknown;  // transition: the state that was waited for
    QString advice;                               // failed transition: what the wrong bits mean, in plain words
    QString stopReason;                           // test move: why it stopped ("button released", "time limit", ...)
};
using Ds402Callback = std::function<void(const Ds402Result&)>;

// A short test move with small limits, for checking wiring and direction on a hold-to-run
// control. Jog: profile velocity (6060h = 3, target velocity 60FFh, CiA 402-2 §14). Relative:
// profile position (6060h = 1, 607Ah relative to the current target, bit 6 of 6040h, §12).
// Acceleration 6083h and deceleration 6084h are written first. The move stops by itself when
// the watchdog is not fed, after maxDurationMs, or when the drive stops answering.
struct Ds402TestMove {
    enum class Kind : uint8_t { Jog, Relative };
    Kind kind = Kind::Jog;
    int32_t velocity = 1000;        // jog: 60FFh (signed); relative: 6081h profile velocity (magnitude)
    int32_t distance = 0;           // relative: 607Ah, position units (signed)
    uint32_t acceleration = 10000;  // 6083h
    uint32_t deceleration = 10000;  // 6084h
    int maxDurationMs = 3000;
    int watchdogMs = 400;  // stop when feedWatchdog() was not called for this long

    // Limits of a test move (velocity/position units of the drive; conservative for commissioning).
    static constexpr int32_t kMaxVelocity = 200000;
    static constexpr int32_t kMaxDistance = 1000000;
    static constexpr int kMaxDurationMs = 30000;
    // Empty when the move is within the limits, else why not.
    QString check() const;
};

// One sample of a running test move (statusword, 6064h position actual, 606Ch velocity actual).
struct Ds402MotionSample {
    qint64 ms = 0;  // since the move started
    uint16_t statusword = 0;
    int32_t position = 0;
    int32_t velocity = 0;
};

// Homing (CiA 402-2 §13; Delta extract §4.5.3, AIMOTOR extract §4.6 C): what home() writes.
// Unset values are left as the drive has them. Units are the drive's (Delta: 6099h in 0.1 rpm,
// 609Ah in ms from 0 to 3000 rpm; AIMOTOR: pulse/s, pulse/s²). canopen::homing lists the
// methods of each drive.
struct Ds402HomingRequest {
    int8_t method = 35;                    // 6098h
    std::optional<uint32_t> fastSpeed;     // 6099h:01 speed during search for switch
    std::optional<uint32_t> slowSpeed;     // 6099h:02 speed during search for zero
    std::optional<uint32_t> acceleration;  // 609Ah homing acceleration
    std::optional<int32_t> offset;         // 607Ch home offset
    // The drive takes a new 6098h only while not in Operation enabled (AIMOTOR): when it is
    // enabled and the method differs, home() sends Shutdown first (homing::DriveHoming).
    bool methodOnlyWhileDisabled = false;
    int timeoutMs = 60000;  // homing attained or error within this
};

// A profile position move (CiA 402-2 §12): what moveTo() writes and how it sets the set-point.
struct Ds402PositionMove {
    int32_t target = 0;                    // 607Ah
    bool relative = false;                 // controlword bit 6
    bool immediate = false;                // bit 5 change set immediately
    std::optional<uint32_t> velocity;      // 6081h profile velocity
    std::optional<uint32_t> acceleration;  // 6083h
    std::optional<uint32_t> deceleration;  // 6084h
    int timeoutMs = 60000;                 // target reached within this
};

// CiA 402 controller over SDO (CiA 402-2 §6.2): reads the state from 6041h, performs the
// state-machine transitions by writing 6040h and waits for the statusword they lead to, sets
// the mode of operation (6060h) and verifies it in 6061h. Axis n of a multi-axis device uses
// the objects at +n*800h (CiA 402-2 §5.2). Never blocks its thread.
//
// Safety: an enable sequence that fails at any step ends with Disable voltage (6040h = 0), so
// the drive is left disabled. Every controlword written is reported through onSend first.
class Ds402Controller : public QObject {
    Q_OBJECT
public:
    Ds402Controller(SdoClient& sdo, uint8_t node, int axis = 0, QObject* parent = nullptr);

    void setTimeout(int ms) { timeoutMs_ = ms > 0 ? ms : 1000; }
    void setPollInterval(int ms) { pollMs_ = ms > 0 ? ms : 10; }
    // Called before each write with a line saying what goes out ("6040h = 0x0006 (Shutdown)").
    void setSendObserver(std::function<void(const QString&)> observer) { onSend_ = std::move(observer); }

    uint16_t objectIndex(uint16_t base) const { return static_cast<uint16_t>(base + axis_ * 0x800); }

    void readState(Ds402Callback done);
    // One transition: writes its controlword and waits for the state it leads to. FaultReset
    // writes bit 7 low then high (a rising edge) and waits for Switch on disabled.
    void transition(ds402::Command command, Ds402Callback done);
    // From any state to Operation enabled (fault reset first when in Fault). On failure the
    // drive is sent Disable voltage.
    void enable(Ds402Callback done);
    // To Switch on disabled: Shutdown (when operating) then Disable voltage.
    void disable(Ds402Callback done);
    void setMode(int8_t mode, Ds402Callback done);
    // Quick stop (6040h = 0002h): the drive brakes on its quick stop ramp and ends in Quick stop
    // active or Switch on disabled (605Ah).
    void quickStop(Ds402Callback done);
    // Disable voltage (6040h = 0000h) at once, whatever the state (no read first), then reads
    // the state back. The safe way out after a failure.
    void disableVoltage(Ds402Callback done);

    // Test move (see Ds402TestMove). False + *why when refused before anything is sent (limits,
    // one already running). The drive must be in Operation enabled, else `done` reports it.
    // `sample` gets each monitoring read (about every 50 ms); `done` runs once, after the drive
    // was stopped (ok, stopReason) or, on a fault or a silent drive, disabled (not ok).
    bool startTestMove(const Ds402TestMove& spec, std::function<void(const Ds402MotionSample&)> sample,
                       Ds402Callback done, QString* why = nullptr);
    // The hold-to-run control is still held.
    void feedWatchdog();
    // Stops a running test move (halt, target velocity 0) and waits until it stands still.
    void stopTestMove(const QString& reason);
    bool testMoveActive() const { return move_ != nullptr; }

    // Homing (Ds402Homing.cpp): 6060h = 6 verified in 6061h, the request's objects, Operation
    // enabled (enable() when not), then 6040h 0Fh -> 1Fh; waits for homing attained (statusword
    // bit 12 with target reached, bit 10) or homing error (bit 13) and ends with bit 4 low
    // (0Fh): the drive stays enabled and homed. `progress` gets each monitoring read (about every
    // 50 ms). A homing error, a fault, the drive leaving Operation enabled, silence or the
    // timeout end with Quick stop and Disable voltage (not ok).
    void home(const Ds402HomingRequest& request, std::function<void(const Ds402MotionSample&)> progress,
              Ds402Callback done);
    // Profile position move (Ds402ProfileMove.cpp): 6060h = 1 verified, 6081h/6083h/6084h and
    // 607Ah, Operation enabled, then the set-point handshake (bit 4 rising with bits 5/6, wait
    // for set-point acknowledge bit 12, bit 4 low) and target reached (bit 10). Failures as home().
    void moveTo(const Ds402PositionMove& move, std::function<void(const Ds402MotionSample&)> progress,
                Ds402Callback done);
    // Stops a running home()/moveTo() at any time (Ds402Motion.cpp): halt (6040h = 010Fh: bit 8,
    // bit 4 low, which also interrupts homing) and waits until it stands still, or Quick stop
    // (0002h). `done` of the motion then reports not ok with stopReason = `reason`.
    void stopMotion(bool quickStop, const QString& reason);
    bool motionActive() const { return motion_ != nullptr; }

    // The steps enable() sends from state `from` (and the mode set first when given), for the
    // dry run: 6040h writes, each followed by the statusword 6041h it must lead to.
    static CommandScript enableScript(uint8_t node, int axis, ds402::State from,
                                      std::optional<int8_t> mode = std::nullopt);
    // The steps of one transition (for the dry run of a single button).
    static std::vector<ScriptStep> transitionSteps(uint8_t node, int axis, ds402::Command command);

    // The statusword mask/value a state shows (CiA 402-2 Table 30).
    static bool expectedStatusword(ds402::State s, uint16_t* mask, uint16_t* value);
    // "missing bit 2 (operation enabled)" / "unexpected bit 6 (switch on disabled)" for the bits
    // where `sw` differs from what `s` needs.
    static QString describeMismatch(ds402::State s, uint16_t sw);
    // The same in plain words for a technician, one sentence per bit, e.g. "Voltage enabled
    // (bit 4) is off: main power is not on". Also names voltage enabled (for Switched on and
    // beyond) and remote, which Table 30 does not use for the state.
    static QString explainMismatch(ds402::State s, uint16_t sw);

private:
    struct Step {
        ds402::Command command;
        ds402::State target;
    };
    void runSteps(std::shared_ptr<std::vector<Step>> steps, size_t i, bool disableOnFailure, Ds402Callback done);
    void writeControlword(uint16_t cw, const QString& why, std::function<void(const SdoResult&)> then);
    void waitForState(ds402::State target, ds402::State alternative, QElapsedTimer started, Ds402Callback done);
    void failSafe(Ds402Result r, Ds402Callback done);
    QString prefix() const;
    struct Move;
    void moveMonitor();
    void moveStopped(Ds402Result r);
    void moveFail(const QString& error);
    // home()/moveTo() (Ds402Motion.cpp): a chain of steps, each calling its continuation with
    // an empty text when it went well, else the error.
    struct Motion;
    using MotionStep = std::function<void(std::function<void(const QString&)>)>;
    using MotionSteps = std::shared_ptr<std::vector<MotionStep>>;
    // `check` decides after each monitoring read: empty = go on, "ok" = finished (then `finish`
    // runs, e.g. bit 4 low), else the error. nullptr when refused (`done` was called).
    std::shared_ptr<Motion> beginMotion(bool homing, int timeoutMs,
                                        std::function<void(const Ds402MotionSample&)> progress, Ds402Callback done,
                                        std::function<QString(const Ds402MotionSample&)> check, MotionStep finish);
    MotionStep writeStep(uint16_t base, uint8_t sub, QByteArray data, const QString& what);
    MotionStep controlwordStep(uint16_t cw, const QString& why);
    MotionStep modeStep(int8_t mode);
    MotionStep enableStep();
    // `liveFrom`: the step that starts the motion (bit 4 rising); a stop asked for after it
    // halts the drive and waits as during the motion (the set-point may already be moving it).
    void motionSteps(std::shared_ptr<Motion> m, MotionSteps steps, size_t i, size_t liveFrom);
    void motionMonitor(std::shared_ptr<Motion> m);
    void motionStopped(std::shared_ptr<Motion> m, const QString& why);
    void motionEnd(std::shared_ptr<Motion> m, Ds402Result r);
    void motionFail(std::shared_ptr<Motion> m, const QString& error);

    SdoClient& sdo_;
    uint8_t node_;
    int axis_;
    int timeoutMs_ = 1000;
    int pollMs_ = 10;
    std::function<void(const QString&)> onSend_;
    std::shared_ptr<Move> move_;
    std::shared_ptr<Motion> motion_;
};

}  // namespace coscope::canopen
