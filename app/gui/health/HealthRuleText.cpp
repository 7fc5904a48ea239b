// SPDX-License-Identifier: GPL-3.0-or-later
// The sentences of the health findings' rules (dissectors/HealthRules.cpp) for lupdate, in
// context "HealthRules": each exactly as the rule table writes it (a test keeps the two equal).
#include "app/gui/health/HealthRuleText.h"

#include "app/gui/language/CoreText.h"
#include "dissectors/HealthRules.h"

#include <QCoreApplication>

namespace coscope::gui {

namespace {
// clang-format off
const char* const kRuleTexts[] = {
    QT_TRANSLATE_NOOP("HealthRules", "Node %1 booted up %2 time(s) without an NMT reset command before it."),
    QT_TRANSLATE_NOOP("HealthRules", "A device that restarts on its own loses its state: a drive drops its enable and the machine stops."),
    QT_TRANSLATE_NOOP("HealthRules", "Check the node's supply voltage and wiring, its watchdog and error history, and the frames just before each boot-up."),
    QT_TRANSLATE_NOOP("HealthRules", "Node %1's %2 stopped: nothing for %3 at the end of the log (period %4)."),
    QT_TRANSLATE_NOOP("HealthRules", "The master's heartbeat consumer sees the node as lost and the application stops using it."),
    QT_TRANSLATE_NOOP("HealthRules", "Check that node %1 still has power and is on the bus (cable, connector, termination), and whether its 1017h was set to 0."),
    QT_TRANSLATE_NOOP("HealthRules", "Node %1's %2 was missing %3 time(s) after regular beats (longest gap %4, period %5)."),
    QT_TRANSLATE_NOOP("HealthRules", "A consumer whose heartbeat time (1016h) is shorter than the gap raises a heartbeat error and may stop the machine."),
    QT_TRANSLATE_NOOP("HealthRules", "Look at the frames around each gap: error frames, bus load, a reset of node %1, a loose connection."),
    QT_TRANSLATE_NOOP("HealthRules", "Node %1's %2 came late %3 time(s) (over 1.5 times the %4 period)."),
    QT_TRANSLATE_NOOP("HealthRules", "Late beats eat the consumer's margin: a little more delay becomes a heartbeat error."),
    QT_TRANSLATE_NOOP("HealthRules", "Compare with the bus load at those times, and check that the consumer time (1016h) leaves margin over %4."),
    QT_TRANSLATE_NOOP("HealthRules", "Node %1 reported EMCY %2 (%3) %4 time(s)."),
    QT_TRANSLATE_NOOP("HealthRules", "The device signals a fault; a drive in Fault stops its motor until the fault is reset."),
    QT_TRANSLATE_NOOP("HealthRules", "Look up %2 in the device's alarm list, remove the cause, then reset the fault (controlword bit 7)."),
    QT_TRANSLATE_NOOP("HealthRules", "Node %1 left %2 SDO request(s) unanswered (no response within 1 s)."),
    QT_TRANSLATE_NOOP("HealthRules", "The master's parameter access fails: a configuration step may have been skipped."),
    QT_TRANSLATE_NOOP("HealthRules", "Check node %1's node-ID, power and NMT state (a stopped node serves no SDO), and the bus load at those times."),
    QT_TRANSLATE_NOOP("HealthRules", "Node %1 aborted %4 SDO transfer(s) with %2 (%3)."),
    QT_TRANSLATE_NOOP("HealthRules", "The value was not read or written: a configuration that relies on it is incomplete."),
    QT_TRANSLATE_NOOP("HealthRules", "Look at the object of each frame: does node %1 have it (its EDS), is it writable, is the value in range?"),
    QT_TRANSLATE_NOOP("HealthRules", "Node %1 answered SDO requests slowly: %2 at the 99th percentile, the slowest %3."),
    QT_TRANSLATE_NOOP("HealthRules", "A master with a short SDO timeout aborts such transfers, and start-up configuration takes longer."),
    QT_TRANSLATE_NOOP("HealthRules", "Check what node %1 does meanwhile (storing parameters, 1010h) and the bus load; raise the master's SDO timeout if needed."),
    QT_TRANSLATE_NOOP("HealthRules", "%1 CAN error frame(s) were recorded."),
    QT_TRANSLATE_NOOP("HealthRules", "Error frames destroy frames and delay others; many of them take nodes to error passive or bus-off."),
    QT_TRANSLATE_NOOP("HealthRules", "Check the termination (120 ohm at both ends), cable, shield and ground, and that every node uses the same bit rate."),
    QT_TRANSLATE_NOOP("HealthRules", "%1 SYNC cycle(s) were missing (period %2)."),
    QT_TRANSLATE_NOOP("HealthRules", "Synchronous PDOs are not sent or applied in those cycles; axes in a cyclic synchronous mode miss set-points."),
    QT_TRANSLATE_NOOP("HealthRules", "Check the SYNC producer's timing and load, and the bus load at those times."),
    QT_TRANSLATE_NOOP("HealthRules", "The bus load peaks at %1 % (average %2 %) at %3 bit/s."),
    QT_TRANSLATE_NOOP("HealthRules", "Above about 70 % the low-priority frames (SDO, heartbeat) wait and may time out."),
    QT_TRANSLATE_NOOP("HealthRules", "Lower PDO rates or mapped data, use inhibit times or event timers, or raise the bit rate."),
    QT_TRANSLATE_NOOP("HealthRules", "%1 (%2) is sent to node %3, which never sent anything."),
    QT_TRANSLATE_NOOP("HealthRules", "The data goes nowhere: node %3 is missing or has another node-ID."),
    QT_TRANSLATE_NOOP("HealthRules", "Check that node %3 is powered and on the bus, and its node-ID."),
    QT_TRANSLATE_NOOP("HealthRules", "%1 of node %2 (%3) comes every %4 with a jitter of %5."),
    QT_TRANSLATE_NOOP("HealthRules", "Cyclic data that arrives unevenly makes control and plots uneven."),
    QT_TRANSLATE_NOOP("HealthRules", "Check the producer's timing (SYNC or event timer) and the bus load; the frames listed end the most irregular intervals."),
    QT_TRANSLATE_NOOP("HealthRules", "RPDO%1 of node %2 (%3) is valid but nobody sends it."),
    QT_TRANSLATE_NOOP("HealthRules", "Node %2 waits for data that never comes; with an RPDO timeout it may fault."),
    QT_TRANSLATE_NOOP("HealthRules", "Map and enable the matching TPDO on the producer, or make this RPDO invalid (COB-ID bit 31)."),
    QT_TRANSLATE_NOOP("HealthRules", "%1 node-ID(s) (%2..%3) got an SDO request from a master and never answered."),
    QT_TRANSLATE_NOOP("HealthRules", "A device the master expects may be missing, or the master scanned the network."),
    QT_TRANSLATE_NOOP("HealthRules", "Compare with the devices the machine should have, and their node-IDs."),
    QT_TRANSLATE_NOOP("HealthRules", "%1 frame(s) are not CANopen."),
    QT_TRANSLATE_NOOP("HealthRules", "They come from another protocol on the same bus (such as J1939) or from a device set up wrongly."),
    QT_TRANSLATE_NOOP("HealthRules", "Look at their identifiers in the trace."),
    QT_TRANSLATE_NOOP("HealthRules", "CoScope's scan (frames sent by the recording side) asked %1 node-ID(s) (%2..%3) that did not answer."),
    QT_TRANSLATE_NOOP("HealthRules", "This is how a scan finds devices: no device is at fault."),
    QT_TRANSLATE_NOOP("HealthRules", "Nothing to fix: these requests are CoScope's own."),
    QT_TRANSLATE_NOOP("HealthRules", "Node %1 aborted %4 SDO request(s) that CoScope sent, with %2 (%3)."),
    QT_TRANSLATE_NOOP("HealthRules", "CoScope's own requests (a scan reading optional objects, a read or write of the user) caused them: not a device fault."),
    QT_TRANSLATE_NOOP("HealthRules", "Nothing to fix unless you expected node %1 to have that object."),
    QT_TRANSLATE_NOOP("HealthRules", "Node %1 did not answer %2 SDO request(s) that CoScope sent."),
    QT_TRANSLATE_NOOP("HealthRules", "CoScope's own requests went unanswered (a scan probing, or the node was busy): not counted as a device fault."),
    QT_TRANSLATE_NOOP("HealthRules", "Nothing to fix unless node %1 should have answered."),
};
// clang-format on
// The words the findings put into those sentences (HealthFindings.cpp: the kind of error control).
const char* const kRuleWords[] = {
    QT_TRANSLATE_NOOP("HealthRules", "heartbeat"),
    QT_TRANSLATE_NOOP("HealthRules", "guarding"),
};
QString argText(const QString& a) {
    for (const char* w : kRuleWords)
        if (a == QLatin1String(w)) return QCoreApplication::translate("HealthRules", w);
    return coreText(a);
}
}  // namespace

std::span<const char* const> healthRuleTexts() { return kRuleTexts; }

QString healthRuleText(const dissect::HealthFinding& f, RulePart part) {
    const dissect::HealthRule* rule = dissect::healthRule(f.rule);
    if (!rule) return part == RulePart::What ? coreLines(f.text) : QString();
    const char* english = part == RulePart::What ? rule->what : part == RulePart::Why ? rule->why : rule->check;
    // The values in the UI language too where they are words ("heartbeat", an EMCY text).
    QStringList args;
    for (const QString& a : f.args) args << argText(a);
    return dissect::fillRule(QCoreApplication::translate("HealthRules", english), args);
}

}  // namespace coscope::gui
