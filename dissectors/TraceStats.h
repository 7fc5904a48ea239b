// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/can/CanFrame.h"
#include "dissectors/BusLoad.h"
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

    // The bus load is counted here, in add(), unless the consumer counts it itself (on the thread
    // that reads the log, once for this report and the health report) and hands it over here
    // before the first frame; it must outlive this object's report().
    void useBusLoad(const BusLoad* load) { sharedLoad_ = load; }

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
    BusLoad ownLoad_;
    const BusLoad* sharedLoad_ = nullptr;  // useBusLoad(); not a pointer to ownLoad_, which moves with a copy
    const BusLoad& load() const { return sharedLoad_ ? *sharedLoad_ : ownLoad_; }
    std::vector<QString> warningSamples_;
};

}  // namespace coscope::dissect
