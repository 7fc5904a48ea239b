// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/logio/LogFormats.h"

#include "core/logio/BusmasterLog.h"
#include "core/logio/CandumpLog.h"
#include "core/logio/CsvReader.h"
#include "core/logio/CsvWriter.h"
#include "core/logio/GvretCsv.h"
#include "core/logio/IxxatTrace.h"
#include "core/logio/KvaserText.h"
#include "core/logio/Mdf4Log.h"
#include "core/logio/PcapLog.h"
#include "core/logio/PeakTrc.h"
#include "core/logio/TextScan.h"
#include "core/logio/VectorAsc.h"
#include "core/logio/VectorBlf.h"

#include <QFile>
#include <QFileInfo>

namespace coscope::logio::LogFormats {

const std::vector<LogFormatInfo>& all() {
    static const std::vector<LogFormatInfo> formats = {
        {QStringLiteral("candump"),
         QStringLiteral("can-utils candump (-L log files and default text)"),
         {QStringLiteral("log"), QStringLiteral("candump"), QStringLiteral("txt")},
         true,
         true},
        {QStringLiteral("asc"), QStringLiteral("Vector ASCII log"), {QStringLiteral("asc")}, true, true},
        {QStringLiteral("blf"), QStringLiteral("Vector binary log"), {QStringLiteral("blf")}, true, true},
        {QStringLiteral("trc"), QStringLiteral("PEAK trace 1.0-2.1 (writes 2.1)"), {QStringLiteral("trc")}, true, true},
        {QStringLiteral("pcap"),
         QStringLiteral("pcap/pcapng, SocketCAN link type (writes pcapng)"),
         {QStringLiteral("pcapng"), QStringLiteral("pcap")},
         true,
         true},
        {QStringLiteral("csv"),
         QStringLiteral("CoScope CSV with a decoded summary column"),
         {QStringLiteral("csv")},
         true,
         true},
        {QStringLiteral("gvret"),
         QStringLiteral("SavvyCAN GVRET CSV (read only)"),
         {QStringLiteral("csv")},
         true,
         false},
        {QStringLiteral("busmaster"),
         QStringLiteral("BUSMASTER log 1.x-3.x, hex/dec, system/absolute/relative time (read only)"),
         {QStringLiteral("log")},
         true,
         false},
        {QStringLiteral("ixxat"),
         QStringLiteral("IXXAT MiniMon / canAnalyser text export (read only)"),
         {QStringLiteral("csv"), QStringLiteral("trc")},
         true,
         false},
        {QStringLiteral("kvaser"),
         QStringLiteral("Kvaser CanKing / Memorator text export, hex (read only)"),
         {QStringLiteral("txt")},
         true,
         false},
        {QStringLiteral("mf4"),
         QStringLiteral("ASAM MDF4 bus logging (CANedge, Vector, PEAK, Kvaser loggers; read only)"),
         {QStringLiteral("mf4")},
         true,
         false},
    };
    return formats;
}

namespace {
bool contains(std::string_view hay, std::string_view needle) { return hay.find(needle) != std::string_view::npos; }
}  // namespace

QString detectContent(const QByteArray& head) {
    if (head.size() >= 4) {
        const auto* p = reinterpret_cast<const unsigned char*>(head.constData());
        if (std::memcmp(p, "LOGG", 4) == 0) return QStringLiteral("blf");
        if (head.size() >= 8 && (std::memcmp(p, "MDF     ", 8) == 0 || std::memcmp(p, "UnFinMF ", 8) == 0))
            return QStringLiteral("mf4");
        const uint32_t le = le32(p), be = be32(p);
        if (le == 0x0A0D0D0A || le == 0xA1B2C3D4 || le == 0xA1B23C4D || be == 0xA1B2C3D4 || be == 0xA1B23C4D)
            return QStringLiteral("pcap");
    }
    // Text: look at the first lines.
    const std::string_view text(head.constData(), size_t(head.size()));
    {
        // Formats that announce themselves in their first non-empty line (a .trc, .log or .csv
        // name alone says nothing: PEAK vs IXXAT .trc, candump vs BUSMASTER .log).
        size_t start = 0;
        if (text.substr(0, 3) == "\xEF\xBB\xBF") start = 3;  // UTF-8 BOM
        while (start < text.size() && isSpace(text[start])) ++start;
        const size_t nl = text.find('\n', start);
        const std::string_view first =
            trimmed(text.substr(start, nl == std::string_view::npos ? std::string_view::npos : nl - start));
        if (isCoScopeCsvHeader(first)) return QStringLiteral("csv");
        if (isGvretHeader(first)) return QStringLiteral("gvret");
        if (isKvaserHeader(first)) return QStringLiteral("kvaser");
        if (first.substr(0, 3) == "***" &&
            (contains(text.substr(0, 4096), "BUSMASTER") || contains(text.substr(0, 4096), "***<Time><Tx/Rx>")))
            return QStringLiteral("busmaster");
        if (isIxxatFirstLine(first)) return QStringLiteral("ixxat");
    }
    if (contains(text, ";$FILEVERSION") || contains(text, ";$STARTTIME")) return QStringLiteral("trc");
    size_t pos = 0;
    int lines = 0;
    while (pos < text.size() && lines < 40) {
        size_t nl = text.find('\n', pos);
        if (nl == std::string_view::npos) nl = text.size();
        const std::string_view line = trimmed(text.substr(pos, nl - pos));
        pos = nl + 1;
        ++lines;
        if (line.empty()) continue;
        if (startsWithNoCase(line, "date ") || startsWithNoCase(line, "base hex") ||
            startsWithNoCase(line, "base dec") || startsWithNoCase(line, "begin triggerblock"))
            return QStringLiteral("asc");
        Tokens t(line);
        std::string_view first = t.next();
        if (first.size() > 1 && first.back() == ')' && first.front() != '(') {
            if (parseDec(first.substr(0, first.size() - 1)))
                return QStringLiteral("trc");  // "  12)  ..." message number
        }
        if (first.front() == '(' && first.back() == ')') first = t.next();  // candump timestamp
        const std::string_view second = t.next();
        if (second.find('#') != std::string_view::npos && parseHex(second.substr(0, second.find('#'))))
            return QStringLiteral("candump");
        const std::string_view third = t.next();
        if (!third.empty() && third.front() == '[' && third.back() == ']' && parseHex(second))
            return QStringLiteral("candump");
    }
    return {};
}

QString formatForExtension(const QString& path) {
    const QString ext = QFileInfo(path).suffix().toLower();
    if (ext.isEmpty()) return {};
    for (const auto& f : all())
        if (f.extensions.contains(ext)) return f.name;
    return {};
}

QString detect(QIODevice* device, const QString& fileName) {
    const QString byContent = device ? detectContent(device->peek(8192)) : QString();
    return byContent.isEmpty() ? formatForExtension(fileName) : byContent;
}

std::unique_ptr<LogReader> createReader(const QString& format) {
    const QString f = format.toLower();
    if (f == u"candump" || f == u"log") return std::make_unique<CandumpReader>();
    if (f == u"asc") return std::make_unique<AscReader>();
    if (f == u"blf") return std::make_unique<BlfReader>();
    if (f == u"trc") return std::make_unique<TrcReader>();
    if (f == u"pcap" || f == u"pcapng") return std::make_unique<PcapReader>();
    if (f == u"csv") return std::make_unique<CsvReader>();
    if (f == u"gvret" || f == u"savvycan") return std::make_unique<GvretCsvReader>();
    if (f == u"busmaster") return std::make_unique<BusmasterReader>();
    if (f == u"ixxat") return std::make_unique<IxxatReader>();
    if (f == u"kvaser") return std::make_unique<KvaserReader>();
    if (f == u"mf4" || f == u"mdf4" || f == u"mdf") return std::make_unique<Mdf4Reader>();
    return nullptr;
}

std::unique_ptr<LogReader> openReader(const QString& path, QString* error) {
    QFile probe(path);
    if (!probe.open(QIODevice::ReadOnly)) {
        if (error) *error = QStringLiteral("cannot open %1: %2").arg(path, probe.errorString());
        return nullptr;
    }
    const QString format = detect(&probe, path);
    probe.close();
    if (format.isEmpty()) {
        if (error)
            *error = QStringLiteral(
                         "%1: not a format CoScope reads (tried candump, Vector ASC and BLF, PEAK TRC, pcap/pcapng, "
                         "CoScope CSV, SavvyCAN GVRET, BUSMASTER, IXXAT, Kvaser and ASAM MDF4)")
                         .arg(path);
        return nullptr;
    }
    auto reader = createReader(format);
    if (!reader) {
        if (error) *error = QStringLiteral("%1: format %2 cannot be read").arg(path, format);
        return nullptr;
    }
    if (!reader->open(path)) {
        if (error) *error = QStringLiteral("%1: %2").arg(path, reader->errorString());
        return nullptr;
    }
    return reader;
}

std::unique_ptr<LogWriter> createWriter(const QString& format) {
    const QString f = format.toLower();
    if (f == u"candump" || f == u"log") return std::make_unique<CandumpWriter>();
    if (f == u"asc") return std::make_unique<AscWriter>();
    if (f == u"blf") return std::make_unique<BlfWriter>();
    if (f == u"trc") return std::make_unique<TrcWriter>();
    if (f == u"pcapng" || f == u"pcap") return std::make_unique<PcapngWriter>();
    if (f == u"csv") return std::make_unique<CsvWriter>();
    return nullptr;
}

QString writerFormatFor(const QString& outputPath, const QString& explicitFormat, QString* error) {
    QString f = explicitFormat.toLower();
    if (f.isEmpty()) {
        const QString ext = QFileInfo(outputPath).suffix().toLower();
        if (ext == u"log" || ext == u"candump") f = QStringLiteral("candump");
        else if (ext == u"asc" || ext == u"blf" || ext == u"trc" || ext == u"csv") f = ext;
        else if (ext == u"pcapng" || ext == u"pcap") f = QStringLiteral("pcapng");
        if (f.isEmpty()) {
            if (error)
                *error = QStringLiteral(
                             "cannot tell the output format from '%1'; use .log, .asc, .blf, .trc, .pcapng or .csv, or "
                             "--to FORMAT")
                             .arg(outputPath);
            return {};
        }
    }
    if (!createWriter(f)) {
        if (error)
            *error = QStringLiteral("unknown output format '%1'; use candump, asc, blf, trc, pcapng or csv").arg(f);
        return {};
    }
    return f == u"log" ? QStringLiteral("candump") : f == u"pcap" ? QStringLiteral("pcapng") : f;
}

}  // namespace coscope::logio::LogFormats
