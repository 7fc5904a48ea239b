// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/canopen/Nmt.h"

#include "core/canopen/CobId.h"

namespace coscope::canopen {

QString nmtCommandName(uint8_t cs) {
    switch (cs) {
    case 0x01: return QStringLiteral("Start");
    case 0x02: return QStringLiteral("Stop");
    case 0x80: return QStringLiteral("Enter pre-operational");
    case 0x81: return QStringLiteral("Reset node");
    case 0x82: return QStringLiteral("Reset communication");
    default: return QStringLiteral("Unknown (0x%1)").arg(cs, 2, 16, QLatin1Char('0'));
    }
}

std::optional<NmtCommand> nmtCommandFromName(const QString& word) {
    const QString w = word.trimmed().toLower();
    if (w == u"start" || w == u"operational") return NmtCommand::Start;
    if (w == u"stop" || w == u"stopped") return NmtCommand::Stop;
    if (w == u"preop" || w == u"pre-operational" || w == u"preoperational") return NmtCommand::EnterPreOperational;
    if (w == u"reset" || w == u"reset-node") return NmtCommand::ResetNode;
    if (w == u"reset-comm" || w == u"reset-communication") return NmtCommand::ResetCommunication;
    return std::nullopt;
}

QString nmtStateName(uint8_t state) {
    switch (state & 0x7F) {
    case 0x00: return QStringLiteral("Boot-up");
    case 0x04: return QStringLiteral("Stopped");
    case 0x05: return QStringLiteral("Operational");
    case 0x7F: return QStringLiteral("Pre-operational");
    default: return QStringLiteral("Unknown state (0x%1)").arg(state & 0x7F, 2, 16, QLatin1Char('0'));
    }
}

int nmtStateAfter(uint8_t cs) {
    switch (cs) {
    case 0x01: return 0x05;
    case 0x02: return 0x04;
    case 0x80: return 0x7F;
    default: return -1;
    }
}

CanFrame nmtFrame(NmtCommand cs, uint8_t node) { return CanFrame::classic(0x000, {static_cast<uint8_t>(cs), node}); }

CanFrame heartbeatFrame(uint8_t node, NmtState state) {
    return CanFrame::classic(defaultCobId(Service::NmtErrorControl, node), {static_cast<uint8_t>(state)});
}

}  // namespace coscope::canopen
