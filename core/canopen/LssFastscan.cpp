// SPDX-License-Identifier: GPL-3.0-or-later
// LSS Fastscan of LssMaster (CiA 305 §6.7.4), tolerant of slaves that answer late.
#include "core/canopen/Lss.h"
#include "core/canopen/LssMaster.h"

#include <QPointer>

#include <algorithm>

namespace coscope::canopen {

namespace {
constexpr int kMaxRestarts = 3;
}  // namespace

struct FastscanState {
    uint32_t id[4] = {};
    int sub = 0;   // LSSSub 0..3: vendor, product, revision, serial
    int bit = 31;  // bit being determined; 0 = confirm the field (bit 0 tried as 0, then as 1)
    bool triedOne = false;
    int windowMs = 0;  // how long a step waits for "some slave matches"
    int restarts = 0;
};

void LssMaster::fastscan(LssCallback done) {
    auto st = std::make_shared<FastscanState>();
    st->windowMs = fastscanMs_;
    fastscanReset(st, done);
}

void LssMaster::fastscanReset(std::shared_ptr<FastscanState> st, LssCallback done) {
    // BitChecked = 80h resets the slaves' fastscan; every unconfigured one answers. The time to
    // the first answer sets the window of the bit steps (at least the configured timeout).
    // Every answer within the window belongs to this request, so late duplicates from the other
    // slaves cannot be taken for a match of the next step.
    std::fill(std::begin(st->id), std::end(st->id), 0u);
    st->sub = 0;
    st->bit = 31;
    st->triedOne = false;
    Request r;
    r.frame = request(lss::Fastscan, {0, 0, 0, 0, 0x80, 0, 0});
    r.expectCs = lss::IdentifySlaveResponse;
    r.timeoutMs = std::max(timeoutMs_, st->windowMs);
    r.graceMs = st->windowMs;
    QPointer<LssMaster> self(this);
    r.then = [self, st, done](bool answered, const CanFrame&) {
        if (!self) return;
        if (!answered) {
            LssResult out;
            out.noSlave = self->sendError_.isEmpty();
            out.error = self->noAnswer(QStringLiteral("no unconfigured LSS slave answered fastscan"));
            return done(out);
        }
        st->windowMs = std::clamp(2 * self->lastRttMs_ + 5, st->windowMs, std::max(self->timeoutMs_, st->windowMs));
        self->fastscanStep(st, done);
    };
    enqueue(std::move(r));
}

void LssMaster::fastscanRetry(std::shared_ptr<FastscanState> st, LssCallback done, const QString& why) {
    // Silence read as a 1-bit when the answer was only late, or a late answer counted for the
    // next bit: the confirmation fails. Scan again with a wider window.
    if (st->restarts >= kMaxRestarts) {
        LssResult out;
        out.error = noAnswer(why);
        return done(out);
    }
    ++st->restarts;
    st->windowMs = std::min(st->windowMs * 3, std::max(timeoutMs_, st->windowMs));
    fastscanReset(st, done);
}

void LssMaster::fastscanStep(std::shared_ptr<FastscanState> st, LssCallback done) {
    // Bits 31..1 of each field: guess 0; a slave answering means its bits down to `bit` match,
    // silence means the bit is 1. Bit 0 is found by the confirmation itself (BitChecked 0,
    // LSSNext = next field): a slave answers only on a full match, first trying 0, then 1.
    Request r;
    r.frame = request(lss::Fastscan);
    const bool confirm = st->bit == 0;
    putLe32(r.frame, 1, st->id[st->sub]);
    r.frame.data[5] = static_cast<uint8_t>(st->bit);
    r.frame.data[6] = static_cast<uint8_t>(st->sub);
    r.frame.data[7] = static_cast<uint8_t>(confirm ? (st->sub + 1) % 4 : st->sub);
    r.expectCs = lss::IdentifySlaveResponse;
    r.timeoutMs = st->windowMs;
    r.graceMs = std::max(2, st->windowMs / 4);
    QPointer<LssMaster> self(this);
    r.then = [self, st, done, confirm](bool answered, const CanFrame&) {
        if (!self) return;
        if (confirm) {
            if (!answered) {
                if (!st->triedOne) {
                    st->triedOne = true;
                    st->id[st->sub] |= 1u;
                    return self->fastscanStep(st, done);
                }
                return self->fastscanRetry(st, done,
                                           QStringLiteral("fastscan: no slave confirmed field %1 = 0x%2")
                                               .arg(st->sub)
                                               .arg(st->id[st->sub], 8, 16, QChar(u'0')));
            }
            if (st->sub == 3) {
                LssResult out;
                out.ok = true;
                out.identity = {st->id[0], st->id[1], st->id[2], st->id[3]};
                return done(out);
            }
            ++st->sub;
            st->bit = 31;
            st->triedOne = false;
            return self->fastscanStep(st, done);
        }
        if (!answered) st->id[st->sub] |= (1u << st->bit);
        --st->bit;
        self->fastscanStep(st, done);
    };
    enqueue(std::move(r));
}

}  // namespace coscope::canopen
