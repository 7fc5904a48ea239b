// SPDX-License-Identifier: GPL-3.0-or-later
// moveTo() of Ds402Controller: a profile position move (CiA 402-2 §12; Delta extract §4.5.1,
// AIMOTOR extract §4.6 A) with the set-point handshake: 607Ah, controlword bit 4 rising (bit 5
// change set immediately, bit 6 relative), statusword bit 12 set-point acknowledge, bit 4 low,
// statusword bit 10 target reached.
#include "core/canopen/Ds402Controller.h"

#include <QElapsedTimer>
#include <QPointer>
#include <QTimer>

namespace coscope::canopen {

namespace {
QByteArray moveLe32(uint32_t v) {
    QByteArray b(4, 0);
    for (int i = 0; i < 4; ++i) b[i] = static_cast<char>((v >> (8 * i)) & 0xFF);
    return b;
}
constexpr uint16_t kSetPointAcknowledge = 1u << 12, kFollowingError = 1u << 13;
}  // namespace

void Ds402Controller::moveTo(const Ds402PositionMove& move, std::function<void(const Ds402MotionSample&)> progress,
                             Ds402Callback done) {
    auto check = [](const Ds402MotionSample& s) -> QString {
        if (s.statusword & kFollowingError)
            return QStringLiteral("following error (statusword 0x%1 bit 13)").arg(s.statusword, 4, 16, QChar(u'0'));
        if ((s.statusword & ds402::sw::TargetReached) && !(s.statusword & kSetPointAcknowledge))
            return QStringLiteral("ok");
        return {};
    };
    auto m = beginMotion(false, move.timeoutMs, std::move(progress), std::move(done), check, nullptr);
    if (!m) return;
    QPointer<Ds402Controller> self(this);
    const uint16_t bits = uint16_t((move.relative ? 0x40 : 0) | (move.immediate ? 0x20 : 0));
    const QString how =
        QStringLiteral("%1%2").arg(move.relative ? QStringLiteral("relative") : QStringLiteral("absolute"),
                                   move.immediate ? QStringLiteral(", change set immediately") : QString());
    auto steps = std::make_shared<std::vector<MotionStep>>();
    steps->push_back(modeStep(1));
    if (move.velocity)
        steps->push_back(writeStep(0x6081, 0, moveLe32(*move.velocity),
                                   QStringLiteral("%1 (profile velocity)").arg(*move.velocity)));
    if (move.acceleration)
        steps->push_back(writeStep(0x6083, 0, moveLe32(*move.acceleration),
                                   QStringLiteral("%1 (profile acceleration)").arg(*move.acceleration)));
    if (move.deceleration)
        steps->push_back(writeStep(0x6084, 0, moveLe32(*move.deceleration),
                                   QStringLiteral("%1 (profile deceleration)").arg(*move.deceleration)));
    steps->push_back(writeStep(0x607A, 0, moveLe32(uint32_t(move.target)),
                               QStringLiteral("%1 (target position, %2)").arg(move.target).arg(how)));
    steps->push_back(enableStep());
    steps->push_back(
        controlwordStep(uint16_t(0x000F | bits), QStringLiteral("Enable operation, new set-point (bit 4) low")));
    const size_t start = steps->size();
    steps->push_back(
        controlwordStep(uint16_t(0x001F | bits), QStringLiteral("New set-point (bit 4 rising), %1").arg(how)));
    // Wait for set-point acknowledge (bit 12), then bit 4 low (the handshake, §12.2).
    steps->push_back([self, m](std::function<void(const QString&)> next) {
        auto since = std::make_shared<QElapsedTimer>();
        since->start();
        auto poll = std::make_shared<std::function<void()>>();
        *poll = [self, m, next, since, poll] {
            if (!self || self->motion_ != m) return;
            self->readState([self, m, next, since, poll](const Ds402Result& st) {
                if (!self || self->motion_ != m) return;
                if (!st.ok || (st.statusword & ds402::sw::Fault) || (st.statusword & kSetPointAcknowledge) ||
                    since->elapsed() > self->timeoutMs_) {
                    auto n = next;
                    *poll = nullptr;
                    if (!st.ok) return n(st.error);
                    if (st.statusword & kSetPointAcknowledge) return n({});
                    if (st.statusword & ds402::sw::Fault)
                        return n(QStringLiteral("%1 faulted after the new set-point (statusword 0x%2)")
                                     .arg(self->prefix())
                                     .arg(st.statusword, 4, 16, QChar(u'0')));
                    return n(QStringLiteral(
                                 "%1 did not acknowledge the set-point (statusword 0x%2, bit 12 not set within %3 ms)")
                                 .arg(self->prefix())
                                 .arg(st.statusword, 4, 16, QChar(u'0'))
                                 .arg(self->timeoutMs_));
                }
                QTimer::singleShot(self->pollMs_, self, [poll] {
                    if (*poll) (*poll)();
                });
            });
        };
        (*poll)();
    });
    steps->push_back(
        controlwordStep(uint16_t(0x000F | bits), QStringLiteral("Set-point acknowledged: new set-point (bit 4) low")));
    motionSteps(m, steps, 0, start);
}

}  // namespace coscope::canopen
