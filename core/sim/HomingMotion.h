// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/canopen/HomingMethods.h"

#include <vector>

namespace coscope::sim {

// The machine a virtual drive homes on, in machine position units (the drive's position units
// before any homing): limit switches, a home switch with two edges, an index pulse once per
// motor revolution and mechanical end stops beyond the limit switches. Simulator conventions,
// in revolutions of the motor: limit switches active at -1.0 and below / +1.0 and above, home
// switch active from +0.20 to +0.35, index pulse at 0.10 + k, end stops at -1.2 and +1.2. A
// one-edge home switch (CiA 402-2 methods 3-6, 19-22) uses the lower edge at +0.20, active
// above it (positive home switch) or below it (negative home switch).
struct HomingMachine {
    double limit = 0;
    double homeLow = 0, homeHigh = 0;
    double indexPhase = 0;
    double perRevolution = 1;
    double hardStop = 0;
    double backOff = 0;  // how far past an edge a slow approach starts

    static HomingMachine forRevolution(double rev);
    // The first index pulse strictly beyond `from` in direction `dir` (+1/-1).
    double nextIndex(double from, int dir) const;
};

// One stretch of a homing run: to a machine position at the fast (6099h:01) or slow (6099h:02)
// speed; `endStop` stretches end on the mechanical end stop (hard-stop homing).
struct HomingLeg {
    double to = 0;
    bool slow = false;
    bool endStop = false;
};

// The path a method takes from machine position `start`: out to its switch (reversing at a limit
// switch where the method does), back off, and onto home. Empty for "current position".
std::vector<HomingLeg> homingPath(const canopen::homing::Method& method, double start, const HomingMachine& g);

}  // namespace coscope::sim
