// SPDX-License-Identifier: GPL-3.0-or-later
#include "dissectors/HealthOutput.h"

#include "core/canopen/Nmt.h"

#include <QJsonArray>

#include <cmath>

namespace coscope::dissect {

namespace {
double r3(double v) { return std::round(v * 1000.0) / 1000.0; }
double sec(int64_t ns, int64_t start) { return r3(static_cast<double>(ns - start) / 1e9); }
QJsonValue stateValue(int s) { return s < 0 ? QJsonValue() : QJsonValue(s); }
QJsonValue stateName(int s) {
    return s < 0 ? QJsonValue() : QJsonValue(canopen::nmtStateName(static_cast<uint8_t>(s)));
}

QJsonObject nodeJson(const NodeHealth& n, int64_t start) {
    QJsonObject hb{
        {QStringLiteral("kind"), n.errorControl.isEmpty() ? QJsonValue() : QJsonValue(n.errorControl)},
        {QStringLiteral("count"), double(n.beats)},
        {QStringLiteral("period_min_ms"), r3(n.periodMinMs)},
        {QStringLiteral("period_avg_ms"), r3(n.periodAvgMs)},
        {QStringLiteral("period_max_ms"), r3(n.periodMaxMs)},
        {QStringLiteral("period_ms"), r3(n.expectedPeriodMs)},
        {QStringLiteral("period_source"), n.periodSource.isEmpty() ? QJsonValue() : QJsonValue(n.periodSource)},
        {QStringLiteral("late"), double(n.late)},
        {QStringLiteral("timeouts"), double(n.timeouts)},
        {QStringLiteral("longest_gap_ms"), r3(n.longestGapMs)},
        {QStringLiteral("silent_now"), n.silentNow},
        {QStringLiteral("silent_for_ms"), r3(n.silentForMs)},
        {QStringLiteral("disabled"), n.heartbeatDisabled}};
    QJsonArray changes;
    for (const NmtChange& c : n.nmtChanges)
        changes.append(QJsonObject{{QStringLiteral("t"), sec(c.timeNs, start)},
                                   {QStringLiteral("from"), stateValue(c.from)},
                                   {QStringLiteral("to"), stateValue(c.to)},
                                   {QStringLiteral("to_name"), stateName(c.to)},
                                   {QStringLiteral("cause"), c.cause}});
    QJsonObject nmt{
        {QStringLiteral("state"), stateValue(n.state)},      {QStringLiteral("state_name"), stateName(n.state)},
        {QStringLiteral("boot_ups"), double(n.bootUps)},     {QStringLiteral("resets"), double(n.resets)},
        {QStringLiteral("commands"), double(n.nmtCommands)}, {QStringLiteral("changes"), changes}};
    QJsonArray aborts;
    for (const AbortCount& a : n.sdoAborts)
        aborts.append(QJsonObject{{QStringLiteral("code"), double(a.code)},
                                  {QStringLiteral("count"), double(a.count)},
                                  {QStringLiteral("text"), a.text}});
    QJsonObject sdo{
        {QStringLiteral("transfers"), double(n.sdoTransfers)}, {QStringLiteral("ok"), double(n.sdoOk)},
        {QStringLiteral("aborted"), double(n.sdoAborted)},     {QStringLiteral("failed"), double(n.sdoFailed)},
        {QStringLiteral("requests"), double(n.sdoRequests)},   {QStringLiteral("responses"), double(n.sdoResponses)},
        {QStringLiteral("timeouts"), double(n.sdoTimeouts)},   {QStringLiteral("response_min_ms"), r3(n.sdoRtMinMs)},
        {QStringLiteral("response_avg_ms"), r3(n.sdoRtAvgMs)}, {QStringLiteral("response_p99_ms"), r3(n.sdoRtP99Ms)},
        {QStringLiteral("response_max_ms"), r3(n.sdoRtMaxMs)}, {QStringLiteral("aborts"), aborts}};
    QJsonArray list;
    for (const EmcyEntry& e : n.emcyList)
        list.append(QJsonObject{{QStringLiteral("t"), sec(e.timeNs, start)},
                                {QStringLiteral("code"), e.code},
                                {QStringLiteral("reg"), e.reg},
                                {QStringLiteral("text"), e.text},
                                {QStringLiteral("vendor"), e.vendor},
                                {QStringLiteral("reset"), e.reset}});
    QJsonObject emcy{{QStringLiteral("count"), double(n.emcys)},
                     {QStringLiteral("resets"), double(n.emcyResets)},
                     {QStringLiteral("list"), list}};
    QJsonArray story;
    for (const StoryEntry& e : n.story)
        story.append(QJsonObject{{QStringLiteral("t"), sec(e.timeNs, start)},
                                 {QStringLiteral("frame"), double(e.frame + 1)},
                                 {QStringLiteral("text"), e.text}});
    return QJsonObject{{QStringLiteral("bus"), n.bus},
                       {QStringLiteral("node"), n.node},
                       {QStringLiteral("frames"), double(n.frames)},
                       {QStringLiteral("heartbeat"), hb},
                       {QStringLiteral("nmt"), nmt},
                       {QStringLiteral("sdo"), sdo},
                       {QStringLiteral("emcy"), emcy},
                       {QStringLiteral("story"), story},
                       {QStringLiteral("story_more"), double(n.storyMore)},
                       {QStringLiteral("outcome"), n.outcome}};
}
}  // namespace

QJsonObject healthJson(const HealthReport& r) {
    QJsonArray findings;
    for (const HealthFinding& f : r.findings) {
        // Frame numbers as the trace's "No." shows them (index + 1); the first 1000, `count` all.
        QJsonArray frames;
        for (uint64_t fr : f.at.frames) frames.append(double(fr + 1));
        findings.append(
            QJsonObject{{QStringLiteral("severity"), severityName(f.severity)},
                        {QStringLiteral("kind"), f.kind},
                        {QStringLiteral("rule"), f.rule},
                        {QStringLiteral("own"), f.own},
                        {QStringLiteral("node"), f.node < 0 ? QJsonValue() : QJsonValue(f.node)},
                        {QStringLiteral("t"), f.hasTime ? QJsonValue(sec(f.timeNs, r.startNs)) : QJsonValue()},
                        {QStringLiteral("count"), double(f.at.count)},
                        {QStringLiteral("first"), f.at.count ? QJsonValue(sec(f.at.firstNs, r.startNs)) : QJsonValue()},
                        {QStringLiteral("last"), f.at.count ? QJsonValue(sec(f.at.lastNs, r.startNs)) : QJsonValue()},
                        {QStringLiteral("frames"), frames},
                        {QStringLiteral("text"), f.text},
                        {QStringLiteral("what"), f.what},
                        {QStringLiteral("why"), f.why},
                        {QStringLiteral("check"), f.check}});
    }
    QJsonArray nodes;
    for (const NodeHealth& n : r.nodes) nodes.append(nodeJson(n, r.startNs));
    QJsonArray pdos;
    for (const PdoHealth& p : r.pdos)
        pdos.append(QJsonObject{{QStringLiteral("bus"), p.bus},
                                {QStringLiteral("cob_id"), double(p.cobId)},
                                {QStringLiteral("service"), p.service},
                                {QStringLiteral("node"), p.node < 0 ? QJsonValue() : QJsonValue(p.node)},
                                {QStringLiteral("frames"), double(p.frames)},
                                {QStringLiteral("rate_hz"), r3(p.rateHz)},
                                {QStringLiteral("period_avg_ms"), r3(p.periodAvgMs)},
                                {QStringLiteral("period_min_ms"), r3(p.periodMinMs)},
                                {QStringLiteral("period_max_ms"), r3(p.periodMaxMs)},
                                {QStringLiteral("cyclic"), p.cyclic},
                                {QStringLiteral("jitter_ms"), p.cyclic ? QJsonValue(r3(p.jitterMs)) : QJsonValue()},
                                {QStringLiteral("consumer_seen"), p.consumerSeen}});
    const BusHealth& b = r.bus;
    QJsonArray buckets, perSecond, noProducer;
    for (const LoadBucket& l : b.loadOverTime)
        buckets.append(QJsonObject{{QStringLiteral("t"), l.startS},
                                   {QStringLiteral("seconds"), l.seconds},
                                   {QStringLiteral("avg_pct"), r3(l.avgPct)},
                                   {QStringLiteral("peak_pct"), r3(l.peakPct)}});
    for (double v : b.perSecondPct) perSecond.append(r3(v));
    for (const RpdoNoProducer& p : b.rpdosNoProducer)
        noProducer.append(QJsonObject{{QStringLiteral("bus"), p.bus},
                                      {QStringLiteral("node"), p.node},
                                      {QStringLiteral("rpdo"), p.number},
                                      {QStringLiteral("cob_id"), double(p.cobId)}});
    QJsonArray silent, ownSilent;
    for (int id : b.silentAddressed) silent.append(id);
    for (int id : b.ownSilentAddressed) ownSilent.append(id);
    QJsonObject bus{{QStringLiteral("bit_rate"), b.bitRate},
                    {QStringLiteral("silent_addressed_nodes"), silent},
                    {QStringLiteral("own_scan_silent_nodes"), ownSilent},
                    {QStringLiteral("frames"), double(b.frames)},
                    {QStringLiteral("duration_s"), r3(b.durationS)},
                    {QStringLiteral("error_frames"), double(b.errorFrames)},
                    {QStringLiteral("non_canopen_frames"), double(b.nonCanopen)},
                    {QStringLiteral("load_avg_pct"), r3(b.loadAvgPct)},
                    {QStringLiteral("load_peak_pct"), r3(b.loadPeakPct)},
                    {QStringLiteral("load_peak_at_s"), b.peakAtS},
                    {QStringLiteral("load_over_time"), buckets},
                    {QStringLiteral("load_per_second_pct"), perSecond},
                    {QStringLiteral("sync"),
                     QJsonObject{{QStringLiteral("count"), double(b.syncs)},
                                 {QStringLiteral("period_ms"), r3(b.syncPeriodMs)},
                                 {QStringLiteral("period_source"),
                                  b.syncPeriodSource.isEmpty() ? QJsonValue() : QJsonValue(b.syncPeriodSource)},
                                 {QStringLiteral("missing"), double(b.syncMissing)}}},
                    {QStringLiteral("rpdos_no_producer"), noProducer}};
    return QJsonObject{{QStringLiteral("verdict"), r.verdict},
                       {QStringLiteral("findings"), findings},
                       {QStringLiteral("nodes"), nodes},
                       {QStringLiteral("pdos"), pdos},
                       {QStringLiteral("bus"), bus}};
}

}  // namespace coscope::dissect
