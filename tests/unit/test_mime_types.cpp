// SPDX-License-Identifier: GPL-3.0-or-later
// The MIME types the desktop entry registers (resources/desktop/coscope.mime.xml) agree with the
// log readers (core/logio/LogFormats): every extension a reader claims has a glob, every glob
// names a readable format, and each type's magic is content the readers' sniffing recognises as
// that same format. A new log format fails here until it has its <mime-type>.
#include "core/logio/LogFormats.h"

#include <QFile>
#include <QXmlStreamReader>
#include <QtEndian>
#include <QtTest>

#include <cstring>

using namespace coscope::logio;

namespace {

struct MimeType {
    QString type;
    QStringList globs;
    QList<QByteArray> magics;  // the first bytes a file of this type starts with
};

// A <match> as the bytes it expects at offset 0 (string, or a 32-bit number in host order).
QByteArray matchBytes(const QXmlStreamAttributes& a) {
    const QString kind = a.value(QLatin1StringView("type")).toString();
    const QString value = a.value(QLatin1StringView("value")).toString();
    if (kind == u"string") return value.toLatin1();
    bool ok = false;
    const quint32 n = value.toUInt(&ok, 16);
    if (!ok) return {};
    quint32 stored = n;
    if (kind == u"big32") stored = qToBigEndian(n);
    else if (kind == u"little32") stored = qToLittleEndian(n);
    QByteArray bytes(4, '\0');
    std::memcpy(bytes.data(), &stored, 4);
    return bytes;
}

QList<MimeType> readMimeTypes(QString* error) {
    QFile file(QStringLiteral(COSCOPE_SOURCE_DIR "/resources/desktop/coscope.mime.xml"));
    if (!file.open(QIODevice::ReadOnly)) {
        *error = file.errorString();
        return {};
    }
    QList<MimeType> types;
    QXmlStreamReader xml(&file);
    while (!xml.atEnd()) {
        if (xml.readNext() != QXmlStreamReader::StartElement) continue;
        const auto a = xml.attributes();
        if (xml.name() == u"mime-type") types.append({a.value(QLatin1StringView("type")).toString(), {}, {}});
        else if (xml.name() == u"glob" && !types.isEmpty())
            types.last().globs << a.value(QLatin1StringView("pattern")).toString();
        else if (xml.name() == u"match" && !types.isEmpty() &&
                 a.value(QLatin1StringView("offset")) == QLatin1StringView("0"))
            types.last().magics << matchBytes(a);
    }
    if (xml.hasError()) *error = QStringLiteral("line %1: %2").arg(xml.lineNumber()).arg(xml.errorString());
    return types;
}

// Extensions too generic to claim for CAN logs (any program writes *.log, *.txt and *.csv; the
// readers tell CoScope, GVRET and IXXAT CSV apart by content, not by name).
const QStringList genericExtensions{QStringLiteral("log"), QStringLiteral("txt"), QStringLiteral("csv")};

}  // namespace

class TestMimeTypes : public QObject {
    Q_OBJECT
private slots:
    void everyReadableExtensionHasAGlob() {
        QString error;
        const auto types = readMimeTypes(&error);
        QVERIFY2(error.isEmpty(), qPrintable(error));
        QStringList globs;
        for (const auto& t : types) globs << t.globs;
        int checked = 0;
        for (const LogFormatInfo& f : LogFormats::all()) {
            if (!f.canRead) continue;
            for (const QString& ext : f.extensions) {
                if (genericExtensions.contains(ext)) continue;
                QVERIFY2(
                    globs.contains(QStringLiteral("*.") + ext),
                    qPrintable(QStringLiteral("format %1 reads *.%2, but resources/desktop/coscope.mime.xml has no "
                                              "<glob pattern=\"*.%2\"/>: add a <mime-type> for it")
                                   .arg(f.name, ext)));
                ++checked;
            }
        }
        QVERIFY(checked >= 5);  // trc, asc, blf, pcapng, pcap at least
    }

    void globsAndMagicNameOneReadableFormat() {
        QString error;
        const auto types = readMimeTypes(&error);
        QVERIFY2(error.isEmpty(), qPrintable(error));
        QVERIFY(types.size() >= 5);
        for (const MimeType& t : types) {
            QVERIFY2(!t.globs.isEmpty(), qPrintable(t.type));
            // All globs of a type lead to one format, and a reader exists for it.
            QString format;
            for (const QString& glob : t.globs) {
                const QString name = QString(glob).replace(u'*', QStringLiteral("capture"));
                const QString byName = LogFormats::formatForExtension(name);
                QVERIFY2(!byName.isEmpty(), qPrintable(QStringLiteral("%1: no format reads %2").arg(t.type, glob)));
                QVERIFY2(format.isEmpty() || format == byName, qPrintable(t.type));
                format = byName;
            }
            QVERIFY2(LogFormats::createReader(format) != nullptr, qPrintable(format));
            // The magic is what the readers sniff as that format.
            for (const QByteArray& head : t.magics) {
                QVERIFY2(!head.isEmpty(), qPrintable(t.type));
                // Text magic goes on with a word, binary with zeros (a header's other fields).
                const bool text = head.front() >= 0x20;
                const QByteArray sample = head + (text ? QByteArray(" 1\n") : QByteArray(32, '\0'));
                QCOMPARE(LogFormats::detectContent(sample), format);
            }
        }
    }

    void noGlobClaimsEveryLogOrTextFile() {
        // A type with only generic globs would claim files that are not CAN logs.
        QString error;
        for (const MimeType& t : readMimeTypes(&error)) {
            for (const QString& glob : t.globs) {
                const QString ext = glob.section(u'.', -1);
                QVERIFY2(!genericExtensions.contains(ext) || !glob.startsWith(QStringLiteral("*.")),
                         qPrintable(QStringLiteral("%1 claims every %2").arg(t.type, glob)));
            }
        }
    }
};

QTEST_GUILESS_MAIN(TestMimeTypes)
#include "test_mime_types.moc"
