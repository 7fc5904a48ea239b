// SPDX-License-Identifier: GPL-3.0-or-later
#include "dissectors/Ds402Meaning.h"

#include "core/canopen/Ds402.h"

namespace coscope::dissect {

namespace ds = canopen::ds402;

QString ds402Meaning(uint16_t index, uint8_t sub, uint64_t raw, Dissection& out, int depth, int byteOffset, int byteLength) {
    if (sub != 0 || index < 0x6000 || index > 0x67FF) return {};
    const uint16_t base = 0x6000 + ((index - 0x6000) & 0x7FF);
    const uint16_t v16 = static_cast<uint16_t>(raw);
    switch (base) {
    case 0x6040: {
        const QString cmd = ds::controlwordCommandName(v16);
        out.addInt("ds402.controlword", v16);
        out.addText("ds402.command", cmd);
        if (out.wantTree()) out.item(depth, QStringLiteral("Command (CiA 402)"), cmd, byteOffset, byteLength);
        return cmd;
    }
    case 0x6041: {
        const QString state = ds::stateName(ds::stateFromStatusword(v16));
        out.addInt("ds402.statusword", v16);
        out.addText("ds402.state", state);
        if (out.wantTree()) {
            out.item(depth, QStringLiteral("State (CiA 402)"), state, byteOffset, byteLength);
            for (int b = 0; b < 16; ++b)
                if (v16 & (1u << b)) {
                    const QString n = ds::statuswordBitName(b);
                    out.item(depth + 1, QStringLiteral("Bit %1").arg(b), n.isEmpty() ? QStringLiteral("set") : n,
                             byteOffset + b / 8, 1, b % 8, 1);
                }
        }
        return state;
    }
    case 0x6060:
    case 0x6061: {
        const auto mode = static_cast<int8_t>(raw);
        const QString name = ds::modeName(mode);
        out.addInt("ds402.mode", mode);
        out.addText("ds402.mode_text", name);
        if (out.wantTree()) out.item(depth, QStringLiteral("Mode of operation (CiA 402)"), name, byteOffset, byteLength);
        return name;
    }
    default: return {};
    }
}

}  // namespace coscope::dissect
