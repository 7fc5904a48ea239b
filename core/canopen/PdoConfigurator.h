// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

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
    PdoConfig previous;      // what was there before
    PdoConfig written;       // what was asked (lengths filled in)
    QString failedStep;      // e.g. "mapping entry 2 (1A00:02)"
    bool restored = false;   // the previous mapping was written back after a failure
    QStringList steps;       // each SDO write, in order, as "1800:01 = 0x800001A5 (COB-ID invalid)"
    QString error;
};

// Reads and writes PDO communication and mapping parameters over SDO (CiA 301 §7.5.2.35-38).
// A mapping is written in the CiA 301 order: node to pre-operational, COB-ID invalid
// (bit 31), mapping sub0 = 0, the entries, sub0 = n, COB-ID valid, transmission type, inhibit
// time, event timer; then every value is read back. If any step fails, the previous
// parameters are written back the same way. A mapping over 64 bits or with an object that is not
// mappable is refused before anything is sent.
class PdoConfigurator : public QObject {
    Q_OBJECT
public:
    PdoConfigurator(SdoClient& sdo, NmtMaster* nmt = nullptr, QObject* parent = nullptr);

    void read(uint8_t node, PdoId pdo, std::function<void(const PdoReadResult&)> done);
    // TPDO1..4 and RPDO1..4; PDOs the node does not have are left out.
    void readSet(uint8_t node, std::function<void(const std::vector<PdoReadResult>&)> done);
    // `wanted.cobId` 0 keeps the current COB-ID (made valid); unset inhibit/event timer are not written.
    void write(uint8_t node, PdoId pdo, PdoConfig wanted, const od::ObjectDictionary* dictionary, std::function<void(const PdoWriteResult&)> done);

private:
    struct Op {
        uint16_t index;
        uint8_t sub;
        QByteArray data;
        QString what;
    };
    using OpsDone = std::function<void(bool ok, int failedAt, const QString& error)>;
    void runOps(uint8_t node, std::shared_ptr<std::vector<Op>> ops, size_t i, QStringList* log, OpsDone done);
    static std::vector<Op> writeOps(const PdoId& pdo, const PdoConfig& c, uint8_t node);

    SdoClient& sdo_;
    NmtMaster* nmt_;
};

}  // namespace coscope::canopen
