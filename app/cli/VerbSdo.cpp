// SPDX-License-Identifier: GPL-3.0-or-later
// coscope-cli sdo read / sdo write: one SDO transfer, values shown with the dictionary's names
// and types.
#include "app/cli/BusSession.h"
#include "app/cli/CliVerb.h"
#include "core/canopen/ServiceWait.h"
#include "core/od/Value.h"
#include "eds/StandardDictionary.h"

#include <QTextStream>

namespace coscope::cli {

namespace {

struct Common {
    QCommandLineOption type{
        QStringLiteral("type"),
        QStringLiteral("Data type (UNSIGNED16, INTEGER32, VISIBLE_STRING, DOMAIN, ...); default: from the dictionary."),
        QStringLiteral("T")};
    QCommandLineOption dict{
        QStringLiteral("dict"),
        QStringLiteral("Dictionary file or library name for the node (default: matched by its 1018h identity)."),
        QStringLiteral("FILE|NAME")};
    QCommandLineOption timeout{QStringLiteral("timeout"),
                               QStringLiteral("SDO timeout per response in ms (default 1000)."), QStringLiteral("MS"),
                               QStringLiteral("1000")};
    QCommandLineOption block{QStringLiteral("block"),
                             QStringLiteral("Use SDO block transfer (segmented if the node declines).")};
    void add(QCommandLineParser& p) { p.addOptions({type, dict, timeout, block}); }
};

struct Target {
    uint8_t node = 0;
    uint16_t index = 0;
    uint8_t sub = 0;
    std::optional<od::DataType> type;
    QString name;
    QString unit;
    double factor = 1.0;
    od::Limits limits;
};

// Resolves type and name: --type wins for the type; names and types come from the node's
// dictionary (given or matched by identity), else from the CiA 301/402 standard objects
// (eds::standardDictionary), so a node without a dictionary still shows 1008h as text.
bool resolve(BusSession& s, Target& t, const QCommandLineParser& p, const Common& c, QString* error) {
    if (p.isSet(c.type)) {
        t.type = od::dataTypeFromString(p.value(c.type));
        if (!t.type) {
            *error = QStringLiteral("unknown data type '%1'").arg(p.value(c.type));
            return false;
        }
    }
    QString dictName, why;
    std::optional<od::ObjectDictionary> dict;
    if (!t.type || p.isSet(c.dict)) dict = s.nodeDictionary(t.node, p.value(c.dict), &dictName, &why);
    if (!dict && p.isSet(c.dict)) {
        *error = why;
        return false;
    }
    const od::ObjectDictionary* names = nullptr;
    const od::SubObject* e = eds::entryWithStandard(dict ? &*dict : nullptr, t.index, t.sub, &names);
    if (!e) return true;  // shown as bytes
    t.name = names->displayName(t.index, t.sub);
    if (!t.type) t.type = e->dataType;
    if (auto u = names->unit(t.index, t.sub)) {
        t.unit = u->text;
        t.factor = u->factor;
    }
    t.limits = e->limits();
    return true;
}

int runSdo(const QStringList& args, bool isRead) {
    const QString verb = isRead ? QStringLiteral("sdo read") : QStringLiteral("sdo write");
    QCommandLineParser p;
    p.setApplicationDescription(isRead ? QStringLiteral("Read an object from a node over SDO.")
                                       : QStringLiteral("Write an object of a node over SDO (never retried)."));
    p.addPositionalArgument(QStringLiteral("BUS"), QStringLiteral("Bus URL, e.g. socketcan://can0 or sim://"));
    p.addPositionalArgument(QStringLiteral("NODE"), QStringLiteral("Node-ID 1-127"));
    p.addPositionalArgument(QStringLiteral("IDX:SUB"), QStringLiteral("Object, e.g. 6041:00"));
    if (!isRead)
        p.addPositionalArgument(QStringLiteral("VALUE"),
                                QStringLiteral("Value as text (0x1F, -5, 1.5, \"text\", hex bytes for DOMAIN)"));
    Common c;
    c.add(p);
    int code = 0;
    if (!parseArgs(p, verb, args, &code)) return code;
    const QStringList pos = p.positionalArguments();
    if (pos.size() != (isRead ? 3 : 4))
        return usageError(verb, isRead ? QStringLiteral("expects BUS NODE IDX:SUB")
                                       : QStringLiteral("expects BUS NODE IDX:SUB VALUE"));
    Target t;
    auto node = parseNodeId(pos[1]);
    if (!node) return usageError(verb, QStringLiteral("node-ID '%1' must be 1-127").arg(pos[1]));
    t.node = *node;
    if (!parseObjectRef(pos[2], &t.index, &t.sub))
        return usageError(verb, QStringLiteral("'%1' is not an object reference IDX:SUB (e.g. 6041:00)").arg(pos[2]));
    bool ok = false;
    const int timeoutMs = p.value(c.timeout).toInt(&ok);
    if (!ok || timeoutMs <= 0) return usageError(verb, QStringLiteral("--timeout must be a positive number of ms"));
    if (p.isSet(c.type) && !od::dataTypeFromString(p.value(c.type)))
        return usageError(verb, QStringLiteral("unknown data type '%1'").arg(p.value(c.type)));

    BusSession s;
    QString error;
    if (!s.open(pos[0], &error)) return failure(verb, error);
    s.sdo().setDefaultTimeout(timeoutMs);
    if (!resolve(s, t, p, c, &error)) return failure(verb, error);

    canopen::SdoOptions o;
    if (p.isSet(c.block)) o.protocol = canopen::SdoOptions::Protocol::Block;
    const QString ref = canopen::objectRef(t.index, t.sub);
    const QString label = t.name.isEmpty() ? ref : QStringLiteral("%1 %2").arg(ref, t.name);
    QTextStream out(stdout);

    if (isRead) {
        auto r = canopen::waitForResult<canopen::SdoResult>(
            [&](auto cb) { s.sdo().upload(t.node, t.index, t.sub, cb, o); }, 600000);
        if (!r) return failure(verb, QStringLiteral("no result from node %1").arg(t.node));
        if (!r->ok) return failure(verb, r->error);
        if (!t.type) {
            out << label << " = " << r->data.toHex(' ') << " (" << r->data.size() << " bytes)\n";
            return Ok;
        }
        QByteArray bytes = r->data;
        const int size = od::byteSize(*t.type);
        // An expedited answer without size indication carries 4 bytes: keep the type's width.
        if (size > 0 && bytes.size() > size) bytes.truncate(size);
        const od::ValueResult v = od::Value::decode(*t.type, bytes);
        if (!v.ok())
            return failure(verb, QStringLiteral("node %1 %2: %3 (bytes %4)")
                                     .arg(t.node)
                                     .arg(ref, v.error, QString::fromLatin1(r->data.toHex(' '))));
        od::FormatOptions fo;
        fo.unit = t.unit;
        fo.factor = t.factor;
        QString text = v.value.format(*t.type, fo);
        if (od::isInteger(*t.type)) {
            od::FormatOptions hx;
            hx.hex = true;
            text += QStringLiteral(" (%1)").arg(v.value.format(*t.type, hx));
        }
        out << label << " (" << od::dataTypeName(*t.type) << ") = " << text << "\n";
        return Ok;
    }

    if (!t.type)
        return failure(
            verb, QStringLiteral("the type of %1 is unknown for node %2: give --type or --dict").arg(ref).arg(t.node));
    const od::ValueResult v = od::Value::parse(*t.type, pos[3], t.limits);
    if (!v.ok())
        return failure(
            verb, QStringLiteral("value '%1' for %2 (%3): %4").arg(pos[3], ref, od::dataTypeName(*t.type), v.error));
    QString encError;
    const QByteArray bytes = v.value.encode(*t.type, &encError);
    if (!encError.isEmpty()) return failure(verb, encError);
    auto r = canopen::waitForResult<canopen::SdoResult>(
        [&](auto cb) { s.sdo().download(t.node, t.index, t.sub, bytes, cb, o); }, 600000);
    if (!r) return failure(verb, QStringLiteral("no result from node %1").arg(t.node));
    if (!r->ok) return failure(verb, r->error);
    out << label << " (" << od::dataTypeName(*t.type) << ") <- " << v.value.format(*t.type) << "\n";
    return Ok;
}

}  // namespace

COSCOPE_CLI_VERB({QStringLiteral("sdo read"), QStringLiteral("Read an object of a node over SDO."),
                  [](const QStringList& a) { return runSdo(a, true); }});
COSCOPE_CLI_VERB({QStringLiteral("sdo write"), QStringLiteral("Write an object of a node over SDO."),
                  [](const QStringList& a) { return runSdo(a, false); }});

}  // namespace coscope::cli
