// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/od/DataType.h"
#include "core/od/NumberText.h"

#include <QByteArray>
#include <QString>

#include <cstdint>
#include <optional>
#include <variant>

namespace coscope::od {

struct Limits;
struct ValueResult;

// Display options for Value::format.
struct FormatOptions {
    bool hex = false;     // integers as 0x with the type's width (two's complement for signed)
    QString unit;         // appended after a space when not empty
    double factor = 1.0;  // display = raw * factor (integers/reals only; 1.0 = raw)
    bool quoteStrings = false;
};

// A typed value of the object dictionary. Representation by type class:
//   BOOLEAN -> bool, INTEGERn -> int64, UNSIGNEDn -> uint64, REALn -> double,
//   VISIBLE_STRING / UNICODE_STRING -> QString, OCTET_STRING / DOMAIN / unknown types -> QByteArray,
//   TIME_OF_DAY / TIME_DIFFERENCE -> uint64 holding the 48-bit wire value
//   (bits 0..27 ms after midnight / ms, bits 32..47 days; CiA 301 7.1.6.5 and 7.1.6.6).
// All encodings are little-endian (CiA 301 7.1.2).
class Value {
public:
    using Storage = std::variant<std::monostate, bool, std::int64_t, std::uint64_t, double, QByteArray, QString>;

    Value() = default;
    static Value boolean(bool v) { return Value(Storage(v)); }
    static Value signedInt(std::int64_t v) { return Value(Storage(v)); }
    static Value unsignedInt(std::uint64_t v) { return Value(Storage(v)); }
    static Value real(double v) { return Value(Storage(v)); }
    static Value bytes(QByteArray v) { return Value(Storage(std::move(v))); }
    static Value text(QString v) { return Value(Storage(std::move(v))); }
    static Value timeOfDay(std::uint32_t ms, std::uint16_t days) {
        return unsignedInt((std::uint64_t(days) << 32) | (ms & 0x0FFFFFFFu));
    }

    bool isNull() const { return std::holds_alternative<std::monostate>(storage_); }
    const Storage& storage() const { return storage_; }

    // Numeric views (nullopt for strings/bytes/null). Bool converts to 0/1.
    std::optional<std::int64_t> toInt64() const;
    std::optional<std::uint64_t> toUInt64() const;
    std::optional<double> toDouble() const;
    QByteArray toBytes() const;  // bytes/strings (Latin-1 for text); empty otherwise
    QString toText() const;      // strings; format() for everything else

    bool operator==(const Value& o) const { return storage_ == o.storage_; }
    bool operator!=(const Value& o) const { return !(*this == o); }

    // Little-endian wire bytes for `type`. Out-of-range numbers and wrong representations are
    // errors (empty result and *error set).
    QByteArray encode(DataType type, QString* error = nullptr) const;
    // Bytes from the wire. Fixed-size types need exactly byteSize(type) bytes; VISIBLE_STRING
    // drops trailing NULs and is read as UTF-8 when valid, else Latin-1 (and encoded as
    // UTF-8); UNICODE_STRING is UTF-16LE and needs an even count.
    static ValueResult decode(DataType type, const QByteArray& bytes);
    // What a person types (or an EDS holds, with TextStyle::Eds): "0x1F", "-5", "1.5", "true",
    // "\"quoted\"", hex bytes "01 02 FF"; REAL also as a 0x bit pattern. Checks the type's range
    // and `limits`, and says which one failed.
    static ValueResult parse(DataType type, const QString& text);
    static ValueResult parse(DataType type, const QString& text, const Limits& limits,
                             TextStyle style = TextStyle::Person);
    // Display text: decimal (or hex), reals shortest round-trip, bytes as "01 02 FF", units.
    static QString format(DataType type, const Value& value, const FormatOptions& options = {});
    QString format(DataType type, const FormatOptions& options = {}) const { return format(type, *this, options); }

private:
    explicit Value(Storage s) : storage_(std::move(s)) {}
    Storage storage_;
};

// Inclusive limits (EDS LowLimit/HighLimit); either side may be absent. Compared in the
// type's own representation (signed, unsigned or real).
struct Limits {
    std::optional<Value> low;
    std::optional<Value> high;
    bool empty() const { return !low && !high; }
};

struct ValueResult {
    Value value;
    QString error;  // empty when ok
    bool ok() const { return error.isEmpty(); }
};

// A parsed integer (parseIntegerText) as a value of integer `type` (INTEGERn, UNSIGNEDn);
// nullopt when it does not fit the type. A hex number (0x1F, 1Fh) is the type's bit pattern:
// FFh as INTEGER8 is -1 (two's complement, CiA 301 §7.1.4.5).
std::optional<Value> integerValue(DataType type, const ParsedInteger& n);
// The smallest and largest value of integer `type` (CiA 301 §7.1.4.4, §7.1.4.5).
Value integerMin(DataType type);
Value integerMax(DataType type);

// Checks `value` against the limits; on failure sets *error ("above HighLimit 100").
bool withinLimits(DataType type, const Value& value, const Limits& limits, QString* error = nullptr);

}  // namespace coscope::od
