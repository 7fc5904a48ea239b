// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/canopen/SdoClient.h"
#include "core/od/ObjectDictionary.h"

#include <QObject>
#include <QPointer>
#include <QString>

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

namespace coscope::canopen {

// One object of a configuration read or write, and how it went.
struct ConfigEntryResult {
    uint16_t index = 0;
    uint8_t sub = 0;
    QString name;
    od::DataType type = od::DataType::Unsigned8;
    bool ok = false;
    QString valueText;       // read: the value as CiA 306 text; write: the value written
    QByteArray data;         // read: the bytes (trimmed to the type's size); write: the bytes sent
    uint32_t abortCode = 0;  // what the node aborted with (0 = none: timeout, decode problem)
    QString error;           // one line naming node, object and the CiA 301 abort text
};

// Which entries a read of "all values" takes.
struct ConfigReadOptions {
    // DOMAIN objects can be large (firmware, logs) and are left out unless asked for.
    bool includeDomains = false;
    int timeoutMs = 0;  // per SDO response; 0 = the client's default
};

struct ConfigReadResult {
    uint8_t node = 0;
    // The dictionary given, with ParameterValue = the value the node answered (DCF view, CiA
    // 306 4.7) and [DeviceCommissioning] NodeID = node. Entries that failed keep no value.
    od::ObjectDictionary values;
    std::vector<ConfigEntryResult> entries;  // every entry asked, in order
    int failed = 0;
    bool cancelled = false;
};

// One SDO write of a DCF application.
struct PlannedWrite {
    uint16_t index = 0;
    uint8_t sub = 0;
    QString name;
    od::DataType type = od::DataType::Unsigned8;
    od::Value value;
    QByteArray data;      // the encoded value (CiA 301 7.1, little-endian)
    QString valueText;    // for people: "500", "0x40000181", "\"text\""
    QString currentText;  // the node's value when it was read first, else empty
};

// An entry of the DCF with a ParameterValue that is not written, and why.
struct SkippedEntry {
    uint16_t index = 0;
    uint8_t sub = 0;
    QString name;
    QString reason;  // "read-only", "unchanged (500)", "command object (1010h store)", ...
};

// Which ParameterValue entries of a DCF are written.
enum class ApplyScope : uint8_t {
    AllValues,      // every writable entry with a ParameterValue
    OnlyDifferent,  // those whose value differs from the node's current one (read first)
};

struct ApplyPlan {
    uint8_t node = 0;
    std::vector<PlannedWrite> writes;  // in the DCF's index order
    std::vector<SkippedEntry> skipped;
};

// Reading a node's values into a DCF and applying a DCF to a node (CiA 306 4.7: ParameterValue
// holds the device's actual value). Works on od::ObjectDictionary only; files are read and
// written by the eds layer (EdsReader, DcfWriter). Transfers go one at a time through the SDO
// client and never block; writes are never retried: a failed entry is reported and the next
// one is written.
class DeviceConfiguration : public QObject {
    Q_OBJECT
public:
    using Progress = std::function<void(const ConfigEntryResult& entry, int done, int total)>;
    using ReadDone = std::function<void(const ConfigReadResult&)>;
    using ApplyDone = std::function<void(const std::vector<ConfigEntryResult>& results, bool cancelled)>;

    explicit DeviceConfiguration(SdoClient& sdo, QObject* parent = nullptr);

    // The entries a full read takes: readable sub-objects (not wo), in index order, without
    // DOMAINs unless asked for.
    static std::vector<std::pair<uint16_t, uint8_t>> readableEntries(const od::ObjectDictionary& dictionary,
                                                                     const ConfigReadOptions& options = {});

    // Reads `entries` (default: readableEntries) of `node`; `progress` after each one.
    void read(uint8_t node, const od::ObjectDictionary& dictionary, Progress progress, ReadDone done,
              ConfigReadOptions options = {});
    void read(uint8_t node, const od::ObjectDictionary& dictionary, std::vector<std::pair<uint16_t, uint8_t>> entries,
              Progress progress, ReadDone done, ConfigReadOptions options = {});

    // What applying `dcf` to `node` writes. `current` (a read result's dictionary) gives the node's
    // values: with OnlyDifferent, entries whose encoded value equals the current one are
    // skipped (entries without a current value are written). Never written: read-only/const
    // entries, command objects (isCommandObject) and values that do not fit their type.
    static ApplyPlan plan(uint8_t node, const od::ObjectDictionary& dcf, const od::ObjectDictionary* current,
                          ApplyScope scope);
    // The entries of a plan's writes (to read them first for OnlyDifferent).
    static std::vector<std::pair<uint16_t, uint8_t>> planEntries(const ApplyPlan& plan);

    // Writes the plan, in order, each once; a refused entry does not stop the others unless
    // setStopOnRefusal(true): then the write after a refusal is not sent (the results end with it).
    void setStopOnRefusal(bool stop) { stopOnRefusal_ = stop; }
    void apply(const ApplyPlan& plan, Progress progress, ApplyDone done, int timeoutMs = 0);

    // Stops after the transfer in progress; the result says cancelled.
    void cancel();
    bool isRunning() const { return running_; }

    // Objects that are commands, not configuration: 1010h store / 1011h restore (CiA 301
    // 7.5.2.13-14), 1F51h program control (CiA 302-3), controlword 6040h of each axis (CiA 402:
    // a controlword from a file could enable a drive).
    static bool isCommandObject(uint16_t index);
    // The value as CiA 306 text for ParameterValue: unsigned as 0x hex, signed and REAL as
    // decimals, BOOLEAN 0/1, strings as they are, OCTET_STRING/DOMAIN as hex digits.
    static QString edsText(od::DataType type, const od::Value& value);
    // Decodes an SDO upload as `type` (an expedited answer without size carries 4 bytes: the
    // type's width is kept).
    static od::ValueResult decodeUpload(od::DataType type, const QByteArray& data, QByteArray* trimmed = nullptr);

private:
    struct Run;
    void step(std::shared_ptr<Run> run);
    void finish(std::shared_ptr<Run> run);
    static void orderPdoWrites(ApplyPlan& plan, const od::ObjectDictionary& dcf, const od::ObjectDictionary* current);

    SdoClient& sdo_;
    bool running_ = false;
    bool cancelRequested_ = false;
    bool stopOnRefusal_ = false;
};

}  // namespace coscope::canopen
