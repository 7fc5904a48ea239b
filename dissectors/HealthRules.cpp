// SPDX-License-Identifier: GPL-3.0-or-later
// The findings' rules and their sentences (HealthRules.h). Thresholds and protocol facts:
// heartbeat CiA 301 §7.2.8.3, SDO §7.2.4, EMCY §7.2.7, SYNC §7.2.5, PDO §7.2.2; CiA 402-2 §6.2
// for the fault reset (controlword bit 7).
#include "dissectors/HealthRules.h"

#include "dissectors/HealthReport.h"

namespace coscope::dissect {

namespace {
using S = HealthFinding::Severity;
// clang-format off
constexpr HealthRule kRules[] = {
    {"nmt.reset", S::Critical,
     "Node %1 booted up %2 time(s) without an NMT reset command before it.",
     "A device that restarts on its own loses its state: a drive drops its enable and the machine stops.",
     "Check the node's supply voltage and wiring, its watchdog and error history, and the frames just before each boot-up."},
    {"heartbeat.stopped", S::Critical,
     "Node %1's %2 stopped: nothing for %3 at the end of the log (period %4).",
     "The master's heartbeat consumer sees the node as lost and the application stops using it.",
     "Check that node %1 still has power and is on the bus (cable, connector, termination), and whether its 1017h was set to 0."},
    {"heartbeat.lost", S::Error,
     "Node %1's %2 was missing %3 time(s) after regular beats (longest gap %4, period %5).",
     "A consumer whose heartbeat time (1016h) is shorter than the gap raises a heartbeat error and may stop the machine.",
     "Look at the frames around each gap: error frames, bus load, a reset of node %1, a loose connection."},
    {"heartbeat.late", S::Warning,
     "Node %1's %2 came late %3 time(s) (over 1.5 times the %4 period).",
     "Late beats eat the consumer's margin: a little more delay becomes a heartbeat error.",
     "Compare with the bus load at those times, and check that the consumer time (1016h) leaves margin over %4."},
    {"emcy.fault", S::Error,
     "Node %1 reported EMCY %2 (%3) %4 time(s).",
     "The device signals a fault; a drive in Fault stops its motor until the fault is reset.",
     "Look up %2 in the device's alarm list, remove the cause, then reset the fault (controlword bit 7)."},
    {"sdo.timeout", S::Error,
     "Node %1 left %2 SDO request(s) unanswered (no response within 1 s).",
     "The master's parameter access fails: a configuration step may have been skipped.",
     "Check node %1's node-ID, power and NMT state (a stopped node serves no SDO), and the bus load at those times."},
    {"sdo.abort", S::Warning,
     "Node %1 aborted %4 SDO transfer(s) with %2 (%3).",
     "The value was not read or written: a configuration that relies on it is incomplete.",
     "Look at the object of each frame: does node %1 have it (its EDS), is it writable, is the value in range?"},
    {"sdo.slow", S::Warning,
     "Node %1 answered SDO requests slowly: %2 at the 99th percentile, the slowest %3.",
     "A master with a short SDO timeout aborts such transfers, and start-up configuration takes longer.",
     "Check what node %1 does meanwhile (storing parameters, 1010h) and the bus load; raise the master's SDO timeout if needed."},
    {"bus.error_frames", S::Error,
     "%1 CAN error frame(s) were recorded.",
     "Error frames destroy frames and delay others; many of them take nodes to error passive or bus-off.",
     "Check the termination (120 ohm at both ends), cable, shield and ground, and that every node uses the same bit rate."},
    {"sync.missing", S::Warning,
     "%1 SYNC cycle(s) were missing (period %2).",
     "Synchronous PDOs are not sent or applied in those cycles; axes in a cyclic synchronous mode miss set-points.",
     "Check the SYNC producer's timing and load, and the bus load at those times."},
    {"bus.load", S::Warning,
     "The bus load peaks at %1 % (average %2 %) at %3 bit/s.",
     "Above about 70 % the low-priority frames (SDO, heartbeat) wait and may time out.",
     "Lower PDO rates or mapped data, use inhibit times or event timers, or raise the bit rate."},
    {"pdo.no_consumer", S::Warning,
     "%1 (%2) is sent to node %3, which never sent anything.",
     "The data goes nowhere: node %3 is missing or has another node-ID.",
     "Check that node %3 is powered and on the bus, and its node-ID."},
    {"pdo.jitter", S::Info,
     "%1 of node %2 (%3) comes every %4 with a jitter of %5.",
     "Cyclic data that arrives unevenly makes control and plots uneven.",
     "Check the producer's timing (SYNC or event timer) and the bus load; the frames listed end the most irregular intervals."},
    {"pdo.no_producer", S::Info,
     "RPDO%1 of node %2 (%3) is valid but nobody sends it.",
     "Node %2 waits for data that never comes; with an RPDO timeout it may fault.",
     "Map and enable the matching TPDO on the producer, or make this RPDO invalid (COB-ID bit 31)."},
    {"sdo.silent_nodes", S::Info,
     "%1 node-ID(s) (%2..%3) got an SDO request from a master and never answered.",
     "A device the master expects may be missing, or the master scanned the network.",
     "Compare with the devices the machine should have, and their node-IDs."},
    {"bus.not_canopen", S::Info,
     "%1 frame(s) are not CANopen.",
     "They come from another protocol on the same bus (such as J1939) or from a device set up wrongly.",
     "Look at their identifiers in the trace."},
    {"coscope.scan", S::Info,
     "CoScope's scan (frames sent by the recording side) asked %1 node-ID(s) (%2..%3) that did not answer.",
     "This is how a scan finds devices: no device is at fault.",
     "Nothing to fix: these requests are CoScope's own."},
    {"coscope.sdo_abort", S::Info,
     "Node %1 aborted %4 SDO request(s) that CoScope sent, with %2 (%3).",
     "CoScope's own requests (a scan reading optional objects, a read or write of the user) caused them: not a device fault.",
     "Nothing to fix unless you expected node %1 to have that object."},
    {"coscope.sdo_timeout", S::Info,
     "Node %1 did not answer %2 SDO request(s) that CoScope sent.",
     "CoScope's own requests went unanswered (a scan probing, or the node was busy): not counted as a device fault.",
     "Nothing to fix unless node %1 should have answered."},
};
// clang-format on
}  // namespace

std::span<const HealthRule> healthRules() { return kRules; }

const HealthRule* healthRule(const QString& id) {
    for (const HealthRule& r : kRules)
        if (id == QLatin1String(r.id)) return &r;
    return nullptr;
}

QString fillRule(const QString& text, const QStringList& args) {
    QString out;
    out.reserve(text.size() + 32);
    for (qsizetype i = 0; i < text.size(); ++i) {
        if (text[i] == u'%' && i + 1 < text.size() && text[i + 1].isDigit() && text[i + 1] != u'0') {
            const int n = text[i + 1].digitValue();
            if (n <= args.size()) {
                out += args[n - 1];
                ++i;
                continue;
            }
        }
        out += text[i];
    }
    return out;
}

}  // namespace coscope::dissect
