// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/can/CanFrame.h"
#include "dissectors/BusLoad.h"
#include "dissectors/Dissection.h"
#include "dissectors/HealthReport.h"
#include "dissectors/NetworkContext.h"

#include <array>
#include <cstdint>
#include <cstring>
#include <limits>
#include <map>
#include <memory>
#include <vector>

namespace coscope::dissect {

struct VendorTable;

// Periods of a repeating frame at little cost per frame: count, min, max, the sum and the sum of
// squares of the deviations from the first period (the shifted-data variance: no cancellation
// for a steady period), and a histogram in 1/32-octave buckets with their sums (for the median
// and the gaps). Sums in nanoseconds: no division per frame.
struct IntervalStats {
    struct Bucket {
        uint64_t count = 0;
        int64_t sumNs = 0;  // the intervals of the bucket added up
    };
    uint64_t count = 0;
    int64_t minNs = 0, maxNs = 0;
    int64_t shiftNs = 0;          // the first interval
    int64_t sumDevNs = 0;         // of (interval - shiftNs)
    double sumSqDevNs = 0;        // of (interval - shiftNs) squared
    std::vector<Bucket> buckets;  // by bucketOf(ns)

    // Inline: every PDO and SYNC frame adds one.
    void add(int64_t ns) {
        if (count == 0) minNs = maxNs = shiftNs = ns;
        if (ns < minNs) minNs = ns;
        if (ns > maxNs) maxNs = ns;
        ++count;
        const int64_t dev = ns - shiftNs;
        sumDevNs += dev;
        sumSqDevNs += static_cast<double>(dev) * static_cast<double>(dev);
        const auto b = static_cast<size_t>(bucketOf(ns));
        if (b >= buckets.size()) [[unlikely]]
            buckets.resize(b + 1);
        ++buckets[b].count;
        buckets[b].sumNs += ns;
    }
    double averageMs() const {
        return count ? (static_cast<double>(shiftNs) + static_cast<double>(sumDevNs) / static_cast<double>(count)) / 1e6
                     : 0;
    }
    double jitterMs() const;  // standard deviation; 0 when empty
    double medianMs() const;  // 0 when empty
    // The q-quantile (0..1, nearest rank), as the mean of its bucket (within 1/32 octave); 0 when
    // empty.
    double quantileMs(double q) const;
    // The share (0..1) of intervals within `tolerance` (0.25 = ±25 %) of `periodMs`.
    double shareNear(double periodMs, double tolerance) const;
    // Gaps over `factor` x `periodMs`: how many, and how many whole periods they leave out.
    uint64_t countOver(double periodMs, double factor, uint64_t* missingPeriods = nullptr) const;
    // The bucket of an interval: the top bits of its double (exponent and 5 bits of mantissa).
    static int bucketOf(int64_t ns) {
        const double x = static_cast<double>(ns > 1 ? ns : 1);
        uint64_t bits;
        std::memcpy(&bits, &x, sizeof bits);
        return static_cast<int>(bits >> 47) - (1023 << 5);  // >= 0 for x >= 1
    }
    static double bucketMidMs(int bucket);
};

// The network health analysis (issue 15): fed frame by frame with the frame and its dissection,
// so it runs live (the app's ingest thread) and offline (`coscope-cli stats`) with the same code.
// Per node: heartbeat/guarding, NMT states and who commanded them, SDO response times, aborts
// and timeouts, EMCY; per PDO COB-ID rate and jitter; SYNC cycles; bus load and error frames.
// add() is O(1) and allocates only when a new node, PDO or second appears (or for the rare
// EMCY/SDO record); report() does the sorting and the findings. Not thread-safe.
class NetworkHealth {
public:
    explicit NetworkHealth(int bitRate = 500000) : bitRate_(bitRate) {}
    void setBitRate(int bitRate) { bitRate_ = bitRate; }
    int bitRate() const { return bitRate_; }

    // Feeds one frame after `ctx` dissected it into `d` (any level). Error frames are counted
    // without looking at `d`. `frameNo`: the frame's index in the trace, for the findings' frame
    // numbers; -1 = the count of frames added before it (a log read from its first frame).
    void add(const CanFrame& f, const Dissection& d, const NetworkContext& ctx, int64_t frameNo = -1);

    // The report as of `nowNs` (a silence up to then counts as a heartbeat or SDO timeout;
    // default: the last frame). `ctx` (may be null) adds the RPDOs configured with no producer.
    HealthReport report(const NetworkContext* ctx = nullptr, int64_t nowNs = std::numeric_limits<int64_t>::min()) const;

    // The bus load is counted here, in add(), unless the consumer counts it itself (on the thread
    // that reads the log, once for this report and the trace statistics) and hands it over here
    // before the first frame; it must outlive this object's report().
    void useBusLoad(const BusLoad* load) { sharedLoad_ = load; }

    uint64_t frames() const { return frames_; }
    int64_t lastNs() const { return lastNs_; }
    // Entries held for the nodes' heartbeat gaps and SDO response times (histogram buckets and
    // gaps kept one by one): bounded however long the trace (issue 38).
    size_t samplesHeld() const;

    // SDO timeout: a request with no answer within this time (CiA 301 leaves it to the client;
    // 1 s is the usual default).
    static constexpr int64_t kSdoTimeoutNs = 1'000'000'000;
    static constexpr size_t kMaxSamples = 1'000'000;  // per node, for heartbeats and SDO times
    static constexpr uint64_t kFirstGaps = 16;
    static constexpr double kLongGap = 1.25;

private:
    // Intervals that differ from the one before by over 25 %: the candidates for the frames of a
    // jitter or missing-SYNC finding, sorted out against the median at report() (bounded).
    struct IntervalMarks {
        struct Mark {
            uint64_t frame;
            int64_t ns, intervalNs;
        };
        int64_t prevNs = 0;
        std::vector<Mark> marks;
        void add(int64_t interval, int64_t ns, uint64_t frame) {
            if (prevNs > 0 && (interval * 4 > prevNs * 5 || interval * 4 < prevNs * 3) &&
                marks.size() < 4 * Occurrences::kMaxFrames) [[unlikely]]
                marks.push_back({frame, ns, interval});
            prevNs = interval;
        }
        // The marks off `periodMs` by more than the share `over` (0.25: outside ±25 %; for a
        // gap, `onlyLonger`: longer than (1 + over) x the period).
        Occurrences select(double periodMs, double over, bool onlyLonger) const;
    };
    struct NodeTrack {
        bool present = false;  // the node sent something (heartbeat, TPDO, SDO response, EMCY)
        uint64_t frames = 0;
        const VendorTable* vendor = nullptr;
        // heartbeat / guarding
        bool guarding = false;
        uint64_t beats = 0;
        int64_t lastBeatNs = 0;
        bool lastWasBootUp = false;  // the frame at lastBeatNs was a boot-up, not a beat
        uint64_t lastBeatFrame = 0;
        // Between beats; none from a boot-up to the first beat. Bounded (issue 38): all of them
        // in a histogram (count, min, max, mean, median); one by one only the first kFirstGaps and
        // those over kLongGap x the shortest so far, the only ones that can be late or lost
        // (over 1.5 x the period), each with the frame that ended it, its time and its number.
        IntervalStats beatGaps;
        struct LongGap {
            int64_t ns, endNs;
            uint64_t frame, number;
        };
        std::vector<LongGap> longGaps;
        Occurrences resetAt;
        int state = -1;
        uint64_t bootUps = 0, resets = 0, nmtCommands = 0;
        int64_t lastCommandNs = 0;
        int lastCommand = -1;  // NMT command specifier addressed to the node or all
        bool lastCommandAll = false;
        std::vector<NmtChange> nmtChanges;
        int heartbeatMs = -1;  // 1017h written or read in the trace, -1 = not seen
        int64_t heartbeatSetNs = 0;
        // SDO
        bool sdoPending = false;
        bool sdoPendingOwn = false;  // the waiting request was sent by the recording side (Tx)
        uint64_t sdoRequestFrame = 0;
        int64_t sdoRequestNs = 0;
        uint64_t ownSdoRequests = 0;
        Occurrences sdoTimeoutAt, ownSdoTimeoutAt;
        Occurrences sdoRequestAt, ownSdoRequestAt;  // kept for a node that never answers
        float sdoRtMaxMs = -1;
        int64_t sdoRtMaxNs = 0;
        uint64_t sdoRtMaxFrame = 0;
        uint64_t sdoRequests = 0, sdoResponses = 0, sdoTimeouts = 0;
        uint64_t sdoOk = 0, sdoAborted = 0, sdoFailed = 0;
        IntervalStats sdoRt;                    // response times, ns (a histogram: bounded, issue 38)
        std::map<uint64_t, AbortCount> aborts;  // by code, own ones (bit 32) apart
        // EMCY
        uint64_t emcys = 0, emcyResets = 0;
        std::vector<EmcyEntry> emcyList;
        // the story (NodeHealth::story) and the CiA 402 state from the statusword
        std::vector<StoryEntry> story;
        uint64_t storyMore = 0;
        int ds402State = -1;
        bool ds402Fault = false;  // was in Fault (or fault reaction) at some time
        void tell(int64_t ns, uint64_t frame, QString text) {
            if (story.size() < NodeHealth::kStory) story.push_back({ns, frame, std::move(text)});
            else ++storyMore;
        }
    };
    struct PdoTrack {
        uint32_t cobId = 0;
        int bus = 0;
        int node = -1;
        bool tpdo = true;
        int number = 0;
        uint64_t frames = 0;
        int64_t firstNs = 0, lastNs = 0;
        uint64_t firstFrame = 0;
        IntervalStats periods;
        IntervalMarks marks;
        // Where the statusword 6041h sits in this TPDO (CiA 402-2 §8.4.1), for the node's story:
        // looked up again when the node's mapping changes.
        const void* swConfig = nullptr;
        int swMapCount = -1;
        int swBit = -1;  // -1 = not mapped
    };
    struct BusTrack {
        std::array<std::unique_ptr<NodeTrack>, 128> nodes;
        std::vector<int32_t> pdoIndex = std::vector<int32_t>(2048, -1);
        std::map<uint32_t, int32_t> extPdoIndex;
        int64_t lastSyncNs = 0;
        bool syncSeen = false;
        int syncPeriodUs = -1;  // 1006h written in the trace or from a dictionary
    };

    NodeTrack& node(int bus, int id);
    // Every frame asks for its bus: inline, the vector grows only for a new bus.
    BusTrack& busTrack(int bus) {
        if (static_cast<size_t>(bus) >= buses_.size()) [[unlikely]]
            buses_.resize(static_cast<size_t>(bus) + 1);
        return buses_[static_cast<size_t>(bus)];
    }
    void addErrorControl(const CanFrame& f, int id, BusTrack& b);                    // HeartbeatHealth.cpp
    void addNmtCommand(const CanFrame& f, BusTrack& b);                              // HeartbeatHealth.cpp
    void addSdo(const CanFrame& f, const Dissection& d, const NetworkContext& ctx);  // SdoHealth.cpp
    void addEmcy(const CanFrame& f, int id, const NetworkContext& ctx);
    void addPdo(const CanFrame& f, const Dissection& d, BusTrack& b, const NetworkContext& ctx);  // PdoHealth.cpp
    void addStatusword(NodeTrack& t, const CanFrame& f, uint16_t sw) const;                       // Ds402Story.cpp
    void fillStory(NodeHealth& h, const NodeTrack& t) const;                                      // Ds402Story.cpp
    void addSync(const CanFrame& f, BusTrack& b);                                                 // PdoHealth.cpp
    void fillHeartbeat(NodeHealth& h, const NodeTrack& t, const NetworkContext* ctx, int bus, int64_t nowNs) const;
    void fillSdo(NodeHealth& h, const NodeTrack& t, int64_t nowNs) const;
    static void timedOut(NodeTrack& t);  // SdoHealth.cpp: the waiting request got no answer
    void fillPdos(HealthReport& r, const NetworkContext* ctx) const;
    void fillBus(HealthReport& r, const NetworkContext* ctx) const;

    int bitRate_;
    uint64_t frames_ = 0, errorFrames_ = 0, nonCanopen_ = 0;
    uint64_t frameNo_ = 0;  // of the frame add() handles
    Occurrences errorFrameAt_, notCanopenAt_;
    IntervalMarks syncMarks_;
    int64_t firstNs_ = 0, lastNs_ = 0;
    bool haveFirst_ = false;
    std::vector<BusTrack> buses_;
    std::vector<PdoTrack> pdos_;
    IntervalStats syncPeriods_;
    uint64_t syncs_ = 0;
    int syncPeriodUs_ = -1;
    BusLoad ownLoad_;
    const BusLoad* sharedLoad_ = nullptr;  // useBusLoad(); not a pointer to ownLoad_, which moves with a copy
    const BusLoad& load() const { return sharedLoad_ ? *sharedLoad_ : ownLoad_; }
};

// Findings in plain words, worst first, own-traffic ones last (HealthFindings.cpp).
std::vector<HealthFinding> healthFindings(const HealthReport& r);
// "Problems found: 1 critical, 2 errors, 5 warnings" or "No problems found" (HealthFindings.cpp).
QString healthVerdict(const std::vector<HealthFinding>& findings);
// "12:03:11" for wall-clock timestamps, else "12.345 s" from the start of the trace.
QString healthTime(int64_t ns, int64_t startNs);

}  // namespace coscope::dissect
