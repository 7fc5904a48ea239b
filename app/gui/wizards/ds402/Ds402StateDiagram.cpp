// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/wizards/ds402/Ds402StateDiagram.h"

#include "app/gui/language/CoreText.h"

#include <QPainter>
#include <QPainterPath>
#include <QtMath>

#include <QCoreApplication>

namespace coscope::gui {

using canopen::ds402::Command;
using canopen::ds402::State;

namespace {
constexpr double kBoxW = 0.36, kBoxH = 0.105;  // fractions of the widget size

// Row and column of each state in the usual drawing of Figure 19.
QPointF cellOf(State s) {
    switch (s) {
    case State::NotReadyToSwitchOn: return {0, 0};
    case State::SwitchOnDisabled: return {0, 1};
    case State::ReadyToSwitchOn: return {0, 2};
    case State::SwitchedOn: return {0, 3};
    case State::OperationEnabled: return {0, 4};
    case State::FaultReactionActive: return {1, 0};
    case State::Fault: return {1, 1};
    case State::QuickStopActive: return {1, 4};
    case State::Unknown: break;
    }
    return {-1, -1};
}

void arrow(QPainter& p, QPointF a, QPointF b, const QString& label, bool lit, QPointF labelOffset = {4, 0}) {
    p.save();
    QPen pen(lit ? QColor(0, 110, 230) : QColor(110, 110, 110), lit ? 2.6 : 1.2);
    p.setPen(pen);
    p.drawLine(a, b);
    const double ang = std::atan2(b.y() - a.y(), b.x() - a.x());
    const double len = lit ? 10 : 8;
    QPolygonF head;
    head << b << b - QPointF(len * std::cos(ang - 0.4), len * std::sin(ang - 0.4))
         << b - QPointF(len * std::cos(ang + 0.4), len * std::sin(ang + 0.4));
    p.setBrush(pen.color());
    p.drawPolygon(head);
    QFont f = p.font();
    f.setPointSizeF(f.pointSizeF() * 0.85);
    f.setBold(lit);
    p.setFont(f);
    p.drawText((a + b) / 2 + labelOffset + QPointF(0, 4), label);
    p.restore();
}
}  // namespace

std::optional<int> ds402TransitionNumber(State from, Command c) {
    switch (from) {
    case State::SwitchOnDisabled: return c == Command::Shutdown ? std::optional<int>(2) : std::nullopt;
    case State::ReadyToSwitchOn:
        if (c == Command::SwitchOn || c == Command::SwitchOnAndEnable || c == Command::EnableOperation) return 3;
        if (c == Command::DisableVoltage || c == Command::QuickStop) return 7;
        return std::nullopt;
    case State::SwitchedOn:
        if (c == Command::EnableOperation) return 4;
        if (c == Command::Shutdown) return 6;
        if (c == Command::DisableVoltage || c == Command::QuickStop) return 10;
        return std::nullopt;
    case State::OperationEnabled:
        if (c == Command::DisableOperation || c == Command::SwitchOn) return 5;
        if (c == Command::Shutdown) return 8;
        if (c == Command::DisableVoltage) return 9;
        if (c == Command::QuickStop) return 11;
        return std::nullopt;
    case State::QuickStopActive:
        if (c == Command::DisableVoltage) return 12;
        if (c == Command::EnableOperation) return 16;
        return std::nullopt;
    case State::Fault: return c == Command::FaultReset ? std::optional<int>(15) : std::nullopt;
    default: return std::nullopt;
    }
}

Ds402StateDiagram::Ds402StateDiagram(QWidget* parent) : QWidget(parent) {
    setObjectName(QStringLiteral("ds402StateDiagram"));
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Expanding);
}

void Ds402StateDiagram::setState(State s) {
    if (s == state_) return;
    state_ = s;
    update();
}

void Ds402StateDiagram::setNextTransition(std::optional<int> n) {
    if (n == next_) return;
    next_ = n;
    update();
}

QRectF Ds402StateDiagram::boxOf(State s) const {
    const QPointF c = cellOf(s);
    if (c.x() < 0) return {};
    const double w = width() * kBoxW, h = height() * kBoxH;
    const double x = c.x() == 0 ? width() * 0.06 : width() * 0.60;
    const double y = height() * (0.05 + c.y() * 0.2);
    return {x, y, w, h};
}

void Ds402StateDiagram::paintEvent(QPaintEvent*) {
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    p.fillRect(rect(), palette().base());
    auto lit = [this](int n) { return next_ && *next_ == n; };
    auto top = [this](State s) {
        const QRectF r = boxOf(s);
        return QPointF(r.center().x(), r.top());
    };
    auto bottom = [this](State s) {
        const QRectF r = boxOf(s);
        return QPointF(r.center().x(), r.bottom());
    };
    const double dx = width() * 0.05;
    // Down the left column: 1, 2, 3, 4 (left of centre); back up: 7, 6, 5 (right of centre).
    const State chain[] = {State::NotReadyToSwitchOn, State::SwitchOnDisabled, State::ReadyToSwitchOn,
                           State::SwitchedOn, State::OperationEnabled};
    const int down[] = {1, 2, 3, 4}, up[] = {0, 7, 6, 5};
    for (int i = 0; i < 4; ++i) {
        arrow(p, bottom(chain[i]) - QPointF(dx, 0), top(chain[i + 1]) - QPointF(dx, 0), QString::number(down[i]),
              lit(down[i]), {-18, 0});
        if (up[i])
            arrow(p, top(chain[i + 1]) + QPointF(dx, 0), bottom(chain[i]) + QPointF(dx, 0), QString::number(up[i]),
                  lit(up[i]));
    }
    // 11 / 16 between Operation enabled and Quick stop active.
    const QRectF oe = boxOf(State::OperationEnabled), qs = boxOf(State::QuickStopActive);
    arrow(p, QPointF(oe.right(), oe.center().y() - 5), QPointF(qs.left(), qs.center().y() - 5), QStringLiteral("11"),
          lit(11), {-6, -8});
    arrow(p, QPointF(qs.left(), qs.center().y() + 7), QPointF(oe.right(), oe.center().y() + 7), QStringLiteral("16"),
          lit(16), {-6, 14});
    // 12: Quick stop active back to Switch on disabled (up the right side of the picture).
    const QRectF sod = boxOf(State::SwitchOnDisabled), fr = boxOf(State::FaultReactionActive), fa = boxOf(State::Fault);
    {
        p.save();
        const bool on = lit(12);
        p.setPen(QPen(on ? QColor(0, 110, 230) : QColor(110, 110, 110), on ? 2.6 : 1.2));
        const double xr = qs.center().x() + qs.width() * 0.25;
        const double ymid = (sod.bottom() + boxOf(State::ReadyToSwitchOn).top()) / 2 + height() * 0.03;
        p.drawLine(QPointF(xr, qs.top()), QPointF(xr, ymid));
        p.restore();
        arrow(p, QPointF(xr, ymid), QPointF(sod.right(), sod.bottom() - 2), QStringLiteral("12"), on, {10, 12});
    }
    // Fault: 13 (from any state), 14, 15.
    arrow(p, QPointF(fr.center().x(), 2), QPointF(fr.center().x(), fr.top()),
          QCoreApplication::translate("Ds402StateDiagram", "13 any fault"), false);
    arrow(p, QPointF(fr.center().x(), fr.bottom()), QPointF(fa.center().x(), fa.top()), QStringLiteral("14"), lit(14));
    arrow(p, QPointF(fa.left(), fa.center().y()), QPointF(sod.right(), sod.center().y()), QStringLiteral("15"), lit(15),
          {-8, -8});

    // The boxes on top.
    for (State s : {State::NotReadyToSwitchOn, State::SwitchOnDisabled, State::ReadyToSwitchOn, State::SwitchedOn,
                    State::OperationEnabled, State::QuickStopActive, State::FaultReactionActive, State::Fault}) {
        const QRectF r = boxOf(s);
        const bool current = s == state_;
        const bool fault = s == State::Fault || s == State::FaultReactionActive;
        QColor fill = palette().window().color();
        if (current)
            fill = fault                          ? QColor(220, 50, 40)
                   : s == State::OperationEnabled ? QColor(40, 170, 70)
                                                  : QColor(250, 200, 40);
        p.setPen(QPen(current ? QColor(20, 20, 20) : QColor(120, 120, 120), current ? 2.5 : 1));
        p.setBrush(fill);
        p.drawRoundedRect(r, 6, 6);
        QFont f = font();
        f.setBold(current);
        p.setFont(f);
        p.setPen(current && (fault || s == State::OperationEnabled) ? Qt::white : palette().text().color());
        p.drawText(r, Qt::AlignCenter | Qt::TextWordWrap, coreText(canopen::ds402::stateName(s)));
    }
    if (state_ == State::Unknown) {
        p.setPen(palette().placeholderText().color());
        p.drawText(QRectF(width() * 0.5, height() * 0.45, width() * 0.5, height() * 0.2),
                   Qt::AlignCenter | Qt::TextWordWrap, tr("State not read yet"));
    }
}

}  // namespace coscope::gui
