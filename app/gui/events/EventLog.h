// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "app/gui/trace/FrameDecoder.h"
#include "core/trace/TraceStore.h"

#include <QString>

#include <array>
#include <atomic>
#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <mutex>
#include <vector>

namespace coscope::gui {

inline constexpr FrameNo kNoFrame = 0xFFFFFFFFu;

// One thing worth a technician's attention, with the frame it came from (kNoFrame when none).
struct TraceEvent {
    enum class Kind : uint8_t {
        Emcy,
        EmcyReset,
        SdoAbort,
        NmtState,
        BootUp,
        NmtCommand,
        HeartbeatTimeout,
        BusError,
        Dropped,
        Info
    };
    Kind kind = Kind::Info;
    int64_t timeNs = 0;
    FrameNo frame = kNoFrame;
    int node = -1;
    QString text;  // in the UI language of when it was logged (or as add() was given it)
    // Writes the text again in the UI language of now (View ▸ Language rebuilds the Events view,
    // which asks for it); empty for events add()ed with a fixed text.
    std::function<QString()> render;
};
QString eventKindName(TraceEvent::Kind kind);

// How much an event asks of the technician: an error (EMCY, a heartbeat lost, a bus error,
// frames dropped), a warning (an SDO abort), or information (NMT, boot-ups, EMCY reset).
enum class EventSeverity : uint8_t { Info, Warning, Error };
EventSeverity eventSeverity(TraceEvent::Kind kind);
QString eventSeverityName(EventSeverity severity);  // in the UI language

// An event whose text `render` writes, now and again in each UI language the Events view is
// built in.
TraceEvent renderedEvent(TraceEvent::Kind kind, int64_t timeNs, FrameNo frame, int node,
                         std::function<QString()> render);

// The event list of a trace: EMCY (code text, error register bits, vendor alarm text from the
// decoder), SDO aborts (not a server's "not present" for an optional identity object), NMT commands and state changes, boot-ups, heartbeat timeouts, error
// frames, plus what the app adds (bus errors, dropped-frame counts). Fed like the node table;
// views read the events appended since their last look. Thread-safe.
//
// Bounded memory (issue 38): the newest kInRam events are in RAM; older ones go to a spill file
// (EventSpill) and are read back from there by since() and events(): every event stays, counts
// and all, however long the capture. A spilled event keeps the text of when it was logged.
class EventSpill;
class EventLog {
public:
    static constexpr size_t kInRam = 4096;

    explicit EventLog(std::shared_ptr<const FrameDecoder> decoder = defaultFrameDecoder());
    ~EventLog();

    void consume(const TraceStore& store, FrameNo first, size_t count);
    // A heartbeat is overdue when nothing came for 3 periods (at least 1.5 s) — live traces only.
    void checkHeartbeats(int64_t nowNs);
    void add(TraceEvent event);
    void clear();
    // The bus was lost and is back at backNs (issue 16): a heartbeat missing while the adapter
    // was gone says nothing about the node, so every node's wait starts again from backNs.
    void restartHeartbeatWaits(int64_t backNs);
    // Stops expecting heartbeats from `node` (its device moved to another node-ID).
    void forgetNode(int node);
    // CoScope watches the node's heartbeat or guards it (HeartbeatMonitor, with the times the
    // user set): its losses are told from there, not guessed here from the heartbeat period.
    void setWatched(int node, bool watched);

    uint64_t generation() const { return generation_.load(std::memory_order_acquire); }  // bumps on clear()
    size_t size() const;
    // Events [from, size()); the caller keeps `from`.
    std::vector<TraceEvent> since(size_t from) const;
    // Events [from, to) (to clamped to size()).
    std::vector<TraceEvent> events(size_t from, size_t to) const;
    size_t eventsInRam() const;

private:
    void checkHeartbeatsLocked(int64_t nowNs);
    void spillLocked();  // the oldest beyond kInRam to the spill file
    std::vector<TraceEvent> eventsLocked(size_t from, size_t to) const;

    std::shared_ptr<const FrameDecoder> decoder_;
    mutable std::mutex mutex_;
    std::deque<TraceEvent> events_;  // events [spill_->size(), size())
    std::unique_ptr<EventSpill> spill_;
    struct NodeWatch {
        int state = -1;
        int64_t lastNs = 0;
        int64_t periodNs = 0;
        bool timedOut = false;
        bool watched = false;  // setWatched()
    };
    std::array<NodeWatch, 128> watch_{};
    std::atomic<uint64_t> generation_{0};
};

}  // namespace coscope::gui
