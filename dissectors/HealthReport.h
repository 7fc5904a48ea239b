// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QString>
#include <QStringList>

#include <cstdint>
#include <vector>

namespace coscope::dissect {

// The network health report (DESIGN.md "Contracts": `coscope-cli stats --format json`, the app's
// Health view, `--format html`): plain figures computed by NetworkHealth. Times are in the
// trace's nanoseconds; durations in milliseconds; loads in percent of the bit rate.

// Where a finding shows in the trace: how often, first and last time, and the frame numbers
// (the trace's frame index, 0-based; outputs show it as the trace's "No.", index + 1). The
// first kMaxFrames are kept, the count goes on: bounded memory on any log.
struct Occurrences {
    static constexpr size_t kMaxFrames = 1000;
    uint64_t count = 0;
    int64_t firstNs = 0, lastNs = 0;
    std::vector<uint64_t> frames;
    void add(int64_t ns, uint64_t frame) {
        if (count++ == 0) firstNs = ns;
        lastNs = ns;
        if (frames.size() < kMaxFrames) frames.push_back(frame);
    }
};

// One line of the findings list, worst first.
struct HealthFinding {
    enum Severity : int { Info = 0, Warning = 1, Error = 2, Critical = 3 };
    int severity = Info;
    QString kind;   // stable key: "reset", "heartbeat_timeout", "emcy", "sdo_abort", ...
    int node = -1;  // -1 = the bus
    int64_t timeNs = 0;
    bool hasTime = false;
    QString text;  // plain words, English (the CLI language)
    // Issue 37: the rule (HealthRules.h, "heartbeat.lost", "sdo.abort", ...), the values its
    // sentences are filled with (%1.. of what/why/check), those sentences in English, and where
    // it happened. `own`: caused by the recording side's own requests (frames marked Tx, e.g.
    // CoScope's scan), never a device's fault: always Info, listed apart.
    QString rule;
    QStringList args;
    QString what, why, check;
    Occurrences at;
    bool own = false;
};
QString severityName(int severity);  // "critical", "error", "warning", "info"

// An NMT state change seen in the node's heartbeat/guarding/boot-up, and what caused it.
struct NmtChange {
    int64_t timeNs = 0;
    int from = -1;  // NMT state (0, 4, 5, 127), -1 = unknown
    int to = -1;
    QString cause;  // "NMT Start (all nodes) at ...", "node itself", "reset (boot-up)"
};

struct EmcyEntry {
    int64_t timeNs = 0;
    uint64_t frame = 0;
    uint16_t code = 0;
    uint8_t reg = 0;
    QString text;        // CiA 301/402 text of the code
    QString vendor;      // vendor alarm text, else empty
    bool reset = false;  // code 0000h: error reset / no error
};

struct AbortCount {
    uint32_t code = 0;
    uint64_t count = 0;
    QString text;
    bool own = false;  // answers to the recording side's own requests (frames marked Tx)
    Occurrences at;    // the frames of the aborts
};

// One line of a node's story (issue 37): a boot-up, an NMT or CiA 402 state change, an EMCY.
struct StoryEntry {
    int64_t timeNs = 0;
    uint64_t frame = 0;
    QString text;  // English, e.g. "CiA 402 state Operation enabled -> Fault"
};

struct NodeHealth {
    int bus = 0;
    int node = 0;
    uint64_t frames = 0;
    // Heartbeat / node guarding (CiA 301 §7.2.8.3)
    QString errorControl;  // "heartbeat", "guarding" or "" (none seen)
    uint64_t beats = 0;
    double periodMinMs = 0, periodAvgMs = 0, periodMaxMs = 0;
    double expectedPeriodMs = 0;  // 1017h when known, else the observed median
    QString periodSource;         // "1017h", "observed" or ""
    uint64_t late = 0;            // beats later than 1.5x the period
    uint64_t timeouts = 0;        // gaps over 3x the period (including a silence at the end)
    double longestGapMs = 0;
    bool silentNow = false;  // nothing for over 3 periods at the end of the trace / now
    double silentForMs = 0;
    bool heartbeatDisabled = false;  // 1017h written 0 in the trace
    uint64_t bootUps = 0;
    uint64_t resets = 0;       // boot-ups without an NMT reset command: the node rebooted
    int state = -1;            // last NMT state
    uint64_t nmtCommands = 0;  // NMT commands addressed to the node (or to all)
    std::vector<NmtChange> nmtChanges;
    // SDO (CiA 301 §7.2.4)
    uint64_t sdoTransfers = 0, sdoOk = 0, sdoAborted = 0, sdoFailed = 0;
    uint64_t sdoRequests = 0, sdoResponses = 0, sdoTimeouts = 0;
    double sdoRtMinMs = 0, sdoRtAvgMs = 0, sdoRtP99Ms = 0, sdoRtMaxMs = 0;
    std::vector<AbortCount> sdoAborts;
    // EMCY (CiA 301 §7.2.7)
    uint64_t emcys = 0, emcyResets = 0;
    std::vector<EmcyEntry> emcyList;  // the first 1000
    // Occurrences of the findings that rest on this node's frames (frame numbers).
    Occurrences resetAt, lostAt, lateAt, sdoTimeoutAt, ownSdoTimeoutAt, slowSdoAt;
    uint64_t ownSdoTimeouts = 0;  // of sdoTimeouts: requests sent by the recording side
    int64_t lastBeatNs = 0;
    uint64_t lastBeatFrame = 0;
    // The story: boot-ups, NMT and CiA 402 state changes, EMCY (the first kStory; storyMore left
    // out), and how it ended: "no problems", "recovered" or "not recovered (...)".
    static constexpr size_t kStory = 200;
    std::vector<StoryEntry> story;
    uint64_t storyMore = 0;
    int ds402State = -1;  // canopen::ds402::State as last seen, -1 = no statusword seen
    QString outcome;
};

struct PdoHealth {
    int bus = 0;
    uint32_t cobId = 0;
    QString service;  // "TPDO1", "RPDO2", ...
    int node = -1;
    uint64_t frames = 0;
    double rateHz = 0;
    double periodAvgMs = 0, periodMinMs = 0, periodMaxMs = 0;
    double jitterMs = 0;  // standard deviation of the period
    // Sent in a cycle (SYNC or event timer): most intervals (80 %) within ±25 % of the median.
    // Jitter means something only then; an event-driven PDO's intervals are the events'.
    bool cyclic = false;
    bool consumerSeen = true;  // RPDO: the addressed node sent anything at all
    uint64_t firstFrame = 0;
    int64_t firstNs = 0;
    Occurrences irregularAt;  // cyclic: intervals off the median by over 25 %
};

struct RpdoNoProducer {
    int bus = 0;
    int node = 0;
    int number = 0;
    uint32_t cobId = 0;
};

struct LoadBucket {
    double startS = 0;
    double seconds = 0;
    double avgPct = 0;
    double peakPct = 0;
};

struct BusHealth {
    int bitRate = 500000;
    uint64_t frames = 0, errorFrames = 0, nonCanopen = 0;
    double durationS = 0;
    double loadAvgPct = 0, loadPeakPct = 0, peakAtS = 0;
    std::vector<LoadBucket> loadOverTime;  // at most 60 buckets
    std::vector<double> perSecondPct;      // one per second since the first frame
    uint64_t syncs = 0;
    double syncPeriodMs = 0;
    QString syncPeriodSource;  // "1006h", "observed" or ""
    uint64_t syncMissing = 0;  // SYNC cycles missing (gaps over 1.5x the period)
    std::vector<RpdoNoProducer> rpdosNoProducer;
    // Node-IDs that got an SDO request or two and never sent anything (a network scan probing
    // 1-127, or a device missing): summarised here, not listed as nodes.
    std::vector<int> silentAddressed;
    Occurrences silentAt;  // the requests to them (other masters')
    // A node-ID another master asked again and again (over 2 requests) that never answered: a
    // device missing. Not a node row (never seen), but its unanswered requests are a finding.
    struct Unanswered {
        int node = 0;
        uint64_t requests = 0, timeouts = 0;
        Occurrences at;  // the requests that timed out
    };
    std::vector<Unanswered> unanswered;
    std::vector<int> ownSilentAddressed;  // the same for requests the recording side sent (Tx)
    Occurrences ownSilentAt;
    Occurrences errorFrameAt, syncMissingAt, notCanopenAt;
};

struct HealthReport {
    int64_t startNs = 0, endNs = 0;
    // "Problems found: 2 errors, 5 warnings" / "No problems found" (own-traffic findings and
    // info do not count).
    QString verdict;
    std::vector<HealthFinding> findings;
    std::vector<NodeHealth> nodes;
    std::vector<PdoHealth> pdos;
    BusHealth bus;
};

}  // namespace coscope::dissect
