// SPDX-License-Identifier: GPL-3.0-or-later
// NetworkHealth: frame dispatch, EMCY, bus load and the report's assembly. Heartbeat/NMT in
// HeartbeatHealth.cpp, SDO in SdoHealth.cpp, PDO/SYNC in PdoHealth.cpp.
#include "dissectors/NetworkHealth.h"

#include "core/canopen/Emcy.h"
#include "dissectors/TraceStats.h"
#include "dissectors/VendorTable.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace coscope::dissect {

using canopen::Service;

// ---- IntervalStats: a double's exponent and top 5 mantissa bits make a 1/32-octave bucket.
double IntervalStats::bucketMidMs(int bucket) {
    const uint64_t bits = (static_cast<uint64_t>(bucket + (1023 << 5)) << 47) | (uint64_t{1} << 46);
    double x;
    std::memcpy(&x, &bits, sizeof x);
    return x / 1e6;
}

double IntervalStats::jitterMs() const {
    if (count == 0) return 0;
    const double n = static_cast<double>(count);
    const double meanDev = static_cast<double>(sumDevNs) / n;
    const double var = sumSqDevNs / n - meanDev * meanDev;  // ns squared
    return var > 0 ? std::sqrt(var) / 1e6 : 0;
}

double IntervalStats::medianMs() const {
    if (count == 0) return 0;
    uint64_t seen = 0;
    for (const Bucket& b : buckets) {
        seen += b.count;
        if (seen * 2 >= count)
            return static_cast<double>(b.sumNs) / static_cast<double>(b.count) / 1e6;  // the mean of the median bucket
    }
    return 0;
}

double IntervalStats::quantileMs(double q) const {
    if (count == 0) return 0;
    const auto rank = std::clamp<uint64_t>(static_cast<uint64_t>(std::ceil(q * static_cast<double>(count))), 1, count);
    uint64_t seen = 0;
    for (const Bucket& b : buckets) {
        seen += b.count;
        if (seen >= rank) return static_cast<double>(b.sumNs) / static_cast<double>(b.count) / 1e6;
    }
    return static_cast<double>(maxNs) / 1e6;
}

double IntervalStats::shareNear(double periodMs, double tolerance) const {
    if (count == 0 || periodMs <= 0) return 0;
    uint64_t near = 0;
    for (const Bucket& b : buckets) {
        if (!b.count) continue;
        const double mid = static_cast<double>(b.sumNs) / static_cast<double>(b.count) / 1e6;
        if (std::abs(mid - periodMs) <= tolerance * periodMs) near += b.count;
    }
    return static_cast<double>(near) / static_cast<double>(count);
}

uint64_t IntervalStats::countOver(double periodMs, double factor, uint64_t* missingPeriods) const {
    uint64_t n = 0, missing = 0;
    if (periodMs <= 0) return 0;
    for (const Bucket& b : buckets) {
        if (!b.count) continue;
        const double mid = static_cast<double>(b.sumNs) / static_cast<double>(b.count) / 1e6;
        if (mid <= factor * periodMs) continue;
        n += b.count;
        missing += b.count * static_cast<uint64_t>(std::max(0.0, std::round(mid / periodMs) - 1.0));
    }
    if (missingPeriods) *missingPeriods = missing;
    return n;
}

// ---- NetworkHealth
size_t NetworkHealth::samplesHeld() const {
    size_t n = 0;
    for (const BusTrack& b : buses_)
        for (const auto& t : b.nodes)
            if (t) n += t->beatGaps.buckets.size() + t->longGaps.size() + t->sdoRt.buckets.size();
    return n;
}

NetworkHealth::NodeTrack& NetworkHealth::node(int bus, int id) {
    auto& slot = busTrack(bus).nodes[static_cast<size_t>(id & 0x7F)];
    if (!slot) slot = std::make_unique<NodeTrack>();
    return *slot;
}

Occurrences NetworkHealth::IntervalMarks::select(double periodMs, double over, bool onlyLonger) const {
    Occurrences o;
    if (periodMs <= 0) return o;
    const double periodNs = periodMs * 1e6;
    for (const Mark& m : marks) {
        const double iv = static_cast<double>(m.intervalNs);
        const bool off = onlyLonger ? iv > (1 + over) * periodNs : std::abs(iv - periodNs) > over * periodNs;
        if (off) o.add(m.ns, m.frame);
    }
    return o;
}

void NetworkHealth::add(const CanFrame& f, const Dissection& d, const NetworkContext& ctx, int64_t frameNo) {
    frameNo_ = frameNo >= 0 ? static_cast<uint64_t>(frameNo) : frames_;
    if (!haveFirst_) {
        firstNs_ = f.timestampNs;
        haveFirst_ = true;
    }
    ++frames_;
    lastNs_ = std::max(lastNs_, f.timestampNs);
    if (!sharedLoad_) ownLoad_.add(f);
    if (f.isError()) {
        ++errorFrames_;
        errorFrameAt_.add(f.timestampNs, frameNo_);
        return;
    }
    if (d.service == Service::Unknown || (f.isExtended() && d.pdoNumber == 0)) {
        ++nonCanopen_;  // a 29-bit PDO the context routes is CANopen
        notCanopenAt_.add(f.timestampNs, frameNo_);
        return;
    }
    BusTrack& b = busTrack(f.bus);
    switch (d.service) {
    case Service::Nmt: addNmtCommand(f, b); break;
    case Service::Sync: addSync(f, b); break;
    case Service::Emcy:
        if (d.node >= 1 && d.node < 128) addEmcy(f, d.node, ctx);
        break;
    case Service::NmtErrorControl:
        if (d.node >= 1 && d.node < 128) addErrorControl(f, d.node, b);
        break;
    case Service::SdoRequest:
    case Service::SdoResponse:
        if (d.node >= 1 && d.node < 128) addSdo(f, d, ctx);
        break;
    case Service::Tpdo1:
    case Service::Tpdo2:
    case Service::Tpdo3:
    case Service::Tpdo4:
    case Service::Rpdo1:
    case Service::Rpdo2:
    case Service::Rpdo3:
    case Service::Rpdo4: addPdo(f, d, b, ctx); break;
    default: break;
    }
}

void NetworkHealth::addEmcy(const CanFrame& f, int id, const NetworkContext& ctx) {
    NodeTrack& t = node(f.bus, id);
    t.present = true;
    ++t.frames;
    if (f.len < 2) return;
    ++t.emcys;
    EmcyEntry e;
    e.timeNs = f.timestampNs;
    e.frame = frameNo_;
    e.code = static_cast<uint16_t>(f.data[0] | (f.data[1] << 8));
    e.reg = f.len >= 3 ? f.data[2] : 0;
    e.reset = e.code == 0;  // CiA 301 §7.2.7.1: error reset or no error
    if (e.reset) ++t.emcyResets;
    if (t.emcyList.size() >= 1000) return;
    e.text = e.reset ? QStringLiteral("error reset") : canopen::emcyCodeText(e.code);
    t.vendor = ctx.node(id).vendor;
    if (t.vendor && !e.reset) e.vendor = t.vendor->decodeEmcy(f.data.data(), f.len, e.code);
    t.tell(e.timeNs, e.frame,
           e.reset ? QStringLiteral("EMCY error reset")
                   : QStringLiteral("EMCY %1h %2%3")
                         .arg(e.code, 4, 16, QLatin1Char('0'))
                         .arg(e.text, e.vendor.isEmpty() ? QString() : QStringLiteral(" (%1)").arg(e.vendor)));
    t.emcyList.push_back(std::move(e));
}

namespace {
// Adds `from` to `into` (the frames of several nodes: sorted again).
void merge(Occurrences& into, const Occurrences& from) {
    if (!from.count) return;
    into.firstNs = into.count ? std::min(into.firstNs, from.firstNs) : from.firstNs;
    into.lastNs = into.count ? std::max(into.lastNs, from.lastNs) : from.lastNs;
    into.count += from.count;
    into.frames.insert(into.frames.end(), from.frames.begin(), from.frames.end());
    std::sort(into.frames.begin(), into.frames.end());
    if (into.frames.size() > Occurrences::kMaxFrames) into.frames.resize(Occurrences::kMaxFrames);
}
}  // namespace

HealthReport NetworkHealth::report(const NetworkContext* ctx, int64_t nowNs) const {
    HealthReport r;
    r.startNs = firstNs_;
    r.endNs = lastNs_;
    const int64_t now = std::max(nowNs, lastNs_);
    for (size_t bus = 0; bus < buses_.size(); ++bus)
        for (int id = 1; id < 128; ++id) {
            const NodeTrack* t = buses_[bus].nodes[static_cast<size_t>(id)].get();
            if (!t) continue;
            // Only nodes seen are listed (issue 37): an NMT command or an SDO request to a
            // node-ID that never sent anything (a scan's probe, a device missing) is summarised.
            if (!t->present) {
                if (t->sdoRequests > t->ownSdoRequests + 2) {
                    NodeHealth h;
                    h.node = id;
                    fillSdo(h, *t, now);
                    r.bus.unanswered.push_back(
                        {id, t->sdoRequests - t->ownSdoRequests, h.sdoTimeouts - h.ownSdoTimeouts, h.sdoTimeoutAt});
                } else if (t->sdoRequests > t->ownSdoRequests) {
                    r.bus.silentAddressed.push_back(id);
                    merge(r.bus.silentAt, t->sdoRequestAt);
                }
                if (t->ownSdoRequests) {
                    r.bus.ownSilentAddressed.push_back(id);
                    merge(r.bus.ownSilentAt, t->ownSdoRequestAt);
                }
                continue;
            }
            NodeHealth h;
            h.bus = static_cast<int>(bus);
            h.node = id;
            h.frames = t->frames;
            fillHeartbeat(h, *t, ctx, static_cast<int>(bus), now);
            fillSdo(h, *t, now);
            h.emcys = t->emcys;
            h.emcyResets = t->emcyResets;
            h.emcyList = t->emcyList;
            fillStory(h, *t);
            r.nodes.push_back(std::move(h));
        }
    fillPdos(r, ctx);
    fillBus(r, ctx);
    r.findings = healthFindings(r);
    r.verdict = healthVerdict(r.findings);
    return r;
}

void NetworkHealth::fillBus(HealthReport& r, const NetworkContext* ctx) const {
    BusHealth& b = r.bus;
    b.bitRate = bitRate_;
    b.frames = frames_;
    b.errorFrames = errorFrames_;
    b.nonCanopen = nonCanopen_;
    b.errorFrameAt = errorFrameAt_;
    b.notCanopenAt = notCanopenAt_;
    b.durationS = static_cast<double>(lastNs_ - firstNs_) / 1e9;
    const std::vector<double>& bitsPerSecond = load().bitsPerSecond();
    const size_t n = bitsPerSecond.size();
    double total = 0;
    b.perSecondPct.resize(n);
    for (size_t i = 0; i < n; ++i) {
        const double pct = 100.0 * bitsPerSecond[i] / bitRate_;
        b.perSecondPct[i] = pct;
        total += pct;
        if (pct > b.loadPeakPct) {
            b.loadPeakPct = pct;
            b.peakAtS = static_cast<double>(i);
        }
    }
    // The average over the time the trace covers (a partial last second counts as a part).
    const double covered = std::max(1.0, std::min(static_cast<double>(n), b.durationS + 1e-9));
    b.loadAvgPct = n ? total / covered : 0;
    // At most 60 buckets of whole seconds.
    const size_t per = std::max<size_t>(1, (n + 59) / 60);
    for (size_t i = 0; i < n; i += per) {
        LoadBucket lb;
        lb.startS = static_cast<double>(i);
        const size_t end = std::min(n, i + per);
        lb.seconds = static_cast<double>(end - i);
        double sum = 0;
        for (size_t k = i; k < end; ++k) {
            sum += b.perSecondPct[k];
            lb.peakPct = std::max(lb.peakPct, b.perSecondPct[k]);
        }
        lb.avgPct = sum / lb.seconds;
        b.loadOverTime.push_back(lb);
    }
    b.syncs = syncs_;
    // SYNC period: 1006h (communication cycle period, µs; CiA 301 §7.5.2.6), else observed.
    int periodUs = syncPeriodUs_;
    if (periodUs <= 0 && ctx)
        for (int bus = 0; bus < ctx->busCount() && periodUs <= 0; ++bus)
            for (int id = 1; id < 128 && periodUs <= 0; ++id) {
                const NodeState& s = ctx->node(bus, id);
                if (!s.dictionary || !s.seen) continue;
                if (const auto* e = s.dictionary->entry(0x1006, 0)) {
                    bool ok = false;
                    const int v = e->defaultValue.toInt(&ok, 0);
                    if (ok && v > 0) periodUs = v;
                }
            }
    if (periodUs > 0) {
        b.syncPeriodMs = periodUs / 1000.0;
        b.syncPeriodSource = QStringLiteral("1006h");
    } else if (syncPeriods_.count) {
        b.syncPeriodMs = syncPeriods_.medianMs();
        b.syncPeriodSource = QStringLiteral("observed");
    }
    if (b.syncPeriodMs > 0) {
        syncPeriods_.countOver(b.syncPeriodMs, 1.5, &b.syncMissing);
        b.syncMissingAt = syncMarks_.select(b.syncPeriodMs, 0.5, true);
    }
}

}  // namespace coscope::dissect
