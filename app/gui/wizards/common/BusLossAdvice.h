// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QCoreApplication>
#include <QString>

namespace coscope::canopen {
class NodeTable;
}

namespace coscope::gui {

// What a wizard says when the bus is lost while it works on a device (issue 16 "Lost adapter"):
// nothing more can be sent, so the device stays in whatever state the last frames left it in.
// The texts name the last known NMT state (CiA 301 §7.2.8.3.2, from the node table) and what to
// check; the CiA 402 wizard adds the drive's last state (CiA 402-2 §6.3).
class BusLossAdvice {
    Q_DECLARE_TR_FUNCTIONS(coscope::gui::BusLossAdvice)
public:
    // "NMT: Operational" or "NMT state unknown" for node `node` as the table last saw it.
    static QString lastNmtState(const canopen::NodeTable& nodes, int node);
    // The CiA 402 wizard: the drive's last state (ds402::stateName) and whether it may be powered.
    static QString driveMessage(const QString& reason, int node, const QString& nmt, const QString& lastDriveState,
                                bool mayBeEnabled);
    // A script run (PDO mapping, node-ID / bit rate, DCF) stopped at step `step` (0-based) of `steps`.
    static QString scriptMessage(const QString& reason, int step, int steps);
    // The PDO wizard's apply (CiA 301 §7.2.2.3: a PDO is disabled by COB-ID bit 31 while mapped).
    static QString pdoMessage(const QString& reason, int node, const QString& pdo, const QString& nmt);
    // The node-ID / bit-rate change (CiA 305 LSS or the vendor's objects, stored with 1010h).
    static QString settingsMessage(const QString& reason, int node, const QString& nmt);
};

}  // namespace coscope::gui
