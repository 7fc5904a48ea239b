// SPDX-License-Identifier: GPL-3.0-or-later
#include "dissectors/Ds402Meaning.h"

#include "core/canopen/Ds402.h"
#include "dissectors/NetworkContext.h"

namespace coscope::dissect {

namespace ds = canopen::ds402;

QString ds402MeaningText(uint16_t index, uint8_t sub, uint64_t raw) {
    if (sub != 0 || index < 0x6000 || index > 0x67FF) return {};
    const uint16_t v16 = static_cast<uint16_t>(raw);
    switch (0x6000 + ((index - 0x6000) & 0x7FF)) {
    case 0x6040: return ds::controlwordCommandName(v16);
    case 0x6041: return ds::stateName(ds::stateFromStatusword(v16));
    case 0x6060:
    case 0x6061: return ds::modeName(static_cast<int8_t>(raw));
    default: return {};
    }
}

std::optional<int8_t> ds402ModeOf(const NodeState& n, uint16_t index) {
    if (index < 0x6000 || index > 0x67FF) return std::nullopt;
    const int axis = (index - 0x6000) / 0x800;
    if (!(n.ds402ModeKnown & (1u << axis))) return std::nullopt;
    return n.ds402Mode[static_cast<size_t>(axis)];
}

void ds402LearnMode(NodeState& n, uint16_t index, uint8_t sub, uint64_t raw) {
    if (sub != 0 || index < 0x6000 || index > 0x67FF || (index & 0x7FE) != 0x060) return;
    const int axis = (index - 0x6000) / 0x800;
    n.ds402Mode[static_cast<size_t>(axis)] = static_cast<int8_t>(raw);
    n.ds402ModeKnown = static_cast<uint8_t>(n.ds402ModeKnown | (1u << axis));
}

QString ds402Meaning(uint16_t index, uint8_t sub, uint64_t raw, Dissection& out, int depth, int byteOffset,
                     int byteLength, std::optional<int8_t> mode) {
    QString text = ds402MeaningText(index, sub, raw);
    if (text.isEmpty()) return {};
    const uint16_t v16 = static_cast<uint16_t>(raw);
    switch (0x6000 + ((index - 0x6000) & 0x7FF)) {
    case 0x6040:
        out.addInt("ds402.controlword", v16);
        out.addText("ds402.command", text);
        if (out.wantTree()) out.item(depth, QStringLiteral("Command (CiA 402)"), text, byteOffset, byteLength);
        break;
    case 0x6041:
        out.addInt("ds402.statusword", v16);
        out.addText("ds402.state", text);
        if (out.wantTree()) {
            out.item(depth, QStringLiteral("State (CiA 402)"), text, byteOffset, byteLength);
            for (int b = 0; b < 16; ++b)
                if (v16 & (1u << b)) {
                    const QString n = ds::statuswordBitName(b, mode);
                    out.item(depth + 1, QStringLiteral("Bit %1").arg(b), n.isEmpty() ? QStringLiteral("set") : n,
                             byteOffset + b / 8, 1, b % 8, 1);
                }
        }
        break;
    default:  // 6060h, 6061h
        out.addInt("ds402.mode", static_cast<int8_t>(raw));
        out.addText("ds402.mode_text", text);
        if (out.wantTree())
            out.item(depth, QStringLiteral("Mode of operation (CiA 402)"), text, byteOffset, byteLength);
        break;
    }
    return text;
}

}  // namespace coscope::dissect
