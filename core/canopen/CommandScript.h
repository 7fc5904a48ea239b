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
        SdoWrite,              // download `data` to node:index:sub
        SdoRead,               // upload node:index:sub (the value is reported)
        SdoExpect,             // upload node:index:sub and compare with `data` (under `mask` when set)
        Nmt,                   // NMT `nmt` to `node` (0 = all nodes)
        LssSwitchGlobal,       // `number` 1 = configuration state, 0 = waiting state (CiA 305 §6.3.2)
        LssSwitchSelective,    // `identity` (CiA 305 §6.3.3)
        LssConfigureNodeId,    // `number` = new node-ID (§6.4.2)
        LssConfigureBitRate,   // `number` = bit/s (§6.4.3, standard table)
        LssStore,              // store configuration (§6.4.5)
        LssActivateBitTiming,  // `number` = switch delay in ms (§6.4.4)
        Wait,                  // `number` ms
        WaitForNode,           // boot-up or heartbeat from `node` within `number` ms
        Reconnect,             // close the adapter and open it again at `number` bit/s
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
    static ScriptStep sdoWriteBytes(uint8_t node, uint16_t index, uint8_t sub, const QByteArray& data,
                                    const QString& why);
    static ScriptStep sdoRead(uint8_t node, uint16_t index, uint8_t sub, const QString& why);
    static ScriptStep sdoExpect(uint8_t node, uint16_t index, uint8_t sub, uint32_t value, int size, uint32_t mask,
                                const QString& why);
    static ScriptStep nmtCommand(NmtCommand command, uint8_t node, const QString& why);
    static ScriptStep wait(uint32_t ms, const QString& why);
    static ScriptStep waitForNode(uint8_t node, uint32_t timeoutMs, const QString& why);
    static ScriptStep reconnect(uint32_t bitRate, const QString& why);
    // LSS builders (CiA 305; added with the implementation, same meaning as the Kind comments).
    static ScriptStep lssSwitchGlobal(bool configuration, const QString& why);
    static ScriptStep lssSwitchSelective(const LssIdentity& identity, const QString& why);
    static ScriptStep lssConfigureNodeId(uint8_t nodeId, const QString& why);
    static ScriptStep lssConfigureBitRate(uint32_t bitRate, const QString& why);
    static ScriptStep lssStore(const QString& why);
    static ScriptStep lssActivateBitTiming(uint16_t switchDelayMs, const QString& why);

    // Same effect on the bus and same reason: compares only the fields the kind uses.
    bool sameAs(const ScriptStep& other) const;
    // SdoExpect: does `value` (as read) match `data` under `mask`? Shorter side zero-extended.
    bool matches(const QByteArray& value) const;

    // The step as one script line (without the comment), e.g. "sdo write 5 0x1600:00 0x00",
    // "sdo expect 5 0x6041:00 0x0027 mask 0x006f", "nmt preop 5", "lss node-id 7", "wait 100",
    // "wait-node 7 3000", "reconnect 250000". See CommandScript for the grammar.
    QString toLine() const;
    // Human summary for the dry-run table: "Write 1600h:00 = 00h on node 5".
    QString describe() const;
};

// A named sequence of steps; text form: one step per line, `# why` comments before each step,
// header comments for title and target. Parsing reports "line N: message" and never throws.
//
// Text form (UTF-8, one step per line, words separated by blanks, case-insensitive keywords):
//   # title: Map RPDO1 of node 5          in the first block of comments (the header)
//   # Stop process data (NMT)             comment lines right before a step are its reason (why);
//   nmt preop 5                           a blank line drops comments not yet attached to a step
//   sdo write 5 0x1600:00 0x00            NODE INDEX:SUB DATA   (index and sub-index in hex)
//   sdo write 5 0x1008:00 bytes 41 42 43
//   sdo read 5 0x1018:01
//   sdo expect 5 0x6041:00 0x0027 mask 0x006f
//   nmt start|stop|preop|reset|reset-comm NODE         (NODE 0 = all nodes)
//   lss switch-global config|wait
//   lss switch-selective VENDOR PRODUCT REVISION SERIAL
//   lss node-id N | lss bitrate BITS | lss store | lss activate DELAY_MS
//   wait MS | wait-node NODE TIMEOUT_MS
//   reconnect BITS                        reopen the adapter at BITS bit/s (after a bit-rate change)
// DATA keeps its length on the bus:
//   0xHH / 0xHHHH / 0xHHHHHHHH   1, 2 or 4 bytes: the number of hex digits (2, 4, 8) is the size,
//                                the value is sent little-endian (0x0006 -> 06 00)
//   u8|u16|u32|i8|i16|i32 N      typed number, decimal or 0x-hex (i = two's complement)
//   bytes B0 B1 ...              raw bytes in bus order (any other length)
// toText() writes the 0x form for 1, 2 and 4 bytes and the bytes form otherwise; a mask uses the
// same form and must have the data's length. Numbers elsewhere are decimal or 0x-hex.
struct CommandScript {
    QString title;
    std::vector<ScriptStep> steps;

    QString toText() const;
    static std::optional<CommandScript> parse(const QString& text, QString* error);
    bool save(const QString& path, QString* error) const;
    static std::optional<CommandScript> load(const QString& path, QString* error);
};

}  // namespace coscope::canopen
