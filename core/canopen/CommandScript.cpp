// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/canopen/CommandScript.h"

#include "core/canopen/Lss.h"
#include "core/od/NumberNotation.h"

#include <QFile>
#include <QRegularExpression>
#include <QSaveFile>
#include <QStringList>

#include <algorithm>

namespace coscope::canopen {

namespace {

QByteArray littleEndian(uint32_t value, int size) {
    QByteArray out;
    for (int i = 0; i < size; ++i) out.append(static_cast<char>((value >> (8 * i)) & 0xFF));
    return out;
}

uint32_t fromLittleEndian(const QByteArray& bytes) {
    uint32_t v = 0;
    for (int i = 0; i < std::min<int>(4, static_cast<int>(bytes.size())); ++i)
        v |= static_cast<uint32_t>(static_cast<uint8_t>(bytes[i])) << (8 * i);
    return v;
}

int clampSize(int size) { return size <= 1 ? 1 : size <= 2 ? 2 : 4; }

QString hexDigits(uint32_t v, int digits) { return QStringLiteral("%1").arg(v, digits, 16, QChar(u'0')); }

// Data as written in a script line: "0x0006" for 1, 2, 4 bytes, "bytes 01 02 03" otherwise.
QString dataText(const QByteArray& data) {
    const int n = static_cast<int>(data.size());
    if (n == 1 || n == 2 || n == 4) return QStringLiteral("0x") + hexDigits(fromLittleEndian(data), n * 2);
    QStringList parts{QStringLiteral("bytes")};
    for (char c : data) parts << hexDigits(static_cast<uint8_t>(c), 2);
    return parts.join(u' ');
}

// A mask for people: "00FFh" or "3 bytes 41 42 43".
QString dataHuman(const QByteArray& data) {
    const int n = static_cast<int>(data.size());
    if (n == 1 || n == 2 || n == 4) return hexDigits(fromLittleEndian(data), n * 2).toUpper() + u'h';
    QStringList parts;
    for (char c : data) parts << hexDigits(static_cast<uint8_t>(c), 2).toUpper();
    return QStringLiteral("%1 bytes %2").arg(n).arg(parts.join(u' ')).trimmed();
}

// The value of index:sub for people, by the app's one rule (od/NumberNotation.h): "60410010h",
// "182h", "0006h" for COB-IDs, mappings, controlwords…, "1000" for quantities.
QString valueHuman(uint16_t index, uint8_t sub, const QByteArray& data) {
    const int n = static_cast<int>(data.size());
    if (n == 1 || n == 2 || n == 4) return od::valueText(index, sub, fromLittleEndian(data), n * 8);
    return dataHuman(data);
}

QString objectText(uint16_t index, uint8_t sub) {
    return QStringLiteral("0x%1:%2").arg(hexDigits(index, 4), hexDigits(sub, 2));
}
QString objectHuman(uint16_t index, uint8_t sub) { return od::objectText(index, sub); }

QString nmtWord(NmtCommand c) {
    switch (c) {
    case NmtCommand::Start: return QStringLiteral("start");
    case NmtCommand::Stop: return QStringLiteral("stop");
    case NmtCommand::EnterPreOperational: return QStringLiteral("preop");
    case NmtCommand::ResetNode: return QStringLiteral("reset");
    case NmtCommand::ResetCommunication: return QStringLiteral("reset-comm");
    }
    return QStringLiteral("unknown");
}

QString bitRateHuman(uint32_t bits) {
    if (bits >= 1000000 && bits % 1000000 == 0) return QStringLiteral("%1 Mbit/s").arg(bits / 1000000);
    if (bits >= 1000 && bits % 1000 == 0) return QStringLiteral("%1 kbit/s").arg(bits / 1000);
    return QStringLiteral("%1 bit/s").arg(bits);
}

// ---- parsing ---------------------------------------------------------------------------------

struct ParseError {
    QString message;
};

// Unsigned number: decimal or 0x-hex, at most `max`.
bool parseNumber(const QString& word, uint64_t max, uint64_t* out) {
    bool ok = false;
    uint64_t v = 0;
    if (word.startsWith(u"0x", Qt::CaseInsensitive)) {
        if (word.size() < 3 || word.size() > 18) return false;
        v = word.mid(2).toULongLong(&ok, 16);
    } else {
        if (word.isEmpty() || word.size() > 20 || !word[0].isDigit()) return false;
        v = word.toULongLong(&ok, 10);
    }
    if (!ok || v > max) return false;
    *out = v;
    return true;
}

bool parseHex(QString word, uint64_t max, uint64_t* out) {
    if (word.startsWith(u"0x", Qt::CaseInsensitive)) word = word.mid(2);
    else if (word.endsWith(u'h', Qt::CaseInsensitive)) word.chop(1);
    if (word.isEmpty() || word.size() > 8) return false;
    bool ok = false;
    const uint64_t v = word.toULongLong(&ok, 16);
    if (!ok || v > max) return false;
    *out = v;
    return true;
}

// Reads the words of one line.
class Words {
public:
    explicit Words(QStringList words) : words_(std::move(words)) {}
    bool atEnd() const { return pos_ >= words_.size(); }
    QString peek() const { return atEnd() ? QString() : words_[pos_]; }
    QString next(const QString& what) {
        if (atEnd()) throw ParseError{QStringLiteral("missing %1").arg(what)};
        return words_[pos_++];
    }
    void expectEnd() const {
        if (!atEnd()) throw ParseError{QStringLiteral("unexpected '%1'").arg(words_[pos_])};
    }
    uint32_t number(const QString& what, uint64_t max) {
        const QString w = next(what);
        uint64_t v = 0;
        if (!parseNumber(w, max, &v))
            throw ParseError{QStringLiteral("%1 '%2' is not a number from 0 to %3").arg(what, w).arg(max)};
        return static_cast<uint32_t>(v);
    }
    uint8_t node(bool allowAll) {
        const QString w = next(QStringLiteral("node-ID"));
        uint64_t v = 0;
        if (!parseNumber(w, 127, &v) || (v == 0 && !allowAll))
            throw ParseError{QStringLiteral("node-ID '%1' is not %2 to 127")
                                 .arg(w, allowAll ? QStringLiteral("0 (all)") : QStringLiteral("1"))};
        return static_cast<uint8_t>(v);
    }
    // INDEX:SUB, both hex ("0x6040:00", "6040:0", "6040h:00h").
    void object(uint16_t* index, uint8_t* sub) {
        const QString w = next(QStringLiteral("object (INDEX:SUB)"));
        const int colon = static_cast<int>(w.indexOf(u':'));
        uint64_t i = 0, s = 0;
        if (colon < 0 || !parseHex(w.left(colon), 0xFFFF, &i) || !parseHex(w.mid(colon + 1), 0xFF, &s))
            throw ParseError{QStringLiteral("object '%1' is not INDEX:SUB in hex, e.g. 0x6040:00").arg(w)};
        *index = static_cast<uint16_t>(i);
        *sub = static_cast<uint8_t>(s);
    }
    // DATA in one of the three forms (see CommandScript.h).
    QByteArray data(const QString& what) {
        const QString w = next(what).toLower();
        if (w == u"bytes") {
            QByteArray out;
            while (!atEnd() && peek().toLower() != u"mask") {
                const QString b = words_[pos_++];
                uint64_t v = 0;
                if (b.size() > 4 || !parseHex(b, 0xFF, &v))
                    throw ParseError{QStringLiteral("'%1' is not a hex byte (00..ff)").arg(b)};
                out.append(static_cast<char>(v));
            }
            if (out.isEmpty()) throw ParseError{QStringLiteral("%1: 'bytes' needs at least one byte").arg(what)};
            if (out.size() > 4096) throw ParseError{QStringLiteral("%1: more than 4096 bytes").arg(what)};
            return out;
        }
        static const struct {
            const char16_t* name;
            int size;
            bool isSigned;
        } types[] = {{u"u8", 1, false}, {u"u16", 2, false}, {u"u32", 4, false},
                     {u"i8", 1, true},  {u"i16", 2, true},  {u"i32", 4, true}};
        for (const auto& t : types) {
            if (w != QStringView(t.name)) continue;
            const QString v = next(QStringLiteral("%1 value").arg(w));
            const uint64_t max = t.size == 4 ? 0xFFFFFFFFull : (1ull << (8 * t.size)) - 1;
            uint64_t u = 0;
            if (t.isSigned && v.startsWith(u'-')) {
                const int64_t lowest = -(1ll << (8 * t.size - 1));
                uint64_t magnitude = 0;
                if (!parseNumber(v.mid(1), static_cast<uint64_t>(-lowest), &magnitude))
                    throw ParseError{QStringLiteral("%1 value '%2' is out of range").arg(w, v)};
                u = static_cast<uint64_t>(-static_cast<int64_t>(magnitude)) & max;
            } else {
                const uint64_t limit = t.isSigned && !v.startsWith(u"0x", Qt::CaseInsensitive) ? (max >> 1) : max;
                if (!parseNumber(v, limit, &u))
                    throw ParseError{QStringLiteral("%1 value '%2' is out of range").arg(w, v)};
            }
            return littleEndian(static_cast<uint32_t>(u), t.size);
        }
        if (w.startsWith(u"0x")) {
            const qsizetype digits = w.size() - 2;
            uint64_t v = 0;
            if ((digits == 2 || digits == 4 || digits == 8) && parseHex(w, 0xFFFFFFFFull, &v))
                return littleEndian(static_cast<uint32_t>(v), static_cast<int>(digits / 2));
            if (parseHex(w, 0xFFFFFFFFull, &v))
                throw ParseError{
                    QStringLiteral("%1 '%2': give 2, 4 or 8 hex digits (the size on the bus), or a type: u16 %3")
                        .arg(what, w)
                        .arg(v)};
        }
        throw ParseError{
            QStringLiteral("%1 '%2' is not 0xHH/0xHHHH/0xHHHHHHHH, u8|u16|u32|i8|i16|i32 N or bytes ..").arg(what, w)};
    }

private:
    QStringList words_;
    qsizetype pos_ = 0;
};

ScriptStep parseStep(const QString& line) {
    Words in(line.split(QRegularExpression(QStringLiteral("\\s+")), Qt::SkipEmptyParts));
    ScriptStep s;
    const QString verb = in.next(QStringLiteral("command")).toLower();
    if (verb == u"sdo") {
        const QString op = in.next(QStringLiteral("sdo operation (write|read|expect)")).toLower();
        s.node = in.node(false);
        in.object(&s.index, &s.sub);
        if (op == u"write") {
            s.kind = ScriptStep::Kind::SdoWrite;
            s.data = in.data(QStringLiteral("data"));
        } else if (op == u"read") {
            s.kind = ScriptStep::Kind::SdoRead;
        } else if (op == u"expect") {
            s.kind = ScriptStep::Kind::SdoExpect;
            s.data = in.data(QStringLiteral("expected value"));
            if (!in.atEnd() && in.peek().toLower() == u"mask") {
                in.next({});
                s.mask = in.data(QStringLiteral("mask"));
                if (s.mask.size() != s.data.size())
                    throw ParseError{
                        QStringLiteral("mask has %1 bytes, the value %2").arg(s.mask.size()).arg(s.data.size())};
            }
        } else {
            throw ParseError{QStringLiteral("unknown sdo operation '%1' (write|read|expect)").arg(op)};
        }
    } else if (verb == u"nmt") {
        const QString word = in.next(QStringLiteral("NMT command (start|stop|preop|reset|reset-comm)"));
        const auto cmd = nmtCommandFromName(word);
        if (!cmd)
            throw ParseError{QStringLiteral("unknown NMT command '%1' (start|stop|preop|reset|reset-comm)").arg(word)};
        s.kind = ScriptStep::Kind::Nmt;
        s.nmt = *cmd;
        s.node = in.node(true);
    } else if (verb == u"lss") {
        const QString op = in.next(QStringLiteral("lss operation")).toLower();
        if (op == u"switch-global") {
            const QString st = in.next(QStringLiteral("state (config|wait)")).toLower();
            if (st != u"config" && st != u"wait")
                throw ParseError{QStringLiteral("switch-global state '%1' is not config or wait").arg(st)};
            s = ScriptStep::lssSwitchGlobal(st == u"config", {});
        } else if (op == u"switch-selective") {
            LssIdentity id;
            id.vendorId = in.number(QStringLiteral("vendor-ID"), 0xFFFFFFFFull);
            id.productCode = in.number(QStringLiteral("product code"), 0xFFFFFFFFull);
            id.revision = in.number(QStringLiteral("revision"), 0xFFFFFFFFull);
            id.serial = in.number(QStringLiteral("serial number"), 0xFFFFFFFFull);
            s = ScriptStep::lssSwitchSelective(id, {});
        } else if (op == u"node-id") {
            const uint32_t n = in.number(QStringLiteral("node-ID"), 255);
            if (n == 0 || (n > 127 && n != 255))
                throw ParseError{QStringLiteral("node-ID %1 is not 1 to 127 or 255 (unconfigured)").arg(n)};
            s = ScriptStep::lssConfigureNodeId(static_cast<uint8_t>(n), {});
        } else if (op == u"bitrate") {
            const uint32_t b = in.number(QStringLiteral("bit rate"), 1000000);
            if (lssTableIndexForBitRate(static_cast<int>(b)) < 0)
                throw ParseError{QStringLiteral("bit rate %1 is not in the CiA 305 table (10000, 20000, 50000, 125000, "
                                                "250000, 500000, 800000, 1000000)")
                                     .arg(b)};
            s = ScriptStep::lssConfigureBitRate(b, {});
        } else if (op == u"store") {
            s = ScriptStep::lssStore({});
        } else if (op == u"activate") {
            s = ScriptStep::lssActivateBitTiming(
                static_cast<uint16_t>(in.number(QStringLiteral("switch delay (ms)"), 0xFFFF)), {});
        } else {
            throw ParseError{
                QStringLiteral(
                    "unknown lss operation '%1' (switch-global|switch-selective|node-id|bitrate|store|activate)")
                    .arg(op)};
        }
    } else if (verb == u"wait") {
        s = ScriptStep::wait(in.number(QStringLiteral("time (ms)"), 3600000), {});
    } else if (verb == u"wait-node") {
        const uint8_t node = in.node(false);
        s = ScriptStep::waitForNode(node, in.number(QStringLiteral("timeout (ms)"), 3600000), {});
    } else if (verb == u"reconnect") {
        const uint32_t b = in.number(QStringLiteral("bit rate"), 1000000);
        if (b < 10000) throw ParseError{QStringLiteral("bit rate %1 is below 10000").arg(b)};
        s = ScriptStep::reconnect(b, {});
    } else {
        throw ParseError{QStringLiteral("unknown command '%1' (sdo|nmt|lss|wait|wait-node|reconnect)").arg(verb)};
    }
    in.expectEnd();
    return s;
}

}  // namespace

// ---- builders --------------------------------------------------------------------------------

ScriptStep ScriptStep::sdoWrite(uint8_t node, uint16_t index, uint8_t sub, uint32_t value, int size,
                                const QString& why) {
    return sdoWriteBytes(node, index, sub, littleEndian(value, clampSize(size)), why);
}

ScriptStep ScriptStep::sdoWriteBytes(uint8_t node, uint16_t index, uint8_t sub, const QByteArray& data,
                                     const QString& why) {
    ScriptStep s;
    s.kind = Kind::SdoWrite;
    s.node = node;
    s.index = index;
    s.sub = sub;
    s.data = data;
    s.why = why;
    return s;
}

ScriptStep ScriptStep::sdoRead(uint8_t node, uint16_t index, uint8_t sub, const QString& why) {
    ScriptStep s;
    s.kind = Kind::SdoRead;
    s.node = node;
    s.index = index;
    s.sub = sub;
    s.why = why;
    return s;
}

// mask 0 or a mask covering every bit of `size` bytes = plain comparison (no mask stored).
ScriptStep ScriptStep::sdoExpect(uint8_t node, uint16_t index, uint8_t sub, uint32_t value, int size, uint32_t mask,
                                 const QString& why) {
    ScriptStep s = sdoRead(node, index, sub, why);
    s.kind = Kind::SdoExpect;
    size = clampSize(size);
    s.data = littleEndian(value, size);
    const uint32_t all = size == 4 ? 0xFFFFFFFFu : (1u << (8 * size)) - 1;
    if (mask != 0 && (mask & all) != all) s.mask = littleEndian(mask, size);
    return s;
}

ScriptStep ScriptStep::nmtCommand(NmtCommand command, uint8_t node, const QString& why) {
    ScriptStep s;
    s.kind = Kind::Nmt;
    s.nmt = command;
    s.node = node;
    s.why = why;
    return s;
}

ScriptStep ScriptStep::wait(uint32_t ms, const QString& why) {
    ScriptStep s;
    s.kind = Kind::Wait;
    s.number = ms;
    s.why = why;
    return s;
}

ScriptStep ScriptStep::waitForNode(uint8_t node, uint32_t timeoutMs, const QString& why) {
    ScriptStep s;
    s.kind = Kind::WaitForNode;
    s.node = node;
    s.number = timeoutMs;
    s.why = why;
    return s;
}

ScriptStep ScriptStep::reconnect(uint32_t bitRate, const QString& why) {
    ScriptStep s;
    s.kind = Kind::Reconnect;
    s.number = bitRate;
    s.why = why;
    return s;
}

ScriptStep ScriptStep::lssSwitchGlobal(bool configuration, const QString& why) {
    ScriptStep s;
    s.kind = Kind::LssSwitchGlobal;
    s.number = configuration ? 1 : 0;
    s.why = why;
    return s;
}

ScriptStep ScriptStep::lssSwitchSelective(const LssIdentity& identity, const QString& why) {
    ScriptStep s;
    s.kind = Kind::LssSwitchSelective;
    s.identity = identity;
    s.why = why;
    return s;
}

ScriptStep ScriptStep::lssConfigureNodeId(uint8_t nodeId, const QString& why) {
    ScriptStep s;
    s.kind = Kind::LssConfigureNodeId;
    s.number = nodeId;
    s.why = why;
    return s;
}

ScriptStep ScriptStep::lssConfigureBitRate(uint32_t bitRate, const QString& why) {
    ScriptStep s;
    s.kind = Kind::LssConfigureBitRate;
    s.number = bitRate;
    s.why = why;
    return s;
}

ScriptStep ScriptStep::lssStore(const QString& why) {
    ScriptStep s;
    s.kind = Kind::LssStore;
    s.why = why;
    return s;
}

ScriptStep ScriptStep::lssActivateBitTiming(uint16_t switchDelayMs, const QString& why) {
    ScriptStep s;
    s.kind = Kind::LssActivateBitTiming;
    s.number = switchDelayMs;
    s.why = why;
    return s;
}

bool ScriptStep::sameAs(const ScriptStep& o) const {
    if (kind != o.kind || why != o.why) return false;
    switch (kind) {
    case Kind::SdoWrite: return node == o.node && index == o.index && sub == o.sub && data == o.data;
    case Kind::SdoRead: return node == o.node && index == o.index && sub == o.sub;
    case Kind::SdoExpect: return node == o.node && index == o.index && sub == o.sub && data == o.data && mask == o.mask;
    case Kind::Nmt: return nmt == o.nmt && node == o.node;
    case Kind::LssSwitchSelective:
        return identity.vendorId == o.identity.vendorId && identity.productCode == o.identity.productCode &&
               identity.revision == o.identity.revision && identity.serial == o.identity.serial;
    case Kind::LssStore: return true;
    case Kind::WaitForNode: return node == o.node && number == o.number;
    case Kind::LssSwitchGlobal:
    case Kind::LssConfigureNodeId:
    case Kind::LssConfigureBitRate:
    case Kind::LssActivateBitTiming:
    case Kind::Reconnect:
    case Kind::Wait: return number == o.number;
    }
    return false;
}

bool ScriptStep::matches(const QByteArray& value) const {
    const qsizetype n = std::max(value.size(), data.size());
    for (qsizetype i = 0; i < n; ++i) {
        const uint8_t got = i < value.size() ? static_cast<uint8_t>(value[i]) : 0;
        const uint8_t want = i < data.size() ? static_cast<uint8_t>(data[i]) : 0;
        const uint8_t m = mask.isEmpty() ? 0xFF : (i < mask.size() ? static_cast<uint8_t>(mask[i]) : 0);
        if ((got & m) != (want & m)) return false;
    }
    return true;
}

// ---- text ------------------------------------------------------------------------------------

QString ScriptStep::toLine() const {
    switch (kind) {
    case Kind::SdoWrite:
        return QStringLiteral("sdo write %1 %2 %3").arg(node).arg(objectText(index, sub), dataText(data));
    case Kind::SdoRead: return QStringLiteral("sdo read %1 %2").arg(node).arg(objectText(index, sub));
    case Kind::SdoExpect: {
        QString line = QStringLiteral("sdo expect %1 %2 %3").arg(node).arg(objectText(index, sub), dataText(data));
        if (!mask.isEmpty()) line += QStringLiteral(" mask ") + dataText(mask);
        return line;
    }
    case Kind::Nmt: return QStringLiteral("nmt %1 %2").arg(nmtWord(nmt)).arg(node);
    case Kind::LssSwitchGlobal:
        return QStringLiteral("lss switch-global %1").arg(number ? QStringLiteral("config") : QStringLiteral("wait"));
    case Kind::LssSwitchSelective:
        return QStringLiteral("lss switch-selective 0x%1 0x%2 0x%3 0x%4")
            .arg(hexDigits(identity.vendorId, 8), hexDigits(identity.productCode, 8), hexDigits(identity.revision, 8),
                 hexDigits(identity.serial, 8));
    case Kind::LssConfigureNodeId: return QStringLiteral("lss node-id %1").arg(number);
    case Kind::LssConfigureBitRate: return QStringLiteral("lss bitrate %1").arg(number);
    case Kind::LssStore: return QStringLiteral("lss store");
    case Kind::LssActivateBitTiming: return QStringLiteral("lss activate %1").arg(number);
    case Kind::Wait: return QStringLiteral("wait %1").arg(number);
    case Kind::WaitForNode: return QStringLiteral("wait-node %1 %2").arg(node).arg(number);
    case Kind::Reconnect: return QStringLiteral("reconnect %1").arg(number);
    }
    return {};
}

QString ScriptStep::describe() const {
    switch (kind) {
    case Kind::SdoWrite:
        return QStringLiteral("Write %1 = %2 on node %3")
            .arg(objectHuman(index, sub), valueHuman(index, sub, data))
            .arg(node);
    case Kind::SdoRead: return QStringLiteral("Read %1 from node %2").arg(objectHuman(index, sub)).arg(node);
    case Kind::SdoExpect:
        // A masked check compares bits: value and mask in hex.
        return mask.isEmpty() ? QStringLiteral("Check %1 = %2 on node %3")
                                    .arg(objectHuman(index, sub), valueHuman(index, sub, data))
                                    .arg(node)
                              : QStringLiteral("Check %1 = %2 (mask %3) on node %4")
                                    .arg(objectHuman(index, sub), dataHuman(data), dataHuman(mask))
                                    .arg(node);
    case Kind::Nmt:
        return node == 0 ? QStringLiteral("NMT %1 to all nodes").arg(nmtCommandName(static_cast<uint8_t>(nmt)))
                         : QStringLiteral("NMT %1 to node %2").arg(nmtCommandName(static_cast<uint8_t>(nmt))).arg(node);
    case Kind::LssSwitchGlobal:
        return number ? QStringLiteral("LSS: every device to configuration state")
                      : QStringLiteral("LSS: every device back to waiting state");
    case Kind::LssSwitchSelective:
        return QStringLiteral("LSS: select the device with vendor %1h, product %2h, revision %3h, serial %4h")
            .arg(hexDigits(identity.vendorId, 8).toUpper(), hexDigits(identity.productCode, 8).toUpper(),
                 hexDigits(identity.revision, 8).toUpper(), hexDigits(identity.serial, 8).toUpper());
    case Kind::LssConfigureNodeId:
        return number == 255 ? QStringLiteral("LSS: set node-ID to unconfigured (FFh)")
                             : QStringLiteral("LSS: set node-ID %1").arg(number);
    case Kind::LssConfigureBitRate: return QStringLiteral("LSS: set bit rate %1").arg(bitRateHuman(number));
    case Kind::LssStore: return QStringLiteral("LSS: store configuration");
    case Kind::LssActivateBitTiming:
        return QStringLiteral("LSS: switch to the new bit rate (switch delay %1 ms)").arg(number);
    case Kind::Wait: return QStringLiteral("Wait %1 ms").arg(number);
    case Kind::WaitForNode:
        return QStringLiteral("Wait up to %1 ms for node %2 (boot-up or heartbeat)").arg(number).arg(node);
    case Kind::Reconnect: return QStringLiteral("Reconnect the adapter at %1").arg(bitRateHuman(number));
    }
    return {};
}

QString CommandScript::toText() const {
    QString out;
    out += QStringLiteral("# CoScope command script: run with `coscope-cli script run BUS FILE` (see --dry-run)\n");
    QString t = title;
    t.replace(u'\r', u' ').replace(u'\n', u' ');
    if (!t.trimmed().isEmpty()) out += QStringLiteral("# title: ") + t.trimmed() + u'\n';
    out += u'\n';
    for (const ScriptStep& s : steps) {
        if (!s.why.isEmpty()) {
            QString why = s.why;
            why.remove(u'\r');
            for (const QString& line : why.split(u'\n'))
                out += (line.isEmpty() ? QStringLiteral("#") : QStringLiteral("# ") + line) + u'\n';
        }
        out += s.toLine() + QStringLiteral("\n\n");
    }
    return out;
}

std::optional<CommandScript> CommandScript::parse(const QString& text, QString* error) {
    CommandScript script;
    QStringList errors;
    QStringList why;
    // The header is the first block of comment lines (up to the first blank line or step);
    // "# title: ..." there names the script.
    bool inHeader = true;
    bool seenContent = false;
    const QStringList lines = text.split(u'\n');
    for (qsizetype i = 0; i < lines.size(); ++i) {
        QString line = lines[i];
        if (line.endsWith(u'\r')) line.chop(1);
        const QString trimmed = line.trimmed();
        if (trimmed.isEmpty()) {
            if (seenContent) inHeader = false;
            why.clear();
            continue;
        }
        seenContent = true;
        if (trimmed.startsWith(u'#')) {
            QString c = trimmed.mid(1);
            if (c.startsWith(u' ')) c = c.mid(1);
            if (inHeader && c.startsWith(QStringLiteral("title:"), Qt::CaseInsensitive)) {
                script.title = c.mid(6).trimmed();
                continue;
            }
            why << c;
            continue;
        }
        inHeader = false;
        try {
            ScriptStep s = parseStep(trimmed);
            s.why = why.join(u'\n');
            script.steps.push_back(std::move(s));
        } catch (const ParseError& e) {
            errors << QStringLiteral("line %1: %2").arg(i + 1).arg(e.message);
        }
        why.clear();
    }
    if (!errors.isEmpty()) {
        if (error) {
            const qsizetype shown = std::min<qsizetype>(errors.size(), 20);
            QStringList out = errors.mid(0, shown);
            if (errors.size() > shown) out << QStringLiteral("(%1 more errors)").arg(errors.size() - shown);
            *error = out.join(u'\n');
        }
        return std::nullopt;
    }
    if (error) error->clear();
    return script;
}

bool CommandScript::save(const QString& path, QString* error) const {
    QSaveFile f(path);
    if (!f.open(QIODevice::WriteOnly | QIODevice::Text)) {
        if (error) *error = QStringLiteral("%1: %2").arg(path, f.errorString());
        return false;
    }
    f.write(toText().toUtf8());
    if (!f.commit()) {
        if (error) *error = QStringLiteral("%1: %2").arg(path, f.errorString());
        return false;
    }
    return true;
}

std::optional<CommandScript> CommandScript::load(const QString& path, QString* error) {
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly)) {
        if (error) *error = QStringLiteral("%1: %2").arg(path, f.errorString());
        return std::nullopt;
    }
    if (f.size() > 16 * 1024 * 1024) {
        if (error) *error = QStringLiteral("%1: larger than 16 MiB, not a command script").arg(path);
        return std::nullopt;
    }
    QString err;
    auto script = parse(QString::fromUtf8(f.readAll()), &err);
    if (!script && error) {
        // "FILE:N: message" per error line
        QStringList lines = err.split(u'\n');
        for (QString& l : lines)
            if (l.startsWith(QStringLiteral("line "))) {
                const qsizetype colon = l.indexOf(u':');
                l = QStringLiteral("%1:%2:%3").arg(path, l.mid(5, colon - 5), l.mid(colon + 1));
            }
        *error = lines.join(u'\n');
    }
    return script;
}

}  // namespace coscope::canopen
