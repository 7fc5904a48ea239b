// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

namespace coscope::gui {

class Workspace;

// `coscope --simulate`: brings the virtual network to life the way a commissioning master
// would, so the views have something to show: once the sim:// bus is open it scans the nodes
// (SDO reads of 1000h, 1008h, 1018h), sets each node's producer heartbeat time 1017h to
// 500 ms and starts all nodes (NMT Start, CiA 301 §7.2.8.3.1). It refuses to touch anything
// but a sim:// bus that may transmit.
void startSimulationDemo(Workspace* ws);

}  // namespace coscope::gui
