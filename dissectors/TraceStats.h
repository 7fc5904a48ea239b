// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/can/CanFrame.h"
#include "dissectors/Dissection.h"
#include "dissectors/NetworkContext.h"

#include <QByteArray>
#include <QString>
#include <QStringList>

#include <array>
#include <cstdint>
#include <map>
#include <vector>

namespace coscope::dissect {

// Bits on the wire by (extended, FD, payload size), computed at compile time (TraceStats::frameBits).
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
            for (int n = 0; n <= 64; ++n) t.bits[ext][fd][n] = ((ext ? 54.0 : 34.0) + 8.0 * n + (fd ? 21.0 : 0.0)) * 1.1 + 13.0;
    return t;
}
inline constexpr FrameBitsTable kFrameBits = makeFrameBitsTable();

// What `coscope-cli stats` reports about a trace: frames per COB-ID and service, nodes with
// their last NMT state, an estimated bus load per second, SDO transfers and aborts, EMCYs and
// warnings. Feed frames in order with add(); the context is run at the Stats level (no text).
class TraceStats {
public:
    explicit TraceStats(int bitRate = 500000) : bitRate_(bitRate) { ctx_.setGenericNames(false); }
    NetworkContext& context() { return ctx_; }

    void add(const CanFrame& f);
    // Names of the buses (CanFrame::bus indexes them), for the per-bus node list.
    void setBusNames(const QStringList& names) { busNames_ = names; }
    // The report as text (UTF-8); the bus load of every second only with `perSecond`.
    QByteArray report(bool perSecond = true) const;
    // The dissection of the last frame add() took (stale after an error frame), for analyses
    // that ride on the same decoding (NetworkHealth).
    const Dissection& lastDissection() const { return d_; }
    const NetworkContext& context() const { return ctx_; }

    uint64_t frames() const { return frames_; }
    uint64_t warnings() const { return warnings_; }
    uint64_t sdoTransfers() const { return sdoOk_ + sdoAborted_ + sdoFailed_; }
    uint64_t sdoAborts() const { return sdoAborted_; }
    uint64_t emcys() const { return emcys_; }
    uint64_t framesOfService(canopen::Service s) const { return perService_[static_cast<size_t>(s)]; }

    // Estimated bits on the wire of one frame: CiA/ISO 11898-1 frame fields plus an average
    // stuffing of 1 bit in 10 of the stuffable part (nominal, not worst case). Inline: `stats`
    // asks twice for every frame (trace and health bus load).
    static double frameBits(const CanFrame& f) {
        return kFrameBits.bits[f.isExtended() ? 1 : 0][f.isFd() ? 1 : 0][f.payloadSize() < 64 ? f.payloadSize() : 64];
    }

private:
    NetworkContext ctx_;
    Dissection d_;
    int bitRate_;
    uint64_t frames_ = 0, warnings_ = 0, emcys_ = 0, errorFrames_ = 0;
    uint64_t sdoOk_ = 0, sdoAborted_ = 0, sdoFailed_ = 0;
    std::vector<uint64_t> perStdId_ = std::vector<uint64_t>(2048, 0);
    std::map<uint32_t, uint64_t> perExtId_;
    uint64_t perService_[32] = {};
    std::map<uint32_t, uint64_t> abortCodes_;
    std::map<int, uint64_t> emcyPerNode_;
    std::vector<std::array<uint64_t, 128>> nodeFrames_;  // per bus, per node-ID
    QStringList busNames_;
    std::vector<double> bitsPerSecond_;
    int64_t t0_ = 0;
    bool haveT0_ = false;
    // The second the last frame fell in and its range of (timestamp - t0_), [secLo_, secHi_):
    // frames of the same second skip the division.
    int64_t sec_ = -1, secLo_ = 0, secHi_ = 0;
    std::vector<QString> warningSamples_;
};

}  // namespace coscope::dissect
