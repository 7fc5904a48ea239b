// SPDX-License-Identifier: GPL-3.0-or-later
#include "eds/DocumentedIdentity.h"

#include "eds/EdsReader.h"
#include "eds/TextDecoding.h"

#include <QFile>

namespace coscope::eds {

namespace {

std::optional<std::uint32_t> defaultNumber(const od::ObjectDictionary& d, std::uint16_t index) {
    const od::SubObject* s = d.entry(index, 0);
    if (!s || s->defaultValue.isEmpty()) return std::nullopt;
    bool ok = false;
    const std::uint32_t v = s->defaultValue.trimmed().toUInt(&ok, 0);
    return ok ? std::optional<std::uint32_t>(v) : std::nullopt;
}

// Whether the identity may depend on section `lower` (its name trimmed and in lower case, as
// IniDocument keys it).
bool bearsOnIdentity(QStringView lower) {
    // Not the object lists: the reader reads an object section that no list names all the same.
    for (const char* name : {"fileinfo", "deviceinfo", "devicecommissioning", "devicecomissioning"})
        if (lower == QLatin1String(name)) return true;
    if (lower.size() < 4) return false;
    bool ok = false;
    const uint index = lower.left(4).toUInt(&ok, 16);
    // [1018], [1018sub1], [1018Value]…; data type definitions (0001h..0FFFh) may type them.
    return ok && (index < 0x1000 || index == 0x1000 || index == 0x1008 || index == 0x1018);
}

}  // namespace

DocumentedIdentity documentedIdentity(const od::ObjectDictionary& d) {
    DocumentedIdentity id;
    id.vendorId = d.vendorId();
    id.productCode = d.productCode();
    id.revision = d.revisionNumber();
    id.deviceType = defaultNumber(d, 0x1000);
    if (const od::SubObject* s = d.entry(0x1008, 0)) id.deviceName = s->defaultValue.trimmed();
    return id;
}

std::optional<DocumentedIdentity> readDocumentedIdentity(const QString& path) {
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly)) return std::nullopt;
    const QString text = decodeDictionaryText(f.readAll());
    if (text.trimmed().startsWith(u'<')) return std::nullopt;  // XDD: read it whole
    // The lines of the sections that bear on the identity; a section starts where IniDocument
    // starts one: a line that begins with '[' once trimmed.
    QString kept;
    bool keep = false;
    for (qsizetype pos = 0; pos < text.size();) {
        qsizetype end = text.indexOf(u'\n', pos);
        end = end < 0 ? text.size() : end + 1;
        const QStringView line = QStringView(text).mid(pos, end - pos);
        const QStringView trimmed = line.trimmed();
        if (trimmed.startsWith(u'[')) {
            const qsizetype close = trimmed.indexOf(u']');
            const QString name = (close < 0 ? trimmed.mid(1) : trimmed.mid(1, close - 1)).trimmed().toString();
            keep = bearsOnIdentity(name.toLower());
        }
        if (keep) kept += line;
        pos = end;
    }
    const ReadResult r = EdsReader::read(kept.toUtf8(), path);
    return documentedIdentity(r.dictionary);
}

}  // namespace coscope::eds
