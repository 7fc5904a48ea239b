// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/canopen/CommandScript.h"
#include "core/canopen/NmtMaster.h"
#include "core/canopen/PdoMapping.h"
#include "core/canopen/SdoClient.h"

#include <QObject>
#include <QStringList>

#include <functional>
#include <memory>

namespace coscope::canopen {

struct PdoReadResult {
    bool ok = false;
    PdoId pdo;
    PdoConfig config;
    QString error;
};

struct PdoWriteResult {
    bool ok = false;
    PdoConfig previous;         // what was there before
    PdoConfig written;          // what was asked (lengths filled in)
    QString failedStep;         // e.g. "mapping entry 2 (1A00:02)"
    int failedStepNumber = -1;  // 0-based index of the failed write in plan()'s SDO writes; -1 = none/verify
    uint32_t abortCode = 0;     // what the device answered to the failed step (0 = no abort: timeout, verify)
    bool restored = false;      // the previous mapping was written back after a failure
    QStringList steps;          // each SDO write, in order, as "1800:01 = 0x800001A5 (COB-ID invalid)"
    QString error;
};

// Reads and writes PDO communication and mapping parameters over SDO (CiA 301 §7.5.2.35-38).
// A mapping is written in the CiA 301 order: node to pre-operational, COB-ID invalid
// (bit 31), transmission type, inhibit time, event timer, mapping sub0 = 0, the entries,
// sub0 = n, COB-ID valid; then every value is read back. If any step fails, the previous
// parameters are written back the same way. A drive whose dictionary marks the COB-ID read-only
// (DEXMART DEV, extract-dexmart §4.6) keeps its COB-ID: those two steps are left out. A mapping over 64 bits or with an object that is not
// mappable is refused before anything is sent.
class PdoConfigurator : public QObject {
    Q_OBJECT
public:
    PdoConfigurator(SdoClient& sdo, NmtMaster* nmt = nullptr, QObject* parent = nullptr);

    void read(uint8_t node, PdoId pdo, std::function<void(const PdoReadResult&)> done);
    // TPDO1..4 and RPDO1..4; PDOs the node does not have are left out.
    void readSet(uint8_t node, std::function<void(const std::vector<PdoReadResult>&)> done);
    // `wanted.cobId` 0 keeps the current COB-ID (made valid); unset inhibit/event timer are not written.
    void write(uint8_t node, PdoId pdo, PdoConfig wanted, const od::ObjectDictionary* dictionary,
               std::function<void(const PdoWriteResult&)> done);
    // The dry run of write(): the same NMT command and SDO writes in the same order (both come
    // from writeOps()), followed by the read-back checks as "expect" steps. Nothing is sent.
    // `wanted.cobId` 0 stands for the PDO's default COB-ID here (write() keeps the device's).
    // A mapping write() would refuse gives a script without steps and *error.
    CommandScript plan(uint8_t node, PdoId pdo, PdoConfig wanted, const od::ObjectDictionary* dictionary,
                       QString* error = nullptr) const;

private:
    struct Op {
        uint16_t index;
        uint8_t sub;
        QByteArray data;
        QString what;  // short, for the step log: "COB-ID invalid"
        QString why;   // plain words for the dry run
    };
    using OpsDone = std::function<void(bool ok, int failedAt, const SdoResult& failure)>;
    void runOps(uint8_t node, std::shared_ptr<std::vector<Op>> ops, size_t i, QStringList* log, OpsDone done);
    // `cobIdWritable` false (the dictionary marks comm sub 1 read-only, e.g. DEXMART DEV): the
    // PDO cannot be switched off; the COB-ID steps are left out and the mapping is rewritten
    // while it is in use (sub0 = 0 still stops it from being sent with half a mapping).
    static std::vector<Op> writeOps(const PdoId& pdo, const PdoConfig& c, uint8_t node, bool cobIdWritable = true);

    SdoClient& sdo_;
    NmtMaster* nmt_;
};

}  // namespace coscope::canopen
