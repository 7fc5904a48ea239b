// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/can/CanFrame.h"

#include <cstdint>
#include <vector>

namespace coscope::dissect {

// Bits on the wire by (extended, FD, payload size), computed at compile time (BusLoad::frameBits).
// Classic base frame: SOF..CRC delimiter = 34 + 8n stuffable bits (+ 20 for a 29-bit id), then
// ACK, EOF and intermission (13 bits); stuffing adds up to ~10 % of the stuffable bits. FD frames
// are counted at the nominal rate (an overestimate when BRS is used).
struct FrameBitsTable {
    double bits[2][2][65];
};
constexpr FrameBitsTable makeFrameBitsTable() {
    FrameBitsTable t{};
    for (int ext = 0; ext < 2; ++ext)
        for (int fd = 0; fd < 2; ++fd)
            for (int n = 0; n <= 64; ++n)
                t.bits[ext][fd][n] = ((ext ? 54.0 : 34.0) + 8.0 * n + (fd ? 21.0 : 0.0)) * 1.1 + 13.0;
    return t;
}
inline constexpr FrameBitsTable kFrameBits = makeFrameBitsTable();

// The estimated bus load of a trace: the bits of its frames added up per second, counted from
// its first frame (the second of a frame is (timestamp - first) / 1 s, truncated, so (-1 s, 1 s)
// is second 0; frames before that or past kMaxSeconds are not counted). One model for the trace
// statistics and the health report; `coscope-cli stats` counts it on the thread that reads the
// log and both reports read it from there.
class BusLoad {
public:
    static constexpr int64_t kMaxSeconds = 10'000'000;  // ~115 days

    // Inline: every frame of a trace comes here.
    void add(const CanFrame& f) {
        if (!haveFirst_) {
            firstNs_ = f.timestampNs;
            haveFirst_ = true;
        }
        const int64_t delta = f.timestampNs - firstNs_;
        if (!(sec_ >= 0 && delta >= secLo_ && delta < secHi_)) [[unlikely]]
            if (!enterSecond(delta)) return;
        bitsPerSecond_[static_cast<size_t>(sec_)] += frameBits(f);
    }
    const std::vector<double>& bitsPerSecond() const { return bitsPerSecond_; }

    // Estimated bits on the wire of one frame: CiA/ISO 11898-1 frame fields plus an average
    // stuffing of 1 bit in 10 of the stuffable part (nominal, not worst case).
    static double frameBits(const CanFrame& f) {
        return kFrameBits.bits[f.isExtended() ? 1 : 0][f.isFd() ? 1 : 0][f.payloadSize() < 64 ? f.payloadSize() : 64];
    }

private:
    bool enterSecond(int64_t delta);  // false: no slot for this frame

    int64_t firstNs_ = 0;
    bool haveFirst_ = false;
    // The second the last frame fell in and its range of (timestamp - first), [secLo_, secHi_):
    // frames of the same second skip the division.
    int64_t sec_ = -1, secLo_ = 0, secHi_ = 0;
    std::vector<double> bitsPerSecond_;
};

}  // namespace coscope::dissect
