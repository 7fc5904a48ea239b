// SPDX-License-Identifier: GPL-3.0-or-later
// NetworkHealth: SDO (CiA 301 §7.2.4) response times per request/response pair, transfers,
// aborts by code and requests left without an answer.
#include "dissectors/NetworkHealth.h"

#include "core/canopen/SdoAbort.h"
#include "dissectors/VendorTable.h"

#include <algorithm>
#include <cmath>

namespace coscope::dissect {

void NetworkHealth::addSdo(const CanFrame& f, const Dissection& d, const NetworkContext& ctx) {
    NodeTrack& t = node(f.bus, d.node);
    const int64_t now = f.timestampNs;
    if (d.service == canopen::Service::SdoRequest) {
        // Sent by the recording side (CoScope's own requests in its captures, issue 37).
        const bool own = f.isTx();
        ++t.sdoRequests;
        if (own) ++t.ownSdoRequests;
        if (!t.present) (own ? t.ownSdoRequestAt : t.sdoRequestAt).add(now, frameNo_);
        // A new request while the last one waits longer than the timeout: that one got no answer.
        if (t.sdoPending && now - t.sdoRequestNs > kSdoTimeoutNs) timedOut(t);
        // Block download segments come back to back: the answer is timed from the last one.
        // A client abort (ccs 4, CiA 301 §7.2.4.3.17) expects no answer.
        const bool abort = f.len >= 1 && (f.data[0] >> 5) == 4;
        t.sdoPending = !abort;
        t.sdoPendingOwn = own;
        t.sdoRequestNs = now;
        t.sdoRequestFrame = frameNo_;
    } else {
        t.present = true;
        ++t.frames;
        if (t.sdoPending) {
            ++t.sdoResponses;
            const float rt = static_cast<float>(static_cast<double>(now - t.sdoRequestNs) / 1e6);
            t.sdoRt.add(now - t.sdoRequestNs);
            if (rt > t.sdoRtMaxMs) {
                t.sdoRtMaxMs = rt;
                t.sdoRtMaxNs = now;
                t.sdoRtMaxFrame = frameNo_;
            }
            t.sdoPending = false;
        }
    }
    if (!d.hasTransfer) return;
    const SdoTransferRecord& x = d.transfer;
    if (x.status == QLatin1String("ok")) {
        ++t.sdoOk;
        // The producer heartbeat time, written or read (CiA 301 §7.5.2.25).
        if (x.index == 0x1017 && x.sub == 0 && x.data.size() >= 2) {
            t.heartbeatMs = static_cast<uint8_t>(x.data[0]) | (static_cast<uint8_t>(x.data[1]) << 8);
            t.heartbeatSetNs = now;
        }
        // The statusword read (or written by a test tool): the node's CiA 402 state.
        if (x.index == 0x6041 && x.sub == 0 && x.data.size() >= 2)
            addStatusword(t, f, static_cast<uint16_t>(uint8_t(x.data[0]) | uint8_t(x.data[1]) << 8));
        if (x.index == 0x1006 && x.sub == 0 && x.data.size() >= 4) {
            const uint32_t us = uint32_t(uint8_t(x.data[0])) | uint32_t(uint8_t(x.data[1])) << 8 |
                                uint32_t(uint8_t(x.data[2])) << 16 | uint32_t(uint8_t(x.data[3])) << 24;
            if (us > 0 && us < 100000000) syncPeriodUs_ = static_cast<int>(us);
        }
    } else if (x.status == QLatin1String("aborted")) {
        ++t.sdoAborted;
        // An abort that answers (or is) a request of the recording side: its own doing.
        const bool own = t.sdoPendingOwn || f.isTx();
        AbortCount& a = t.aborts[uint64_t{x.abortCode} | (own ? uint64_t{1} << 32 : 0)];
        if (a.count++ == 0) {
            a.code = x.abortCode;
            a.own = own;
            const VendorTable* vt = ctx.node(d.node).vendor;
            a.text = vt && vt->aborts.contains(x.abortCode) ? vt->aborts.value(x.abortCode)
                                                            : canopen::sdoAbortText(x.abortCode);
            // A code no table knows (issue 37): say so, not an empty text (code 0 reads "No reason given").
            if (a.text.isEmpty()) a.text = QStringLiteral("Abort code not in CiA 301");
        }
        a.at.add(now, frameNo_);
    } else {
        ++t.sdoFailed;
    }
}

void NetworkHealth::timedOut(NodeTrack& t) {
    ++t.sdoTimeouts;
    (t.sdoPendingOwn ? t.ownSdoTimeoutAt : t.sdoTimeoutAt).add(t.sdoRequestNs, t.sdoRequestFrame);
}

void NetworkHealth::fillSdo(NodeHealth& h, const NodeTrack& t, int64_t nowNs) const {
    h.sdoOk = t.sdoOk;
    h.sdoAborted = t.sdoAborted;
    h.sdoFailed = t.sdoFailed;
    h.sdoTransfers = t.sdoOk + t.sdoAborted + t.sdoFailed;
    h.sdoRequests = t.sdoRequests;
    h.sdoResponses = t.sdoResponses;
    h.sdoTimeoutAt = t.sdoTimeoutAt;
    h.ownSdoTimeoutAt = t.ownSdoTimeoutAt;
    h.sdoTimeouts = t.sdoTimeouts;
    if (t.sdoPending && nowNs - t.sdoRequestNs > kSdoTimeoutNs) {  // the last request, still unanswered
        ++h.sdoTimeouts;
        (t.sdoPendingOwn ? h.ownSdoTimeoutAt : h.sdoTimeoutAt).add(t.sdoRequestNs, t.sdoRequestFrame);
    }
    h.ownSdoTimeouts = h.ownSdoTimeoutAt.count;
    if (t.sdoRtMaxMs >= 0) h.slowSdoAt.add(t.sdoRtMaxNs, t.sdoRtMaxFrame);
    for (const auto& [code, a] : t.aborts) h.sdoAborts.push_back(a);
    std::sort(h.sdoAborts.begin(), h.sdoAborts.end(),
              [](const AbortCount& a, const AbortCount& b) { return a.count > b.count; });
    if (!t.sdoRt.count) return;
    h.sdoRtMinMs = static_cast<double>(t.sdoRt.minNs) / 1e6;
    h.sdoRtMaxMs = static_cast<double>(t.sdoRt.maxNs) / 1e6;
    h.sdoRtAvgMs = t.sdoRt.averageMs();
    // Nearest-rank 99th percentile, within its 1/32-octave bucket (never beyond the extremes).
    h.sdoRtP99Ms = std::clamp(t.sdoRt.quantileMs(0.99), h.sdoRtMinMs, h.sdoRtMaxMs);
}

}  // namespace coscope::dissect
