// SPDX-License-Identifier: GPL-3.0-or-later
#include "dissectors/TraceStats.h"

#include "core/canopen/Nmt.h"
#include "core/canopen/SdoAbort.h"

#include <algorithm>
#include <cstdio>
#include <functional>

namespace coscope::dissect {

void TraceStats::add(const CanFrame& f) {
    ++frames_;
    if (!sharedLoad_) ownLoad_.add(f);
    if (f.isError()) {
        ++errorFrames_;
        return;
    }
    if (f.isExtended()) ++perExtId_[f.id];
    else ++perStdId_[f.id & 0x7FF];
    ctx_.dissect(f, d_, Dissection::Level::Stats);
    ++perService_[static_cast<size_t>(d_.service)];
    if (d_.node >= 1 && d_.node < 128) {
        if (f.bus >= nodeFrames_.size()) nodeFrames_.resize(size_t(f.bus) + 1, std::array<uint64_t, 128>{});
        ++nodeFrames_[f.bus][static_cast<size_t>(d_.node)];
    }
    if (d_.service == canopen::Service::Emcy) {
        ++emcys_;
        ++emcyPerNode_[d_.node];
    }
    if (!d_.warnings.isEmpty()) {
        warnings_ += static_cast<uint64_t>(d_.warnings.size());
        if (warningSamples_.size() < 10)
            warningSamples_.push_back(QStringLiteral("frame %1 (COB-ID 0x%2): %3")
                                          .arg(frames_)
                                          .arg(f.id, 3, 16, QLatin1Char('0'))
                                          .arg(d_.warnings.first()));
    }
    if (d_.hasTransfer) {
        const QString& s = d_.transfer.status;
        if (s == QLatin1String("ok")) ++sdoOk_;
        else if (s == QLatin1String("aborted")) {
            ++sdoAborted_;
            ++abortCodes_[d_.transfer.abortCode];
        } else ++sdoFailed_;
    }
}

QByteArray TraceStats::report(bool perSecond) const {
    QByteArray o;
    char line[256];
    auto put = [&](const char* fmt, auto... args) {
        const int n = std::snprintf(line, sizeof line, fmt, args...);
        o.append(line, std::min<int>(n, sizeof line - 1));
    };
    double seconds = 0;
    put("Frames: %llu (%llu error frames)\n", (unsigned long long)frames_, (unsigned long long)errorFrames_);
    o.append("\nFrames per service:\n");
    for (int s = 0; s < 32; ++s)
        if (perService_[s])
            put("  %-10s %12llu\n", qPrintable(canopen::serviceName(static_cast<canopen::Service>(s))),
                (unsigned long long)perService_[s]);
    o.append("\nFrames per COB-ID:\n");
    // The busiest kCobIdRows in COB-ID order, the rest summed (a short report, issue 37).
    constexpr size_t kCobIdRows = 12;
    std::vector<uint64_t> counts;
    for (uint64_t n : perStdId_)
        if (n) counts.push_back(n);
    uint64_t least = 0;  // a COB-ID with fewer frames is left out
    if (counts.size() > kCobIdRows) {
        std::nth_element(counts.begin(), counts.begin() + kCobIdRows - 1, counts.end(), std::greater<>());
        least = counts[kCobIdRows - 1];
    }
    size_t rows = 0, leftIds = 0;
    uint64_t leftFrames = 0;
    for (int id = 0; id < 2048; ++id) {
        const uint64_t n = perStdId_[static_cast<size_t>(id)];
        if (!n) continue;
        if (n < least || rows >= kCobIdRows) {
            ++leftIds;
            leftFrames += n;
            continue;
        }
        ++rows;
        const canopen::CobIdInfo info = canopen::classifyCobId(static_cast<uint32_t>(id));
        put("  0x%03X  %-10s %12llu\n", id, qPrintable(canopen::serviceName(info.service)),
            (unsigned long long)perStdId_[static_cast<size_t>(id)]);
    }
    if (leftIds) put("  ... %zu more COB-IDs with %llu frames\n", leftIds, (unsigned long long)leftFrames);
    for (const auto& [id, n] : perExtId_) put("  0x%08X (29-bit) %12llu\n", id, (unsigned long long)n);
    o.append("\nNodes:\n");
    bool anyNode = false;
    // Each bus has its own nodes (the network context keeps one state per bus).
    const bool severalBuses = nodeFrames_.size() > 1;
    for (size_t bus = 0; bus < nodeFrames_.size(); ++bus)
        for (int n = 1; n < 128; ++n) {
            const uint64_t count = nodeFrames_[bus][static_cast<size_t>(n)];
            // Only nodes that sent something (issue 37): a broadcast NMT or an SDO request to a
            // node-ID is no sign of a node. Its own COB-IDs of the predefined set (CiA 301 §7.3.5):
            // EMCY, TPDO1-4, SDO response, error control.
            uint64_t sent = 0;
            for (int base : {0x080, 0x180, 0x280, 0x380, 0x480, 0x580, 0x700})
                sent += perStdId_[static_cast<size_t>(base) + static_cast<size_t>(n)];
            if (!count || !sent) continue;
            const NodeState& s = ctx_.node(static_cast<int>(bus), n);
            anyNode = true;
            const QString state =
                s.nmtState >= 0 ? canopen::nmtStateName(static_cast<uint8_t>(s.nmtState)) : QStringLiteral("unknown");
            const QString where =
                !severalBuses
                    ? QString()
                    : (bus < size_t(busNames_.size()) ? busNames_[int(bus)] : QStringLiteral("bus %1").arg(bus)) + u' ';
            put("  %snode %3d  %-16s frames %10llu  dictionary %s\n", qPrintable(where), n, qPrintable(state),
                (unsigned long long)count, s.dictionaryName.isEmpty() ? "-" : qPrintable(s.dictionaryName));
        }
    if (!anyNode) o.append("  (none)\n");
    double peak = 0, total = 0;
    const std::vector<double>& bitsPerSecond = load().bitsPerSecond();
    for (double b : bitsPerSecond) {
        peak = std::max(peak, b);
        total += b;
    }
    seconds = static_cast<double>(bitsPerSecond.size());
    if (perSecond) {
        o.append("\nBus load (estimated, ");
        put("%d bit/s):\n", bitRate_);
    }
    if (perSecond && seconds > 0)
        put("  average %.1f %%, peak %.1f %% over %.0f s\n", 100.0 * total / seconds / bitRate_,
            100.0 * peak / bitRate_, seconds);
    const size_t shown = perSecond ? std::min<size_t>(bitsPerSecond.size(), 3600) : 0;
    for (size_t i = 0; i < shown; ++i) put("  second %6zu  %5.1f %%\n", i, 100.0 * bitsPerSecond[i] / bitRate_);
    if (perSecond && shown < bitsPerSecond.size()) put("  ... %zu more seconds\n", bitsPerSecond.size() - shown);
    put("\nSDO transfers: %llu (ok %llu, aborted %llu, failed %llu)\n",
        (unsigned long long)sdoOk_ + sdoAborted_ + sdoFailed_, (unsigned long long)sdoOk_,
        (unsigned long long)sdoAborted_, (unsigned long long)sdoFailed_);
    for (const auto& [code, n] : abortCodes_)
        put("  abort 0x%08X x%llu  %s\n", code, (unsigned long long)n, qPrintable(canopen::sdoAbortText(code)));
    put("\nEMCY: %llu\n", (unsigned long long)emcys_);
    for (const auto& [node, n] : emcyPerNode_) put("  node %d: %llu\n", node, (unsigned long long)n);
    put("\nWarnings: %llu\n", (unsigned long long)warnings_);
    for (const QString& w : warningSamples_) o.append("  ").append(w.toUtf8()).append('\n');
    return o;
}

}  // namespace coscope::dissect
