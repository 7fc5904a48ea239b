// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/canopen/HeartbeatGuard.h"

#include "core/canopen/SdoAbort.h"

#include <QPointer>

#include <vector>

namespace coscope::canopen {

namespace {
QByteArray le(uint32_t v, int bytes) {
    QByteArray b(bytes, 0);
    for (int i = 0; i < bytes; ++i) b[i] = static_cast<char>((v >> (8 * i)) & 0xFF);
    return b;
}
uint32_t readLe(const QByteArray& b) {
    uint32_t v = 0;
    for (int i = 0; i < std::min<int>(4, static_cast<int>(b.size())); ++i) v |= uint32_t(uint8_t(b[i])) << (8 * i);
    return v;
}
uint8_t producerOf(uint32_t entry) { return static_cast<uint8_t>(entry >> 16); }
uint16_t timeOf(uint32_t entry) { return static_cast<uint16_t>(entry & 0xFFFF); }
// An entry watches a node when its time and its node-ID (1..127) are set (CiA 301 §7.5.2.18).
bool inUse(uint32_t entry) { return timeOf(entry) != 0 && producerOf(entry) >= 1 && producerOf(entry) <= 127; }
bool missing(const SdoResult& r) {
    return r.serverAborted && (r.abortCode == sdoabort::NoObject || r.abortCode == sdoabort::NoSubIndex);
}
QString hex32(uint32_t v) { return QStringLiteral("0x") + QStringLiteral("%1").arg(v, 8, 16, QChar(u'0')).toUpper(); }
QString subText(uint8_t sub) { return QStringLiteral("%1").arg(int(sub), 2, 16, QChar(u'0')).toUpper(); }

// What a drive without 6007h does when the heartbeat it consumes stops, where its manual says.
QString makersReaction(const QString& dictionary) {
    if (dictionary == u"delta-asda-a2")
        return QStringLiteral(
            "alarm AL170 (servo on), a fault: it stops on its fault reaction 605Eh (extract-delta §6.3)");
    if (dictionary == u"aimotor") return QStringLiteral("alarm Er.D03 \"CAN communication interrupted\", a fault");
    return QStringLiteral("as its maker defines");
}
}  // namespace

struct HeartbeatGuard::Arming {
    HeartbeatGuardCallback done;
    uint8_t producer = 0;
    uint16_t timeMs = 0;
    uint8_t count = 0;              // 1016h:00
    std::vector<uint32_t> entries;  // 1016h:01.. as read
    uint8_t sub = 0;
    std::optional<int16_t> oldOption;
};

HeartbeatGuard::HeartbeatGuard(SdoClient& sdo, uint8_t node, int axis, QObject* parent)
    : QObject(parent), sdo_(sdo), node_(node), axis_(axis) {}

HeartbeatGuard::~HeartbeatGuard() = default;

QString HeartbeatGuard::prefix() const {
    return axis_ ? QStringLiteral("node %1 axis %2").arg(node_).arg(axis_) : QStringLiteral("node %1").arg(node_);
}

QString HeartbeatGuard::abortOptionName(int16_t code) {
    switch (code) {
    case 0: return QStringLiteral("no action");
    case 1: return QStringLiteral("fault signal");
    case 2: return QStringLiteral("disable voltage");
    case 3: return QStringLiteral("quick stop");
    default: return code < 0 ? QStringLiteral("manufacturer-specific") : QStringLiteral("reserved");
    }
}

uint16_t HeartbeatGuard::consumerTimeFor(uint16_t periodMs) {
    const uint32_t t = 3u * periodMs;
    return t > 0xFFFF ? 0 : static_cast<uint16_t>(t);
}

void HeartbeatGuard::finish(const HeartbeatGuardCallback& done, HeartbeatGuardResult r) {
    busy_ = false;
    changing_ = false;
    if (!done) return;
    // Always later, never from inside arm()/release().
    QMetaObject::invokeMethod(
        this, [done, r] { done(r); }, Qt::QueuedConnection);
}

void HeartbeatGuard::write(uint16_t index, uint8_t sub, const QByteArray& data, const QString& what, SdoCallback then) {
    // As Ds402Controller reports its writes: "node 3: 1016h:01 = ...", "node 3: 6007h = ...".
    const QString object = QStringLiteral("%1").arg(index, 4, 16, QChar(u'0')).toUpper() + u'h';
    if (onSend_)
        onSend_(QStringLiteral("%1: %2 = %3").arg(prefix(), sub ? object + u':' + subText(sub) : object, what));
    sdo_.download(node_, index, sub, data, std::move(then));
}

void HeartbeatGuard::arm(const HeartbeatProducer& producer, HeartbeatGuardCallback done) {
    HeartbeatGuardResult fail;
    if (busy_) fail.error = QStringLiteral("%1: the heartbeat guard is busy").arg(prefix());
    else if (armed_) fail.error = QStringLiteral("%1: the heartbeat guard is already armed").arg(prefix());
    else if (!producer.isRunning())
        fail.error =
            QStringLiteral("%1: CoScope's heartbeat is not running; start it before arming the guard (nothing changed)")
                .arg(prefix());
    const uint16_t time = consumerTimeMs_ ? consumerTimeMs_ : consumerTimeFor(producer.periodMs());
    if (fail.error.isEmpty() && time <= producer.periodMs())
        fail.error = QStringLiteral(
                         "%1: a consumer time of %2 ms does not cover the heartbeat period of %3 ms (use at least "
                         "twice the period; nothing changed)")
                         .arg(prefix())
                         .arg(time)
                         .arg(producer.periodMs());
    if (!fail.error.isEmpty()) {
        finish(done, fail);
        return;
    }
    busy_ = true;
    auto a = std::make_shared<Arming>();
    a->done = std::move(done);
    a->producer = producer.nodeId();
    a->timeMs = time;
    QPointer<HeartbeatGuard> self(this);
    // 1016h:00, the number of consumer entries.
    sdo_.upload(node_, 0x1016, 0, [self, a](const SdoResult& r) {
        if (!self) return;
        HeartbeatGuardResult out;
        if (!r.ok || r.data.isEmpty()) {
            out.error =
                missing(r)
                    ? QStringLiteral(
                          "%1 has no heartbeat consumer (1016h): it cannot watch CoScope's heartbeat (nothing changed)")
                          .arg(self->prefix())
                    : r.error + QStringLiteral(" (nothing changed)");
            self->finish(a->done, out);
            return;
        }
        const uint8_t count = static_cast<uint8_t>(r.data[0]);
        if (count == 0) {
            out.error = QStringLiteral("%1 has no heartbeat consumer entries (1016h:00 = 0; nothing changed)")
                            .arg(self->prefix());
            self->finish(a->done, out);
            return;
        }
        a->count = count;
        self->readEntries(a, 1);
    });
}

void HeartbeatGuard::readEntries(std::shared_ptr<Arming> a, uint8_t sub) {
    QPointer<HeartbeatGuard> self(this);
    sdo_.upload(node_, 0x1016, sub, [self, a, sub](const SdoResult& r) {
        if (!self) return;
        if (!r.ok) {
            HeartbeatGuardResult out;
            out.error = r.error + QStringLiteral(" (nothing changed)");
            self->finish(a->done, out);
            return;
        }
        a->entries.push_back(readLe(r.data));
        if (a->entries.size() < a->count) {
            self->readEntries(a, static_cast<uint8_t>(sub + 1));
            return;
        }
        // The entry already watching CoScope's node-ID, else the first free one.
        for (size_t i = 0; i < a->entries.size() && !a->sub; ++i)
            if (inUse(a->entries[i]) && producerOf(a->entries[i]) == a->producer) a->sub = static_cast<uint8_t>(i + 1);
        for (size_t i = 0; i < a->entries.size() && !a->sub; ++i)
            if (!inUse(a->entries[i])) a->sub = static_cast<uint8_t>(i + 1);
        if (!a->sub) {
            QStringList watched;
            for (uint32_t e : a->entries) watched << QString::number(producerOf(e));
            HeartbeatGuardResult out;
            out.error =
                QStringLiteral(
                    "%1: all %2 heartbeat consumer entries (1016h) are in use, watching node %3 (nothing changed)")
                    .arg(self->prefix())
                    .arg(a->entries.size())
                    .arg(watched.join(QStringLiteral(", ")));
            self->finish(a->done, out);
            return;
        }
        self->readAbortOption(a);
    });
}

void HeartbeatGuard::readAbortOption(std::shared_ptr<Arming> a) {
    QPointer<HeartbeatGuard> self(this);
    sdo_.upload(node_, abortIndex(), 0, [self, a](const SdoResult& r) {
        if (!self) return;
        const uint32_t raw = readLe(r.data.left(2));
        if (r.ok && !r.data.isEmpty())
            a->oldOption =
                r.data.size() >= 2 ? static_cast<int16_t>(raw) : static_cast<int16_t>(static_cast<int8_t>(raw));
        else if (!missing(r)) {
            HeartbeatGuardResult out;
            out.error = r.error + QStringLiteral(" (nothing changed)");
            self->finish(a->done, out);
            return;
        }
        self->writeAll(a);
    });
}

std::vector<DirectDownload> HeartbeatGuard::putBackWrites() const {
    std::vector<DirectDownload> out;
    if (!armed_ && !changing_) return out;
    out.push_back(DirectDownload::of(node_, 0x1016, sub_, le(oldEntry_, 4)));
    if (oldAbortOption_) out.push_back(DirectDownload::of(node_, abortIndex(), 0, le(uint16_t(*oldAbortOption_), 2)));
    return out;
}

void HeartbeatGuard::writeAll(std::shared_ptr<Arming> a) {
    QPointer<HeartbeatGuard> self(this);
    const uint32_t entry = (uint32_t(a->producer) << 16) | a->timeMs;
    const uint32_t old = a->entries[a->sub - 1];
    // Known from here on, for a put-back while the writes are under way (putBackWrites()).
    changing_ = true;
    sub_ = a->sub;
    oldEntry_ = old;
    oldAbortOption_ = a->oldOption;
    auto writeConsumer = [self, a, entry, old]() {
        self->write(
            0x1016, a->sub, le(entry, 4),
            QStringLiteral("%1 (watch node %2's heartbeat, %3 ms)").arg(hex32(entry)).arg(a->producer).arg(a->timeMs),
            [self, a, entry, old](const SdoResult& r) {
                if (!self) return;
                HeartbeatGuardResult out;
                out.consumerSub = a->sub;
                out.consumerEntry = entry;
                if (!r.ok) {
                    out.error = r.error;
                    if (!a->oldOption) {
                        out.error += QStringLiteral(" (nothing changed)");
                        self->finish(a->done, out);
                        return;
                    }
                    // Put 6007h back; what that write says ends the report.
                    const int16_t back = *a->oldOption;
                    self->write(self->abortIndex(), 0, le(uint16_t(back), 2),
                                QStringLiteral("%1 (%2, put back)").arg(back).arg(abortOptionName(back)),
                                [self, a, out](const SdoResult& b) mutable {
                                    if (!self) return;
                                    out.error += b.ok ? QStringLiteral("; 6007h put back")
                                                      : QStringLiteral("; putting 6007h back failed: ") + b.error;
                                    self->finish(a->done, out);
                                });
                    return;
                }
                self->armed_ = true;
                self->sub_ = a->sub;
                self->oldEntry_ = old;
                self->newEntry_ = entry;
                self->oldAbortOption_ = a->oldOption;
                out.ok = true;
                if (a->oldOption) out.abortOption = self->abortOption_;
                const QString reaction =
                    a->oldOption ? QStringLiteral("6007h = %1 (%2)")
                                       .arg(self->abortOption_)
                                       .arg(abortOptionName(self->abortOption_))
                                 : QStringLiteral("no 6007h, so the drive's own reaction: %1")
                                       .arg(makersReaction(self->sdo_.context().nodeDictionary(self->node_)));
                out.summary =
                    QStringLiteral("%1 watches CoScope's heartbeat (node %2) in 1016h:%3 with %4 ms; when it stops: %5")
                        .arg(self->prefix())
                        .arg(a->producer)
                        .arg(subText(a->sub))
                        .arg(a->timeMs)
                        .arg(reaction);
                self->finish(a->done, out);
            });
    };
    if (!a->oldOption) {
        writeConsumer();
        return;
    }
    // 6007h first: the reaction is in place before the drive starts watching.
    write(abortIndex(), 0, le(uint16_t(abortOption_), 2),
          QStringLiteral("%1 (%2 when CoScope's heartbeat stops)").arg(abortOption_).arg(abortOptionName(abortOption_)),
          [self, a, writeConsumer](const SdoResult& r) {
              if (!self) return;
              if (!r.ok) {
                  HeartbeatGuardResult out;
                  out.error = r.error + QStringLiteral(" (nothing changed)");
                  self->finish(a->done, out);
                  return;
              }
              writeConsumer();
          });
}

void HeartbeatGuard::release(HeartbeatGuardCallback done) {
    HeartbeatGuardResult r;
    if (busy_) {
        r.error = QStringLiteral("%1: the heartbeat guard is busy").arg(prefix());
        finish(done, r);
        return;
    }
    if (!armed_) {
        r.ok = true;
        finish(done, r);
        return;
    }
    busy_ = true;
    r.consumerSub = sub_;
    r.consumerEntry = oldEntry_;
    QPointer<HeartbeatGuard> self(this);
    auto finished = [self, done](HeartbeatGuardResult out) {
        if (!self) return;
        self->armed_ = false;
        out.ok = true;
        out.summary =
            QStringLiteral("%1: heartbeat consumer 1016h:%2 = %3%4 put back")
                .arg(self->prefix(), subText(self->sub_), hex32(self->oldEntry_))
                .arg(self->oldAbortOption_ ? QStringLiteral(" and 6007h = %1").arg(*self->oldAbortOption_) : QString());
        self->finish(done, out);
    };
    // The entry first: the drive stops watching before its reaction changes.
    write(0x1016, sub_, le(oldEntry_, 4), QStringLiteral("%1 (put back)").arg(hex32(oldEntry_)),
          [self, done, r, finished](const SdoResult& w) {
              if (!self) return;
              if (!w.ok) {
                  HeartbeatGuardResult out = r;
                  out.error = w.error + QStringLiteral(" (the guard stays armed)");
                  self->finish(done, out);
                  return;
              }
              if (!self->oldAbortOption_) {
                  finished(r);
                  return;
              }
              const int16_t back = *self->oldAbortOption_;
              self->write(self->abortIndex(), 0, le(uint16_t(back), 2),
                          QStringLiteral("%1 (%2, put back)").arg(back).arg(abortOptionName(back)),
                          [self, done, r, finished](const SdoResult& b) {
                              if (!self) return;
                              if (!b.ok) {
                                  HeartbeatGuardResult out = r;
                                  out.error = b.error + QStringLiteral(" (1016h was put back; 6007h was not)");
                                  self->finish(done, out);
                                  return;
                              }
                              finished(r);
                          });
          });
}

}  // namespace coscope::canopen
