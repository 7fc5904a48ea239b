// SPDX-License-Identifier: GPL-3.0-or-later
// NetworkHealth: heartbeat and node guarding (CiA 301 §7.2.8.3), boot-ups and NMT state changes
// with the NMT command (§7.2.8.3.1) that caused them.
#include "dissectors/NetworkHealth.h"

#include "core/canopen/Nmt.h"

#include <algorithm>

namespace coscope::dissect {

namespace {
// An NMT command explains a state change or a boot-up seen within this time.
constexpr int64_t kCommandWindowNs = 5'000'000'000;
constexpr uint8_t kResetNode = 129, kResetComm = 130;
}  // namespace

void NetworkHealth::addNmtCommand(const CanFrame& f, BusTrack& b) {
    if (f.len < 2) return;
    const int cs = f.data[0];
    const int target = f.data[1];
    auto mark = [&](NodeTrack& t) {
        ++t.nmtCommands;
        t.lastCommand = cs;
        t.lastCommandNs = f.timestampNs;
        t.lastCommandAll = target == 0;
    };
    if (target != 0) {
        if (target < 128) mark(node(f.bus, target));
        return;
    }
    // To all nodes: every node known on this bus (a node appearing later finds no command).
    for (auto& slot : b.nodes)
        if (slot) mark(*slot);
}

void NetworkHealth::addErrorControl(const CanFrame& f, int id, BusTrack&) {
    NodeTrack& t = node(f.bus, id);
    if (f.isRemote()) {  // a node-guarding request from the master
        t.guarding = true;
        return;
    }
    if (f.len < 1) return;
    const bool wasPresent = t.present;
    t.present = true;
    ++t.frames;
    const int state = f.data[0] & 0x7F;  // bit 7 is the guarding toggle
    // The time from a boot-up to the first heartbeat is no heartbeat period: a producer starts
    // when its 1017h is set, often seconds later (issue 37: such a start is not "lost").
    if (t.beats && !t.lastWasBootUp && f.timestampNs >= t.lastBeatNs) {
        const int64_t gap = f.timestampNs - t.lastBeatNs;
        const uint64_t number = t.beatGaps.count;
        const bool longGap = number < kFirstGaps || double(gap) > kLongGap * double(t.beatGaps.minNs);
        t.beatGaps.add(gap);
        if (longGap && t.longGaps.size() < kMaxSamples) t.longGaps.push_back({gap, f.timestampNs, frameNo_, number});
    }
    ++t.beats;
    t.lastBeatNs = f.timestampNs;
    t.lastBeatFrame = frameNo_;
    t.lastWasBootUp = state == 0;
    const bool commanded = t.lastCommand >= 0 && f.timestampNs - t.lastCommandNs <= kCommandWindowNs;
    auto commandText = [&] {
        return QStringLiteral("NMT %1 (%2)")
            .arg(canopen::nmtCommandName(static_cast<uint8_t>(t.lastCommand)),
                 t.lastCommandAll ? QStringLiteral("all nodes") : QStringLiteral("node %1").arg(id));
    };
    if (state == 0) {  // boot-up
        ++t.bootUps;
        const bool resetCommanded = commanded && (t.lastCommand == kResetNode || t.lastCommand == kResetComm);
        // A node seen before that boots without being told to has reset itself (power, watchdog).
        if (wasPresent && !resetCommanded) {
            ++t.resets;
            t.resetAt.add(f.timestampNs, frameNo_);
        }
        const QString cause = resetCommanded ? commandText()
                              : wasPresent   ? QStringLiteral("node itself (unexpected reset)")
                                             : QStringLiteral("power-on");
        if (t.nmtChanges.size() < 1000) t.nmtChanges.push_back({f.timestampNs, t.state, 0, cause});
        t.tell(f.timestampNs, frameNo_, QStringLiteral("boot-up (%1)").arg(cause));
        if (resetCommanded) t.lastCommand = -1;
        t.state = 0;
        return;
    }
    if (state == t.state) return;
    QString cause;
    if (commanded && (canopen::nmtStateAfter(static_cast<uint8_t>(t.lastCommand)) == state)) {
        cause = commandText();
        t.lastCommand = -1;
    } else if (t.state == 0 && state == 127) {
        cause = QStringLiteral("node itself (after boot-up)");  // CiA 301 §7.3.2.1: boot-up leads to pre-operational
    } else if (t.state < 0) {
        cause = QStringLiteral("first seen");
    } else {
        cause = QStringLiteral("node itself");
    }
    if (t.nmtChanges.size() < 1000) t.nmtChanges.push_back({f.timestampNs, t.state, state, cause});
    // The first state seen after a boot-up is the boot-up's own (CiA 301 §7.3.2.1): not news.
    if (!(t.state == 0 && state == 127 && !commanded))
        t.tell(f.timestampNs, frameNo_,
               QStringLiteral("NMT %1%2 (%3)")
                   .arg(t.state < 0 ? QString()
                                    : canopen::nmtStateName(static_cast<uint8_t>(t.state)) + QStringLiteral(" -> "),
                        canopen::nmtStateName(static_cast<uint8_t>(state)), cause));
    t.state = state;
}

void NetworkHealth::fillHeartbeat(NodeHealth& h, const NodeTrack& t, const NetworkContext* ctx, int bus,
                                  int64_t nowNs) const {
    h.errorControl = t.beats == 0 ? QString() : t.guarding ? QStringLiteral("guarding") : QStringLiteral("heartbeat");
    h.beats = t.beats;
    h.bootUps = t.bootUps;
    h.resets = t.resets;
    h.state = t.state;
    h.nmtCommands = t.nmtCommands;
    h.nmtChanges = t.nmtChanges;
    h.heartbeatDisabled = t.heartbeatMs == 0;
    h.resetAt = t.resetAt;
    h.lastBeatNs = t.lastBeatNs;
    h.lastBeatFrame = t.lastBeatFrame;
    if (t.beatGaps.count) {
        h.periodMinMs = static_cast<double>(t.beatGaps.minNs) / 1e6;
        h.periodMaxMs = static_cast<double>(t.beatGaps.maxNs) / 1e6;
        h.periodAvgMs = t.beatGaps.averageMs();
        h.longestGapMs = h.periodMaxMs;
    }
    // The producer heartbeat time 1017h (CiA 301 §7.5.2.25): written/read in the trace, else the
    // dictionary's default, else the median of what was seen. Guarding has no 1017h.
    int periodMs = t.guarding ? -1 : t.heartbeatMs;
    if (periodMs <= 0 && !t.guarding && ctx) {
        const NodeState& s = ctx->node(bus, h.node);
        if (s.dictionary)
            if (const auto* e = s.dictionary->entry(0x1017, 0)) {
                bool ok = false;
                const int v = e->defaultValue.toInt(&ok, 0);
                if (ok && v > 0) periodMs = v;
            }
    }
    if (periodMs > 0) {
        h.expectedPeriodMs = periodMs;
        h.periodSource = QStringLiteral("1017h");
    } else if (t.beatGaps.count) {
        h.expectedPeriodMs = t.beatGaps.medianMs();
        h.periodSource = QStringLiteral("observed");
    }
    if (h.expectedPeriodMs <= 0) return;
    const double lateNs = 1.5e6 * h.expectedPeriodMs, lostNs = 3e6 * h.expectedPeriodMs;
    // "Lost" is a stop after regular beats: a long gap before the first regular interval is a
    // heartbeat that started late (or was set up later), not a lost one.
    // A gap not kept one by one was at most kLongGap x the shortest: regular.
    bool regular = false;
    uint64_t next = 0;  // the number of the gap after the last long one looked at
    for (const auto& g : t.longGaps) {
        if (g.number > next) regular = true;
        next = g.number + 1;
        const double gd = static_cast<double>(g.ns);
        if (gd > lostNs) {
            if (regular) {
                ++h.timeouts;
                h.lostAt.add(g.endNs, g.frame);
            }
        } else if (gd > lateNs) {
            if (regular) {
                ++h.late;
                h.lateAt.add(g.endNs, g.frame);
            }
        } else {
            regular = true;
        }
    }
    // Silent since the last beat: the heartbeat stopped (a timeout that has not ended).
    if (regular && !t.lastWasBootUp && static_cast<double>(nowNs - t.lastBeatNs) > lostNs) {
        h.silentNow = true;
        h.silentForMs = static_cast<double>(nowNs - t.lastBeatNs) / 1e6;
        ++h.timeouts;
        h.longestGapMs = std::max(h.longestGapMs, h.silentForMs);
    }
}

}  // namespace coscope::dissect
