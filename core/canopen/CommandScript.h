// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/canopen/LssMaster.h"
#include "core/canopen/Nmt.h"

#include <QByteArray>
#include <QString>

#include <optional>
#include <vector>

namespace coscope::canopen {

// One step of a commissioning sequence: exactly what goes on the bus (or what is waited for),
// with a plain-words reason. Wizards build these for their dry run; `coscope-cli script run`
// replays a saved sequence through the same services.
struct ScriptStep {
    enum class Kind {
        SdoWrite,             // download `data` to node:index:sub
        SdoRead,              // upload node:index:sub (the value is reported)
        SdoExpect,            // upload node:index:sub and compare with `data` (under `mask` when set)
        Nmt,                  // NMT `nmt` to `node` (0 = all nodes)
        LssSwitchGlobal,      // `number` 1 = configuration state, 0 = waiting state (CiA 305 §6.3.2)
        LssSwitchSelective,   // `identity` (CiA 305 §6.3.3)
        LssConfigureNodeId,   // `number` = new node-ID (§6.4.2)
        LssConfigureBitRate,  // `number` = bit/s (§6.4.3, standard table)
        LssStore,             // store configuration (§6.4.5)
        LssActivateBitTiming, // `number` = switch delay in ms (§6.4.4)
        Wait,                 // `number` ms
        WaitForNode,          // boot-up or heartbeat from `node` within `number` ms
    };
    Kind kind = Kind::Wait;
    uint8_t node = 0;
    uint16_t index = 0;
    uint8_t sub = 0;
    QByteArray data;  // SdoWrite / SdoExpect: the value's bytes, little-endian, as on the bus
    QByteArray mask;  // SdoExpect: optional, same length as data
    NmtCommand nmt = NmtCommand::Start;
    uint32_t number = 0;
    LssIdentity identity;
    QString why;  // plain words for a technician, CiA term in brackets; saved as a comment

    // Builders (values little-endian, `size` bytes: 1, 2 or 4).
    static ScriptStep sdoWrite(uint8_t node, uint16_t index, uint8_t sub, uint32_t value, int size, const QString& why);
    static ScriptStep sdoWriteBytes(uint8_t node, uint16_t index, uint8_t sub, const QByteArray& data, const QString& why);
    static ScriptStep sdoRead(uint8_t node, uint16_t index, uint8_t sub, const QString& why);
    static ScriptStep sdoExpect(uint8_t node, uint16_t index, uint8_t sub, uint32_t value, int size, uint32_t mask, const QString& why);
    static ScriptStep nmtCommand(NmtCommand command, uint8_t node, const QString& why);
    static ScriptStep wait(uint32_t ms, const QString& why);
    static ScriptStep waitForNode(uint8_t node, uint32_t timeoutMs, const QString& why);

    // The step as one script line (without the comment), e.g. "sdo write 5 0x1600:00 0x00",
    // "sdo expect 5 0x6041:00 0x0027 mask 0x006f", "nmt preop 5", "lss node-id 7", "wait 100",
    // "wait-node 7 3000".
    QString toLine() const;
    // Human summary for the dry-run table: "Write 1600h:00 = 00h on node 5".
    QString describe() const;
};

// A named sequence of steps; text form: one step per line, `# why` comments before each step,
// header comments for title and target. Parsing reports "line N: message" and never throws.
struct CommandScript {
    QString title;
    std::vector<ScriptStep> steps;

    QString toText() const;
    static std::optional<CommandScript> parse(const QString& text, QString* error);
    bool save(const QString& path, QString* error) const;
    static std::optional<CommandScript> load(const QString& path, QString* error);
};

}  // namespace coscope::canopen
