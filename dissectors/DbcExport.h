// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "dissectors/NetworkContext.h"
#include "dissectors/RawSignal.h"

#include <QByteArray>

#include <vector>

namespace coscope::dissect {

// The PDO layout in force in `ctx` (dictionary defaults, then what SDO writes in the trace or
// a wizard changed) on bus `bus` as a DBC file (Vector CANdb++ text, as cantools, SavvyCAN and
// Cabana read it): one BO_ per valid TPDO/RPDO with a known mapping, the mapped objects as
// SG_ signals in Intel order at their bit positions (CiA 301 §7.2.2.4: LSB first), scaled by
// the dictionary's units; CM_ comments give the PDO and each signal's object index:sub.
// PDOs whose COB-ID was never seen written use the predefined connection set (CiA 301
// §7.3.5: TPDOn = 180h + 100h x (n - 1) + node-ID, RPDOn = 200h + ...). The user's raw
// signals join the message of their COB-ID, or get one of their own.
// Nodes: those seen in the trace or given a dictionary. `pdos`, when given, counts the PDO
// messages written.
QByteArray pdoLayoutDbc(const NetworkContext& ctx, const std::vector<RawSignal>& raw = {}, int bus = 0,
                        int* pdos = nullptr);

// A DBC identifier (C identifier) from a display name: "Position actual value" -> Position_actual_value.
QByteArray dbcIdentifier(const QString& name);

}  // namespace coscope::dissect
