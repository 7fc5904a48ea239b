// SPDX-License-Identifier: GPL-3.0-or-later
// Folder dissectors/ owns CANopen decoding of frames and transfers into named fields: one dissector
// per service, the network context (per-node dictionaries, PDO mappings, SDO reassembly), filters,
// output formats and statistics. QtCore only.
#pragma once

#include "core/canopen/CobId.h"

#include <QByteArray>
#include <QString>
#include <QStringList>

#include <cstdint>
#include <vector>

namespace coscope::dissect {

// What a dissector produces for one frame. One object is reused frame after frame (reset()
// keeps the capacity of its vectors and strings), so the flat/summary mode allocates little.
//
// Flat field keys and their JSON value formats (stable, Wireshark style; DESIGN.md "Contracts"):
//   nmt.cs         integer   NMT command specifier (1 start, 2 stop, 128 pre-op, 129 reset node, 130 reset comm)
//   nmt.node       integer   NMT target node-ID (0 = all nodes)
//   nmt.state      integer   NMT_EC: 0 boot-up, 4 stopped, 5 operational, 127 pre-operational
//   nmt.toggle     integer   NMT_EC node-guarding reply: toggle bit 0/1 (absent for heartbeats)
//   nmt.rtr        bool      NMT_EC: a node-guarding request (remote frame)
//   sync.counter   integer   SYNC counter 1..240 (absent when the SYNC carries no counter)
//   time.ms        integer   TIME: milliseconds after midnight
//   time.days      integer   TIME: days since 1 January 1984
//   emcy.code      integer   EMCY error code (bytes 0-1)
//   emcy.reg       integer   error register 1001h (byte 2)
//   emcy.text      string    CiA 301/402 text of the error code
//   emcy.vendor    string    vendor alarm text from the bundled alarm table, else the 5 manufacturer bytes in hex
//   emcy.vendor_bytes string the 5 manufacturer-specific bytes in hex (always)
//   sdo.cs         string    command name ("initiate download request", "abort", "block segment", ...)
//   sdo.index      integer   object index (frames that carry the multiplexer)
//   sdo.sub        integer   sub-index
//   sdo.size       integer   size indicated by an initiate frame
//   sdo.toggle     integer   segment toggle bit
//   sdo.seqno      integer   block segment sequence number
//   sdo.abort      integer   abort code
//   sdo.abort_text string    CiA 301 text, or the vendor's text for vendor codes
//   sdo.value      integer|number|string  expedited value, typed by the dictionary when known
//                            (integers are numbers, strings are strings; unknown 1..4 byte data is
//                            an unsigned little-endian integer)
//   lss.cs         integer   LSS command specifier (CiA 305)
//   lss.node       integer   LSS node-ID (configure / inquire node-ID)
//   lss.value      integer   LSS 32-bit value (identity parts, fastscan IDNumber)
//   pdo.pdoSignals    array     [{obj: "6041:00", name: string, value: number|string, unit: string|null}]
//   ds402.controlword integer, ds402.command string, ds402.statusword integer, ds402.state string,
//   ds402.mode integer, ds402.mode_text string   (CiA 402 meaning of 6040h/6041h/6060h/6061h,
//                            from an SDO or a PDO)
//   can.err.class  integer   CAN error frame: SocketCAN error class bits (linux/can/error.h)
//   can.err.state  string    "error active", "error warning", "error passive", "bus-off" (when reported)
//   can.err.tx_errors, can.err.rx_errors integer  the controller's error counters (when reported)
//   can.err.text   string    what the error frame reports, in words
class SummaryBuffer;  // dissectors/SummaryBuffer.h
struct PdoTextSink;   // dissectors/PdoText.h

struct FlatField {
    enum class Kind : uint8_t { Int, UInt, Real, Bool, Text };
    const char* key = nullptr;  // a string literal: the stable field name
    Kind kind = Kind::Int;
    int64_t i = 0;
    uint64_t u = 0;
    double d = 0;
    QString text;
};

// One decoded PDO signal.
struct PdoSignal {
    uint16_t index = 0;
    uint8_t sub = 0;
    uint8_t bitOffset = 0;
    uint8_t bitLength = 0;
    QString name;
    FlatField value;   // key unused; Int/UInt/Real/Text
    QString unit;      // empty = none
    bool raw = false;  // a raw signal (RawSignal.h): no object, index/sub unused
};

// One node of the field tree: pre-order list, `depth` 0 for top-level items. Byte/bit
// positions refer to the frame payload (byteLength 0 = no bytes, e.g. derived meaning).
struct TreeItem {
    int depth = 0;
    QString label;
    QString value;
    int byteOffset = 0;
    int byteLength = 0;
    int bitOffset = -1;  // -1 = whole bytes
    int bitLength = 0;
};

// A finished (or aborted) SDO transfer, reassembled from its frames.
struct SdoTransferRecord {
    int node = -1;
    bool upload = false;  // server -> client data
    bool block = false;
    bool segmented = false;
    uint16_t index = 0;
    uint8_t sub = 0;
    uint32_t size = 0;  // bytes carried
    QByteArray data;
    QString status;  // "ok", "aborted", "crc error", "size mismatch"
    uint32_t abortCode = 0;
    QString abortText;
    QString name;       // object name from the dictionary
    QString namesFrom;  // that dictionary's bundledName (Dissection::namesFrom)
    QString valueText;  // typed value text ("" when not decodable)
    int64_t startNs = 0;
    int64_t endNs = 0;
};

class Dissection {
public:
    // How much to produce: Stats = service, node, warnings and transfers only (no text);
    // Flat = + summary and flat fields; Tree = + field tree.
    enum class Level : uint8_t { Stats, Flat, Tree };

    void reset(Level level);
    Level level() const { return level_; }
    bool wantText() const { return level_ != Level::Stats; }
    bool wantTree() const { return level_ == Level::Tree; }

    canopen::Service service = canopen::Service::Unknown;
    int node = -1;      // -1 = none
    int pdoNumber = 0;  // 1-based PDO number for PDO frames (may exceed 4 for custom COB-IDs)
    QString summary;
    QStringList warnings;
    std::vector<PdoSignal> pdoSignals;  // valid [0, signalCount); not "signals": a Qt macro
    int signalCount = 0;
    bool hasTransfer = false;
    SdoTransferRecord transfer;
    // The bundled dictionary the object names in this frame's texts come from
    // (od::ObjectDictionary::bundledName): the GUI names those objects in its language
    // (dissectors/ObjectNames.h). Empty = a user's dictionary or none: its names stay as written.
    QString namesFrom;
    std::vector<TreeItem> tree;
    // Set by a consumer that keeps the summaries of many frames in one buffer (the CLI's text
    // output): dissectors that can (PDO) append the summary there and leave `summary` empty.
    // The consumer tells by the buffer's size; reset() does not change it.
    SummaryBuffer* summarySink = nullptr;
    // Set by a consumer that writes the text itself, maybe on another thread (the CLI's text
    // output): a PDO frame of integer signals (without the tree) leaves a record of its
    // decoded values there (writePdoSummary() writes its text) and no summary. The consumer
    // tells by the number of records; reset() does not change it.
    PdoTextSink* pdoTextSink = nullptr;
    // False for a consumer that reads no flat fields, PDO signals or namesFrom (the CLI's text output:
    // summary, warnings, transfer): add*() keep nothing, addSignal() hands out a scratch signal,
    // signalCount stays 0, PDO frames set no namesFrom. reset() does not change it.
    bool wantFields = true;

    // Flat fields, valid [0, fieldCount()).
    int fieldCount() const { return fieldCount_; }
    const FlatField& field(int i) const { return fields_[static_cast<size_t>(i)]; }
    const FlatField* find(const char* key) const;  // by name (strcmp), nullptr if absent

    void addInt(const char* key, int64_t v);
    void addUInt(const char* key, uint64_t v);
    void addReal(const char* key, double v);
    void addBool(const char* key, bool v);
    void addText(const char* key, const QString& v);
    PdoSignal& addSignal(const QString& name, const QString& unit);
    void warn(const QString& text) { warnings.append(text); }
    void item(int depth, const QString& label, const QString& value, int byteOffset = 0, int byteLength = 0,
              int bitOffset = -1, int bitLength = 0);

private:
    FlatField& next(const char* key, FlatField::Kind kind);
    Level level_ = Level::Flat;
    PdoSignal scratchSignal_;  // addSignal() without wantFields
    std::vector<FlatField> fields_;
    int fieldCount_ = 0;
};

// "0x1A00" style helpers used by several dissectors.
QString hex(uint32_t v, int width);
QString hexBytes(const uint8_t* data, int len, bool spaced);

}  // namespace coscope::dissect
