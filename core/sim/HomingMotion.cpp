// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/sim/HomingMotion.h"

#include <cmath>

namespace coscope::sim {

using canopen::homing::Method;
using canopen::homing::Reference;

HomingMachine HomingMachine::forRevolution(double rev) {
    HomingMachine m;
    m.perRevolution = rev;
    m.limit = 1.0 * rev;
    m.homeLow = 0.20 * rev;
    m.homeHigh = 0.35 * rev;
    m.indexPhase = 0.10 * rev;
    m.hardStop = 1.2 * rev;
    m.backOff = 0.02 * rev;
    return m;
}

double HomingMachine::nextIndex(double from, int dir) const {
    // Index pulses at indexPhase + k * perRevolution; "strictly beyond" keeps a drive sitting on
    // one from taking it without moving.
    const double k = (from - indexPhase) / perRevolution;
    double n = dir > 0 ? std::floor(k) + 1 : std::ceil(k) - 1;
    return indexPhase + n * perRevolution;
}

std::vector<HomingLeg> homingPath(const Method& m, double start, const HomingMachine& g) {
    std::vector<HomingLeg> legs;
    // After the edge E was reached: onto the index pulse on the home side, or back off and
    // approach E slowly from the home side (CiA 402-2 §13 figures).
    auto finish = [&](double edge) {
        if (m.index) {
            legs.push_back({g.nextIndex(edge, m.homeSide), true, false});
        } else {
            legs.push_back({edge + m.homeSide * g.backOff, true, false});
            legs.push_back({edge, true, false});
        }
    };
    switch (m.reference) {
    case Reference::None:
    case Reference::CurrentPosition: break;
    case Reference::LimitSwitch: {
        const double edge = m.switchSide * g.limit;
        legs.push_back({edge, false, false});
        finish(edge);
        break;
    }
    case Reference::HomeSwitch: {
        // One edge; the switch state at the start gives the direction, which is towards the edge
        // whichever side the switch is active on.
        const double edge = g.homeLow;
        legs.push_back({edge, false, false});
        finish(edge);
        break;
    }
    case Reference::HomeCam: {
        // Fixed first direction; the limit switch on the way reverses the search.
        const double edge = m.edge == 1 ? g.homeLow : g.homeHigh;
        if ((edge - start) * m.direction <= 0) legs.push_back({m.direction * g.limit, false, false});
        legs.push_back({edge, false, false});
        finish(edge);
        break;
    }
    case Reference::IndexPulse: {
        const double index = g.nextIndex(start, m.direction);
        if (m.homeSide != 0)
            legs.push_back({index + m.homeSide * g.backOff, true, false});  // past it, then back onto it
        legs.push_back({index, true, false});
        break;
    }
    case Reference::HardStop: legs.push_back({m.direction * g.hardStop, true, true}); break;
    }
    return legs;
}

}  // namespace coscope::sim
