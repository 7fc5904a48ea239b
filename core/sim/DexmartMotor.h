// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstdint>

namespace coscope::sim {

class VirtualDevice;

// One motor of the DEXMART (Trumman) DEV two-motor drive, which has no CiA 402 profile: it is
// commanded through the vendor Multi-Drive objects (M1 3051h, M2 3052h: sub 1 CMD, sub 2 Data1,
// sub 3 Data2) and Multi-Drive Lite objects (M1 305Bh, M2 305Ch: sub 1 CMD, sub 2 Data) and
// reports in its monitor object (M1 3046h, M2 304Ah). Commands (extract-dexmart §6-7):
// Multi-Drive CMD 0Ah continuous run at Data2 rpm, 0Fh relative move of Data1 revolutions,
// Lite CMD 01h continuous run at Data rpm; CMD 00h stops.
class DexmartMotor {
public:
    DexmartMotor(VirtualDevice& device, int motor);

    void onWrite(uint16_t index, uint8_t sub);
    void step(int64_t dtNs);
    void reset();
    void raiseAlarm(uint8_t code);
    bool alarmed() const { return alarm_ != 0; }
    double speedRpm() const { return speed_; }
    double revolutions() const { return revs_; }

private:
    void publish();
    uint16_t monitor() const { return motor_ == 0 ? 0x3046 : 0x304A; }

    VirtualDevice& dev_;
    int motor_;
    double speed_ = 0;        // rpm, actual
    double targetSpeed_ = 0;  // rpm
    double revs_ = 0;         // position in revolutions
    double moveTarget_ = 0;
    bool moving_ = false;
    uint8_t alarm_ = 0;
    int publishCountdown_ = 0;
};

}  // namespace coscope::sim
