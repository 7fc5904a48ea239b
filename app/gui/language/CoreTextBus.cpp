// SPDX-License-Identifier: GPL-3.0-or-later
// The bus-level texts of the lower layers: CAN error frames (core/can/CanErrorFrame.cpp,
// dissectors/CanErrorDissector.cpp, SocketCAN's error.h classes), LSS (core/canopen/Lss.cpp,
// dissectors/LssDissector.cpp, CiA 305 §4), the EMCY summary with a vendor alarm and the alarm
// fields of resources/alarms/*.json; and how the lower layers join a list (joins()).
// Each entry exactly as the lower layer writes it; %1.. = the values it fills in (CoreText.h).
#include "app/gui/language/CoreTextLists.h"

#include <QCoreApplication>

namespace coscope::gui::coretext {

namespace {
// clang-format off
const char* const kBusTexts[] = {
    // CAN error frames: summary, details pane labels, bus states.
    QT_TRANSLATE_NOOP("CoreText", "CAN error: %1"),
    QT_TRANSLATE_NOOP("CoreText", "Error classes"),
    QT_TRANSLATE_NOOP("CoreText", "Bus state"),
    QT_TRANSLATE_NOOP("CoreText", "Problem"),
    QT_TRANSLATE_NOOP("CoreText", "TX error counter"),
    QT_TRANSLATE_NOOP("CoreText", "RX error counter"),
    QT_TRANSLATE_NOOP("CoreText", "error active"),
    QT_TRANSLATE_NOOP("CoreText", "error warning"),
    QT_TRANSLATE_NOOP("CoreText", "error passive"),
    QT_TRANSLATE_NOOP("CoreText", "bus-off"),
    QT_TRANSLATE_NOOP("CoreText", "bus-off (the controller stopped sending after too many errors)"),
    QT_TRANSLATE_NOOP("CoreText", "controller: %1"),
    QT_TRANSLATE_NOOP("CoreText", "TX error passive"),
    QT_TRANSLATE_NOOP("CoreText", "RX error passive"),
    QT_TRANSLATE_NOOP("CoreText", "TX error warning"),
    QT_TRANSLATE_NOOP("CoreText", "RX error warning"),
    QT_TRANSLATE_NOOP("CoreText", "RX buffer overflow (frames lost)"),
    QT_TRANSLATE_NOOP("CoreText", "TX buffer overflow"),
    QT_TRANSLATE_NOOP("CoreText", "back to error active"),
    QT_TRANSLATE_NOOP("CoreText", "unspecified"),
    QT_TRANSLATE_NOOP("CoreText", "no acknowledge (no other node on the bus, or a different bit rate)"),
    QT_TRANSLATE_NOOP("CoreText", "protocol violation"),
    QT_TRANSLATE_NOOP("CoreText", "protocol violation: %1"),
    QT_TRANSLATE_NOOP("CoreText", "protocol violation: %1 in the %2"),
    QT_TRANSLATE_NOOP("CoreText", "protocol violation in the %1"),
    QT_TRANSLATE_NOOP("CoreText", "bit error"),
    QT_TRANSLATE_NOOP("CoreText", "form error"),
    QT_TRANSLATE_NOOP("CoreText", "stuff error"),
    QT_TRANSLATE_NOOP("CoreText", "could not send a dominant bit"),
    QT_TRANSLATE_NOOP("CoreText", "could not send a recessive bit"),
    QT_TRANSLATE_NOOP("CoreText", "bus overload"),
    QT_TRANSLATE_NOOP("CoreText", "active error flag"),
    QT_TRANSLATE_NOOP("CoreText", "while transmitting"),
    QT_TRANSLATE_NOOP("CoreText", "start of frame"),
    QT_TRANSLATE_NOOP("CoreText", "identifier bits %1"),
    QT_TRANSLATE_NOOP("CoreText", "SRTR bit"),
    QT_TRANSLATE_NOOP("CoreText", "IDE bit"),
    QT_TRANSLATE_NOOP("CoreText", "RTR bit"),
    QT_TRANSLATE_NOOP("CoreText", "reserved bit %1"),
    QT_TRANSLATE_NOOP("CoreText", "data length code"),
    QT_TRANSLATE_NOOP("CoreText", "data field"),
    QT_TRANSLATE_NOOP("CoreText", "CRC sequence"),
    QT_TRANSLATE_NOOP("CoreText", "CRC delimiter"),
    QT_TRANSLATE_NOOP("CoreText", "ACK slot"),
    QT_TRANSLATE_NOOP("CoreText", "ACK delimiter"),
    QT_TRANSLATE_NOOP("CoreText", "end of frame"),
    QT_TRANSLATE_NOOP("CoreText", "intermission"),
    QT_TRANSLATE_NOOP("CoreText", "transceiver problem (status 0x%1)"),
    QT_TRANSLATE_NOOP("CoreText", "lost arbitration at bit %1"),
    QT_TRANSLATE_NOOP("CoreText", "lost arbitration"),
    QT_TRANSLATE_NOOP("CoreText", "transmit timeout"),
    QT_TRANSLATE_NOOP("CoreText", "bus error"),
    QT_TRANSLATE_NOOP("CoreText", "controller restarted"),
    QT_TRANSLATE_NOOP("CoreText", "error counters TX %1, RX %2"),
    QT_TRANSLATE_NOOP("CoreText", "error frame (class %1h)"),
    // LSS (CiA 305 §4): command names both ways, then the summaries.
    QT_TRANSLATE_NOOP("CoreText", "Switch state global"),
    QT_TRANSLATE_NOOP("CoreText", "Switch state selective: vendor-ID"),
    QT_TRANSLATE_NOOP("CoreText", "Switch state selective: product code"),
    QT_TRANSLATE_NOOP("CoreText", "Switch state selective: revision number"),
    QT_TRANSLATE_NOOP("CoreText", "Switch state selective: serial number"),
    QT_TRANSLATE_NOOP("CoreText", "Switch state selective response"),
    QT_TRANSLATE_NOOP("CoreText", "Configure node-ID"),
    QT_TRANSLATE_NOOP("CoreText", "Configure node-ID response"),
    QT_TRANSLATE_NOOP("CoreText", "Configure bit timing"),
    QT_TRANSLATE_NOOP("CoreText", "Configure bit timing response"),
    QT_TRANSLATE_NOOP("CoreText", "Activate bit timing"),
    QT_TRANSLATE_NOOP("CoreText", "Store configuration"),
    QT_TRANSLATE_NOOP("CoreText", "Store configuration response"),
    QT_TRANSLATE_NOOP("CoreText", "Inquire vendor-ID"),
    QT_TRANSLATE_NOOP("CoreText", "Vendor-ID"),
    QT_TRANSLATE_NOOP("CoreText", "Inquire product code"),
    QT_TRANSLATE_NOOP("CoreText", "Product code"),
    QT_TRANSLATE_NOOP("CoreText", "Inquire revision number"),
    QT_TRANSLATE_NOOP("CoreText", "Revision number"),
    QT_TRANSLATE_NOOP("CoreText", "Inquire serial number"),
    QT_TRANSLATE_NOOP("CoreText", "Serial number"),
    QT_TRANSLATE_NOOP("CoreText", "Inquire node-ID"),
    QT_TRANSLATE_NOOP("CoreText", "Identify remote slave: vendor-ID"),
    QT_TRANSLATE_NOOP("CoreText", "Identify remote slave: product code"),
    QT_TRANSLATE_NOOP("CoreText", "Identify remote slave: revision low"),
    QT_TRANSLATE_NOOP("CoreText", "Identify remote slave: revision high"),
    QT_TRANSLATE_NOOP("CoreText", "Identify remote slave: serial low"),
    QT_TRANSLATE_NOOP("CoreText", "Identify remote slave: serial high"),
    QT_TRANSLATE_NOOP("CoreText", "Identify non-configured remote slave"),
    QT_TRANSLATE_NOOP("CoreText", "Identify slave"),
    QT_TRANSLATE_NOOP("CoreText", "Identify non-configured slave"),
    QT_TRANSLATE_NOOP("CoreText", "Fastscan"),
    QT_TRANSLATE_NOOP("CoreText", "Unknown LSS command 0x%1"),
    QT_TRANSLATE_NOOP("CoreText", "LSS %1"),
    QT_TRANSLATE_NOOP("CoreText", "LSS %1: configuration"),
    QT_TRANSLATE_NOOP("CoreText", "LSS %1: waiting"),
    QT_TRANSLATE_NOOP("CoreText", "LSS %1: node-ID %2"),
    QT_TRANSLATE_NOOP("CoreText", "LSS %1: error %2"),
    QT_TRANSLATE_NOOP("CoreText", "LSS %1: ok"),
    QT_TRANSLATE_NOOP("CoreText", "LSS %1: %2 kbit/s"),
    QT_TRANSLATE_NOOP("CoreText", "LSS %1: table %2 index %3"),
    QT_TRANSLATE_NOOP("CoreText", "LSS %1: delay %2 ms"),
    QT_TRANSLATE_NOOP("CoreText", "LSS %1: 0x%2"),
    QT_TRANSLATE_NOOP("CoreText", "LSS Node-ID: %1"),
    QT_TRANSLATE_NOOP("CoreText", "LSS %1: IDNumber 0x%2, bit %3, sub %4, next %5"),
    QT_TRANSLATE_NOOP("CoreText", "LSS (malformed)"),
    QT_TRANSLATE_NOOP("CoreText", "LSS frame with %1 bytes; CiA 305 requires 8"),
    // EMCY with the vendor's alarm (dissectors/EmcyDissector.cpp) and the alarm fields named in
    // resources/alarms/*.json ("alarmFields"), shown when the value is not in the table.
    QT_TRANSLATE_NOOP("CoreText", "EMCY node %1: %2 %3, register 0x%4, %5"),
    QT_TRANSLATE_NOOP("CoreText", "Delta alarm number"),
    QT_TRANSLATE_NOOP("CoreText", "AIMOTOR fault code"),
    QT_TRANSLATE_NOOP("CoreText", "M1 alarm code"),
    QT_TRANSLATE_NOOP("CoreText", "M2 alarm code"),
    // CoScope's heartbeat guard of the drives it enabled (core/canopen/GuardedDrives.cpp,
    // HeartbeatGuard.cpp) and its watch over the nodes' error control (HeartbeatMonitor.cpp).
    QT_TRANSLATE_NOOP("CoreText", "%1: the bus is listen-only: CoScope sends nothing, so no heartbeat and no guard"),
    QT_TRANSLATE_NOOP("CoreText", "%1: CoScope's heartbeat node-ID %2 is the drive's own; choose another in the master settings"),
    QT_TRANSLATE_NOOP("CoreText", "%1: CoScope's heartbeat cannot start: %2"),
    QT_TRANSLATE_NOOP("CoreText", "%1 may still be enabled: it keeps watching CoScope's heartbeat (1016h, 6007h not put back), so it stops by itself when the heartbeat stops"),
    QT_TRANSLATE_NOOP("CoreText", "%1: the old 1016h/6007h could not be put back (the bus is closed); check them"),
    QT_TRANSLATE_NOOP("CoreText", "%1: heartbeat consumer 1016h and 6007h put back before the bus closed"),
    QT_TRANSLATE_NOOP("CoreText", "%1: the old 1016h/6007h were not all put back (%2); check them"),
    QT_TRANSLATE_NOOP("CoreText", "%1 watches CoScope's heartbeat (node %2) in 1016h:%3 with %4 ms; when it stops: %5"),
    QT_TRANSLATE_NOOP("CoreText", "%1: heartbeat consumer 1016h:%2 = %3%4 put back"),
    QT_TRANSLATE_NOOP("CoreText", "node %1: node guarding answer with toggle bit %2, %3 expected"),
    QT_TRANSLATE_NOOP("CoreText", "node %1: no answer to a node guarding request within the guard time %2 ms"),
};

// A list the lower layers join with ", " or "; " (the problems of one CAN error frame, the
// vendor alarms of one EMCY): translated item by item when every item is (CoreText.cpp). In
// this order: a "; " list is tried before the patterns, a ", " list after them.
const char* const kJoins[] = {
    QT_TRANSLATE_NOOP("CoreText", "%1; %2"),
    QT_TRANSLATE_NOOP("CoreText", "%1, %2"),
};
// clang-format on
}  // namespace

std::span<const char* const> bus() { return kBusTexts; }
std::span<const char* const> joins() { return kJoins; }

}  // namespace coscope::gui::coretext
