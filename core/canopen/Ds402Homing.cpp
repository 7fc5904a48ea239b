// SPDX-License-Identifier: GPL-3.0-or-later
// home() of Ds402Controller: homing mode (CiA 402-2 §13) as the Delta (extract-delta §4.5.3)
// and AIMOTOR (extract-aimotor §4.6 C) manuals do it: 6060h = 6, 607Ch, 6098h, 6099h:01/02,
// 609Ah, then 6040h 06 -> 07 -> 0F -> 1F and statusword bits 12 (homing attained) / 13 (homing
// error); bit 4 back low at the end.
#include "core/canopen/Ds402Controller.h"

#include <QPointer>

namespace coscope::canopen {

using ds402::Command;
using ds402::State;

namespace {
QByteArray homingLe32(uint32_t v) {
    QByteArray b(4, 0);
    for (int i = 0; i < 4; ++i) b[i] = static_cast<char>((v >> (8 * i)) & 0xFF);
    return b;
}
constexpr uint16_t kHomingAttained = 1u << 12, kHomingError = 1u << 13;
}  // namespace

void Ds402Controller::home(const Ds402HomingRequest& req, std::function<void(const Ds402MotionSample&)> progress,
                           Ds402Callback done) {
    auto check = [](const Ds402MotionSample& s) -> QString {
        // CiA 402-2 §13.1 bits 13/12/10: 1xx homing error, 011 homing attained (and target
        // reached), 000 in progress, 001 interrupted.
        if (s.statusword & kHomingError)
            return QStringLiteral("homing error (statusword 0x%1 bit 13)").arg(s.statusword, 4, 16, QChar(u'0'));
        if ((s.statusword & kHomingAttained) && (s.statusword & ds402::sw::TargetReached)) return QStringLiteral("ok");
        return {};
    };
    // Homed: bit 4 back low (the drive stays enabled).
    auto m = beginMotion(true, req.timeoutMs, std::move(progress), std::move(done), check,
                         controlwordStep(0x000F, QStringLiteral("Homing attained: homing start (bit 4) low")));
    if (!m) return;
    QPointer<Ds402Controller> self(this);
    auto steps = std::make_shared<std::vector<MotionStep>>();
    if (req.methodOnlyWhileDisabled) {
        // The drive takes a new method only while disabled (AIMOTOR, extract-aimotor §4.7):
        // when it is enabled with another method, Shutdown first (Ready to switch on).
        steps->push_back([self, method = req.method](std::function<void(const QString&)> next) {
            self->readState([self, method, next](const Ds402Result& st) {
                if (!self) return;
                if (!st.ok) return next(st.error);
                if (st.state != State::OperationEnabled) return next({});
                self->sdo_.upload(self->node_, self->objectIndex(0x6098), 0, [self, method, next](const SdoResult& r) {
                    if (!self) return;
                    if (!r.ok) return next(r.error);
                    if (!r.data.isEmpty() && static_cast<int8_t>(r.data[0]) == method) return next({});
                    self->transition(Command::Shutdown,
                                     [next](const Ds402Result& t) { next(t.ok ? QString() : t.error); });
                });
            });
        });
    }
    steps->push_back(modeStep(6));
    if (req.offset)
        steps->push_back(writeStep(0x607C, 0, homingLe32(uint32_t(*req.offset)),
                                   QStringLiteral("%1 (home offset)").arg(*req.offset)));
    steps->push_back(writeStep(0x6098, 0, QByteArray(1, static_cast<char>(req.method)),
                               QStringLiteral("%1 (homing method)").arg(req.method)));
    if (req.fastSpeed)
        steps->push_back(writeStep(0x6099, 1, homingLe32(*req.fastSpeed),
                                   QStringLiteral("%1 (speed during search for switch)").arg(*req.fastSpeed)));
    if (req.slowSpeed)
        steps->push_back(writeStep(0x6099, 2, homingLe32(*req.slowSpeed),
                                   QStringLiteral("%1 (speed during search for zero)").arg(*req.slowSpeed)));
    if (req.acceleration)
        steps->push_back(writeStep(0x609A, 0, homingLe32(*req.acceleration),
                                   QStringLiteral("%1 (homing acceleration)").arg(*req.acceleration)));
    steps->push_back(enableStep());
    // Bit 4 low first so that 1Fh is a rising edge whatever was sent before.
    steps->push_back(controlwordStep(0x000F, QStringLiteral("Enable operation, homing start (bit 4) low")));
    const size_t start = steps->size();
    steps->push_back(controlwordStep(0x001F, QStringLiteral("Homing operation start (bit 4 rising)")));
    motionSteps(m, steps, 0, start);
}

}  // namespace coscope::canopen
