// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/events/EventLog.h"
#include "app/gui/events/EventSpill.h"

#include "app/gui/language/CoreText.h"
#include "app/gui/language/ObjectNameText.h"
#include "core/can/CanErrorFrame.h"

#include "core/canopen/CobId.h"
#include "core/canopen/Emcy.h"
#include "core/canopen/Nmt.h"
#include "core/canopen/SdoAbort.h"

#include <algorithm>

#include <QCoreApplication>

namespace coscope::gui {

using canopen::Service;

QString eventKindName(TraceEvent::Kind kind) {
    switch (kind) {
    case TraceEvent::Kind::Emcy: return QStringLiteral("EMCY");
    case TraceEvent::Kind::EmcyReset: return QCoreApplication::translate("EventLog", "EMCY reset");
    case TraceEvent::Kind::SdoAbort: return QCoreApplication::translate("EventLog", "SDO abort");
    case TraceEvent::Kind::NmtState: return QCoreApplication::translate("EventLog", "NMT state");
    case TraceEvent::Kind::BootUp: return QCoreApplication::translate("EventLog", "Boot-up");
    case TraceEvent::Kind::NmtCommand: return QCoreApplication::translate("EventLog", "NMT command");
    case TraceEvent::Kind::HeartbeatTimeout: return QCoreApplication::translate("EventLog", "Heartbeat timeout");
    case TraceEvent::Kind::BusError: return QCoreApplication::translate("EventLog", "Bus error");
    case TraceEvent::Kind::Dropped: return QCoreApplication::translate("EventLog", "Dropped frames");
    case TraceEvent::Kind::Info: return QCoreApplication::translate("EventLog", "Info");
    }
    return {};
}

EventSeverity eventSeverity(TraceEvent::Kind kind) {
    using K = TraceEvent::Kind;
    switch (kind) {
    case K::Emcy:
    case K::HeartbeatTimeout:
    case K::BusError:
    case K::Dropped: return EventSeverity::Error;
    case K::SdoAbort: return EventSeverity::Warning;
    default: return EventSeverity::Info;
    }
}

QString eventSeverityName(EventSeverity severity) {
    switch (severity) {
    case EventSeverity::Error: return QCoreApplication::translate("EventLog", "error");
    case EventSeverity::Warning: return QCoreApplication::translate("EventLog", "warning");
    case EventSeverity::Info: return QCoreApplication::translate("EventLog", "info");
    }
    return {};
}

TraceEvent renderedEvent(TraceEvent::Kind kind, int64_t timeNs, FrameNo frame, int node,
                         std::function<QString()> render) {
    TraceEvent e{kind, timeNs, frame, node, render(), {}};
    e.render = std::move(render);
    return e;
}

namespace {
// A server's "object does not exist" / "sub-index does not exist" abort for an optional
// identity object: 1008h device name, 1009h hardware version, 100Ah software version (CiA 301
// §7.5.2.9-11) or 1018h sub 2-4 (§7.5.2.21). A device without them is normal (a scan asks every
// node): the trace shows the abort, the node table says "not present", it is no event.
bool optionalObjectAbsent(const TraceRecord& r) {
    if (r.len < 8) return false;
    const uint16_t index = static_cast<uint16_t>(r.data[1] | (r.data[2] << 8));
    const uint8_t sub = r.data[3];
    const uint32_t code =
        uint32_t(r.data[4]) | uint32_t(r.data[5]) << 8 | uint32_t(r.data[6]) << 16 | uint32_t(r.data[7]) << 24;
    if (code != canopen::sdoabort::NoObject && code != canopen::sdoabort::NoSubIndex) return false;
    return ((index == 0x1008 || index == 0x1009 || index == 0x100A) && sub == 0) ||
           (index == 0x1018 && sub >= 2 && sub <= 4);
}
}  // namespace

EventLog::EventLog(std::shared_ptr<const FrameDecoder> decoder)
    : decoder_(std::move(decoder)), spill_(std::make_unique<EventSpill>()) {}

EventLog::~EventLog() = default;

void EventLog::spillLocked() {
    if (events_.size() <= kInRam + kInRam / 4) return;  // in steps of a quarter, not one by one
    while (events_.size() > kInRam) {
        if (!spill_->append(events_.front())) return;  // no file: they stay in RAM
        events_.pop_front();
    }
}

void EventLog::consume(const TraceStore& store, FrameNo first, size_t count) {
    if (count == 0) return;
    std::lock_guard lock(mutex_);
    // Each event keeps what it needs to be written again in another UI language.
    auto push = [&](TraceEvent::Kind k, const TraceRecord& r, FrameNo n, int node, std::function<QString()> render) {
        events_.push_back(renderedEvent(k, r.timestampNs, n, node, std::move(render)));
    };
    for (size_t i = 0; i < count; ++i) {
        const FrameNo n = first + static_cast<FrameNo>(i);
        const TraceRecord& r = store.record(n);
        if (r.flags & CanFrame::Error) {
            push(TraceEvent::Kind::BusError, r, n, -1,
                 [f = store.frame(n)] { return coreText(decodeCanError(f).summary()); });
            continue;
        }
        if (r.flags & CanFrame::Extended) continue;
        const auto info = canopen::classifyCobId(r.id);
        switch (info.service) {
        case Service::Nmt:
            if (r.len >= 2) {
                push(
                    TraceEvent::Kind::NmtCommand, r, n, r.data[1] ? r.data[1] : -1, [cs = r.data[0], node = r.data[1]] {
                        const QString target = node == 0 ? QCoreApplication::translate("EventLog", "all nodes")
                                                         : QCoreApplication::translate("EventLog", "node %1").arg(node);
                        return QStringLiteral("%1 → %2").arg(coreText(canopen::nmtCommandName(cs)), target);
                    });
            }
            break;
        case Service::NmtErrorControl: {
            if ((r.flags & CanFrame::Remote) || r.len < 1) break;
            NodeWatch& w = watch_[static_cast<size_t>(info.node)];
            const int state = r.data[0] & 0x7F;
            if (w.timedOut) {
                push(TraceEvent::Kind::NmtState, r, n, info.node,
                     [] { return QCoreApplication::translate("EventLog", "Heartbeat back after timeout"); });
                w.timedOut = false;
            }
            if (state == 0) {
                push(TraceEvent::Kind::BootUp, r, n, info.node,
                     [] { return QCoreApplication::translate("EventLog", "Boot-up"); });
                w.state = 0x7F;  // pre-operational after boot-up (CiA 301 §7.3.2.2.1)
                w.lastNs = 0;
                w.periodNs = 0;
                break;
            }
            if (w.state != state) {
                push(TraceEvent::Kind::NmtState, r, n, info.node, [from = w.state, state] {
                    const QString now = coreText(canopen::nmtStateName(static_cast<uint8_t>(state)));
                    return from < 0 ? QCoreApplication::translate("EventLog", "State %1").arg(now)
                                    : QStringLiteral("%1 → %2").arg(
                                          coreText(canopen::nmtStateName(static_cast<uint8_t>(from))), now);
                });
                w.state = state;
            }
            if (w.lastNs && r.timestampNs > w.lastNs) w.periodNs = r.timestampNs - w.lastNs;
            w.lastNs = r.timestampNs;
            break;
        }
        case Service::Emcy:
        case Service::SdoResponse:
        case Service::SdoRequest: {
            const bool emcy = info.service == Service::Emcy;
            if (!emcy && !(r.len >= 1 && (r.data[0] >> 5) == 4)) break;  // only aborts: cs 4 (CiA 301 §7.2.4.3.17)
            // Our own "SDO protocol timed out" aborts (05040000h) are reported where the user
            // acted (and are expected during a scan); they are not bus events.
            if (!emcy && (r.flags & CanFrame::Tx) && r.len >= 8 && r.data[4] == 0x00 && r.data[5] == 0x00 &&
                r.data[6] == 0x04 && r.data[7] == 0x05)
                break;
            if (info.service == Service::SdoResponse && optionalObjectAbsent(r)) break;
            const CanFrame f = store.frame(n);
            // Decoded again on each render: the vendor alarm name follows the UI language.
            auto render = [f, emcy, decoder = decoder_] {
                dissect::Dissection d;
                d.reset(dissect::Dissection::Level::Flat);
                decoder->decode(f, d);
                QString text = coreText(localObjectNames(d, d.summary));
                if (emcy) {
                    const auto m = canopen::parseEmcy(f.data.data(), f.len);
                    // The dissector's summary names the vendor alarm already; else the raw vendor bytes.
                    if (const auto* v = d.find("emcy.vendor"); v && !d.summary.endsWith(QStringLiteral(", ") + v->text))
                        text += QStringLiteral(" — %1").arg(coreLines(v->text));
                    QStringList bits = canopen::errorRegisterBits(m.errorRegister);
                    for (QString& b : bits) b = coreText(b);
                    if (!bits.isEmpty()) text += QStringLiteral(" [%1]").arg(bits.join(QStringLiteral(", ")));
                }
                return text;
            };
            if (emcy)
                push(canopen::parseEmcy(f.data.data(), f.len).code == 0 ? TraceEvent::Kind::EmcyReset
                                                                        : TraceEvent::Kind::Emcy,
                     r, n, info.node, std::move(render));
            else push(TraceEvent::Kind::SdoAbort, r, n, info.node, std::move(render));
            break;
        }
        default: break;
        }
    }
    // Offline, the log's own clock tells when a heartbeat went missing.
    checkHeartbeatsLocked(store.record(first + static_cast<FrameNo>(count - 1)).timestampNs);
    spillLocked();
}

void EventLog::checkHeartbeats(int64_t nowNs) {
    std::lock_guard lock(mutex_);
    checkHeartbeatsLocked(nowNs);
    spillLocked();
}

void EventLog::checkHeartbeatsLocked(int64_t nowNs) {
    for (size_t id = 1; id < watch_.size(); ++id) {
        NodeWatch& w = watch_[id];
        if (!w.lastNs || !w.periodNs || w.timedOut || w.watched) continue;
        const int64_t limit = std::max<int64_t>(3 * w.periodNs, 1'500'000'000);
        if (nowNs - w.lastNs > limit) {
            w.timedOut = true;
            auto render = [silentMs = (nowNs - w.lastNs) / 1'000'000, periodMs = w.periodNs / 1'000'000] {
                return QCoreApplication::translate("EventLog", "No heartbeat for %1 ms (period %2 ms)")
                    .arg(silentMs)
                    .arg(periodMs);
            };
            events_.push_back(renderedEvent(TraceEvent::Kind::HeartbeatTimeout, nowNs, kNoFrame, static_cast<int>(id),
                                            std::move(render)));
        }
    }
}

void EventLog::add(TraceEvent event) {
    std::lock_guard lock(mutex_);
    events_.push_back(std::move(event));
    spillLocked();
}

void EventLog::restartHeartbeatWaits(int64_t backNs) {
    std::lock_guard lock(mutex_);
    for (NodeWatch& w : watch_)
        if (w.lastNs && !w.timedOut) w.lastNs = backNs;
}

void EventLog::setWatched(int node, bool watched) {
    if (node < 1 || node > 127) return;
    std::lock_guard lock(mutex_);
    watch_[static_cast<size_t>(node)].watched = watched;
}

void EventLog::forgetNode(int node) {
    if (node < 1 || node > 127) return;
    std::lock_guard lock(mutex_);
    watch_[static_cast<size_t>(node)] = {};
}

void EventLog::clear() {
    std::lock_guard lock(mutex_);
    events_.clear();
    spill_->clear();
    watch_ = {};
    generation_.fetch_add(1, std::memory_order_release);
}

size_t EventLog::size() const {
    std::lock_guard lock(mutex_);
    return spill_->size() + events_.size();
}

size_t EventLog::eventsInRam() const {
    std::lock_guard lock(mutex_);
    return events_.size();
}

std::vector<TraceEvent> EventLog::eventsLocked(size_t from, size_t to) const {
    const size_t spilled = spill_->size();
    to = std::min(to, spilled + events_.size());
    if (from >= to) return {};
    std::vector<TraceEvent> out;
    if (from < spilled) out = spill_->read(from, std::min(to, spilled));
    const size_t a = std::max(from, spilled) - spilled, b = std::max(to, spilled) - spilled;
    if (a < b)
        out.insert(out.end(), events_.begin() + static_cast<std::ptrdiff_t>(a),
                   events_.begin() + static_cast<std::ptrdiff_t>(b));
    return out;
}

std::vector<TraceEvent> EventLog::since(size_t from) const {
    std::lock_guard lock(mutex_);
    return eventsLocked(from, SIZE_MAX);
}

std::vector<TraceEvent> EventLog::events(size_t from, size_t to) const {
    std::lock_guard lock(mutex_);
    return eventsLocked(from, to);
}

}  // namespace coscope::gui
