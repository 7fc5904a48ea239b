// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QByteArray>
#include <QList>
#include <QString>

namespace coscope {

// A Linux CAN network interface as the kernel reports it (rtnetlink IFLA_CAN_*, shown by
// `ip -details -json link show`): used by the Connect dialog to list adapters with their state
// and bit rate, and to say how to bring one up.
struct SocketCanLink {
    QString name;             // can0, vcan0 ...
    QString kind;             // linkinfo.info_kind: can, vcan, vxcan, slcan ...
    bool up = false;          // administratively up (flag UP)
    QString controllerState;  // ERROR-ACTIVE, ERROR-WARNING, ERROR-PASSIVE, BUS-OFF, STOPPED, SLEEPING; empty for vcan
    int bitrate = 0;          // nominal bit rate, 0 = not set / virtual
    int dataBitrate = 0;      // CAN FD data phase, 0 = none
    bool fd = false;          // ctrlmode FD or MTU 72
    int txErrors = -1;        // berr_counter (TEC/REC), -1 = not reported
    int rxErrors = -1;
    bool isVirtual() const { return kind == u"vcan" || kind == u"vxcan"; }
};

// Parses the JSON that `ip -details -json link show` prints; keeps only CAN links
// (link_type "can"). Returns false with a reason when the text is not that JSON.
bool parseIpLinkJson(const QByteArray& json, QList<SocketCanLink>* links, QString* error);

// Runs `ip -details -json link show` (the program can be replaced by the environment variable
// COSCOPE_IP, used by tests) and parses it. Empty with a reason when `ip` is missing or fails.
QList<SocketCanLink> listSocketCanLinks(QString* error);

// One line the user can paste into a shell to bring the interface up at the chosen rate,
// e.g. "sudo ip link set can0 up type can bitrate 500000" (vcan takes no bit rate).
QString bringUpCommand(const SocketCanLink& link, int bitrate, int dataBitrate = 0);

// "up, 500 kbit/s, ERROR-ACTIVE" / "down" / "up (virtual)": the state in a few words (CLI, English).
QString describeLink(const SocketCanLink& link);

// What an error from opening a SocketCAN interface means and what to do about it, appended to the
// raw system text: "Address family not supported by protocol" -> CAN support not loaded
// (modprobe can_raw), "No such device" -> no such interface (lists the ones there are),
// "Network is down" -> the bring-up command, "Operation not permitted" -> permissions.
// Returns the raw text unchanged when there is nothing to add.
QString explainSocketCanError(const QString& interfaceName, const QString& rawError, int bitrate);

}  // namespace coscope
