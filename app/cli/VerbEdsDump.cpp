// SPDX-License-Identifier: GPL-3.0-or-later
// coscope-cli eds dump FILE [--node-id N] [--format text|json]: the entries of a dictionary.
#include "app/cli/CliVerb.h"
#include "eds/DictionaryLibrary.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTextStream>

namespace coscope::cli {

namespace {

QJsonValue jsonValue(const od::SubObject& s, const std::optional<od::Value>& v) {
    if (!v) return QJsonValue::Null;
    switch (od::typeClass(s.dataType)) {
    case od::TypeClass::Boolean: return v->toUInt64().value_or(0) != 0;
    case od::TypeClass::Signed: return static_cast<double>(v->toInt64().value_or(0));
    case od::TypeClass::Unsigned:
    case od::TypeClass::Time: {
        const auto u = v->toUInt64().value_or(0);
        return u <= (1ull << 53) ? QJsonValue(static_cast<double>(u)) : QJsonValue(QString::number(u));
    }
    case od::TypeClass::Real: return v->toDouble().value_or(0);
    default: return v->format(s.dataType);
    }
}

QJsonValue limitValue(const od::SubObject& s, const QString& text, std::uint8_t node) {
    if (text.isEmpty()) return QJsonValue::Null;
    return jsonValue(s, s.interpret(text, node));
}

}  // namespace

static int runEdsDump(const QStringList& args) {
    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral("Print the entries of a dictionary (file or bundled name)."));
    parser.addPositionalArgument(QStringLiteral("FILE"), QStringLiteral("EDS/DCF/XDD file or dictionary name."));
    parser.addOption(
        {QStringLiteral("node-id"), QStringLiteral("Resolve $NODEID with N (1..127)."), QStringLiteral("N")});
    parser.addOption({QStringLiteral("format"), QStringLiteral("text (default) or json."), QStringLiteral("FORMAT"),
                      QStringLiteral("text")});
    int code = 0;
    const QString verb = QStringLiteral("eds dump");
    if (!parseArgs(parser, verb, args, &code)) return code;
    const QStringList pos = parser.positionalArguments();
    if (pos.size() != 1) return usageError(verb, QStringLiteral("needs exactly one FILE"));
    const QString format = parser.value(QStringLiteral("format"));
    if (format != u"text" && format != u"json")
        return usageError(verb, QStringLiteral("--format must be text or json, not '%1'").arg(format));
    int node = -1;
    if (parser.isSet(QStringLiteral("node-id"))) {
        bool ok = false;
        node = parser.value(QStringLiteral("node-id")).toInt(&ok, 0);
        if (!ok || node < 1 || node > 127)
            return usageError(
                verb,
                QStringLiteral("--node-id must be 1..127, not '%1'").arg(parser.value(QStringLiteral("node-id"))));
    }
    const eds::ReadResult r = eds::loadDictionaryByPathOrName(pos.front());
    if (!r.usable) {
        QString why = r.diagnostics.empty() ? QStringLiteral("not usable") : r.diagnostics.back().toString();
        return failure(verb, why);
    }
    const od::ObjectDictionary& od = r.dictionary;
    const std::uint8_t nodeId = static_cast<std::uint8_t>(node > 0 ? node : (od.nodeId() ? od.nodeId() : 0));
    QTextStream out(stdout);
    if (format == u"json") {
        QJsonArray list;
        for (const auto& [index, obj] : od.objects()) {
            for (const od::SubObject& s : obj.subs) {
                QJsonObject e;
                e.insert(QStringLiteral("index"), index);
                e.insert(QStringLiteral("sub"), s.sub);
                e.insert(QStringLiteral("name"), od.displayName(index, s.sub));
                e.insert(QStringLiteral("type"), od::dataTypeName(s.dataType));
                e.insert(QStringLiteral("access"), od::accessName(s.access));
                e.insert(QStringLiteral("pdo"), s.pdoMappable);
                e.insert(QStringLiteral("default"), jsonValue(s, s.resolvedDefault(nodeId)));
                e.insert(QStringLiteral("value"), jsonValue(s, s.resolvedValue(nodeId)));
                e.insert(QStringLiteral("low"), limitValue(s, s.lowLimit, nodeId));
                e.insert(QStringLiteral("high"), limitValue(s, s.highLimit, nodeId));
                if (s.unit) e.insert(QStringLiteral("unit"), s.unit->text);
                list.append(e);
            }
        }
        out << QJsonDocument(list).toJson(QJsonDocument::Indented);
        return Ok;
    }
    const auto& d = od.device;
    out << "Vendor: " << d.vendorName;
    if (od.vendorId()) out << QStringLiteral(" (0x%1)").arg(*od.vendorId(), 8, 16, QLatin1Char('0'));
    out << "\nProduct: " << d.productName;
    if (od.productCode()) out << QStringLiteral(" (0x%1)").arg(*od.productCode(), 8, 16, QLatin1Char('0'));
    if (od.revisionNumber())
        out << QStringLiteral(", revision 0x%1").arg(*od.revisionNumber(), 8, 16, QLatin1Char('0'));
    out << "\nObjects: " << od.objectCount() << ", sub-objects: " << od.subObjectCount();
    if (nodeId) out << ", node-ID " << nodeId;
    out << "\n\n";
    for (const auto& [index, obj] : od.objects()) {
        out << QStringLiteral("%1     %2 %3\n")
                   .arg(index, 4, 16, QLatin1Char('0'))
                   .arg(od::objectTypeName(obj.objectType).leftJustified(9), obj.name);
        for (const od::SubObject& s : obj.subs) {
            const auto v = s.resolvedValue(nodeId);
            QString val = v ? v->format(s.dataType) : s.parameterValue.isEmpty() ? s.defaultValue : s.parameterValue;
            if (v && od::isInteger(s.dataType)) {
                od::FormatOptions hex;
                hex.hex = true;
                val += QStringLiteral(" (%1)").arg(v->format(s.dataType, hex));
            }
            if (s.unit && !s.unit->text.isEmpty()) val += u' ' + s.unit->text;
            out << QStringLiteral("%1:%2  %3 %4 %5 %6  %7\n")
                       .arg(index, 4, 16, QLatin1Char('0'))
                       .arg(s.sub, 2, 16, QLatin1Char('0'))
                       .arg(od::dataTypeName(s.dataType).leftJustified(15), od::accessName(s.access).leftJustified(5),
                            s.pdoMappable ? QStringLiteral("pdo") : QStringLiteral("   "),
                            (obj.isComposite() ? s.name : QString()).leftJustified(obj.isComposite() ? 32 : 0), val);
        }
    }
    return Ok;
}

COSCOPE_CLI_VERB({QStringLiteral("eds dump"), QStringLiteral("Print a dictionary's entries (text or JSON)."),
                  runEdsDump});

}  // namespace coscope::cli
