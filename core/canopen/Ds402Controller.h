// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/canopen/Ds402.h"
#include "core/canopen/SdoClient.h"

#include <QElapsedTimer>
#include <QObject>
#include <QString>

#include <functional>
#include <memory>

class QTimer;

namespace coscope::canopen {

// Outcome of a CiA 402 request.
struct Ds402Result {
    bool ok = false;
    uint16_t statusword = 0;
    ds402::State state = ds402::State::Unknown;
    int8_t mode = 0;         // setMode: 6061h read back
    QString error;           // one line: what failed and, for a transition, the missing bits
};
using Ds402Callback = std::function<void(const Ds402Result&)>;

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

    // The statusword mask/value a state shows (CiA 402-2 Table 30).
    static bool expectedStatusword(ds402::State s, uint16_t* mask, uint16_t* value);
    // "missing bit 2 (operation enabled)" / "unexpected bit 6 (switch on disabled)" for the bits
    // where `sw` differs from what `s` needs.
    static QString describeMismatch(ds402::State s, uint16_t sw);

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

    SdoClient& sdo_;
    uint8_t node_;
    int axis_;
    int timeoutMs_ = 1000;
    int pollMs_ = 10;
    std::function<void(const QString&)> onSend_;
};

}  // namespace coscope::canopen
