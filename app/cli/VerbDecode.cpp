// SPDX-License-Identifier: GPL-3.0-or-later
// coscope-cli decode LOG [--dict NODE=NAME|FILE]... [--signal NAME=COBID:START:LEN:TYPE...]...
//                       [--format text|jsonl|csv] [--filter EXPR]
// Decodes every frame of a log with the CANopen dissectors (formats in dissectors/DecodeOutput.h);
// raw signals (dissectors/RawSignal.h) join the PDO signals of their frames.
#include "app/cli/CliVerb.h"
#include "app/cli/TextWriter.h"
#include "core/logio/LogFormats.h"
#include "core/logio/ReadAhead.h"
#include "dissectors/DecodeFilter.h"
#include "dissectors/DecodeOutput.h"
#include "dissectors/NetworkContext.h"
#include "dissectors/RawSignal.h"

#include <cstdio>
#include <cstring>
#include <memory>
#include <span>
#include <string>
#include <thread>
#include <vector>

namespace coscope::cli {

namespace {

const QString kVerb = QStringLiteral("decode");

// --dict NODE=NAME|FILE for every entry; false with a usage message on error.
bool applyDicts(dissect::NetworkContext& ctx, const QStringList& dicts, int* code) {
    for (const QString& spec : dicts) {
        const qsizetype eq = spec.indexOf(u'=');
        bool ok = false;
        const int node = eq > 0 ? spec.left(eq).toInt(&ok, 0) : 0;
        if (!ok || node < 1 || node > 127) {
            *code =
                usageError(kVerb, QStringLiteral("--dict '%1': expected NODE=NAME|FILE with NODE 1..127").arg(spec));
            return false;
        }
        QString error;
        if (!ctx.assignDictionary(node, spec.mid(eq + 1), &error)) {
            *code = failure(kVerb, QStringLiteral("--dict %1: %2").arg(spec, error));
            return false;
        }
    }
    return true;
}

int runDecode(const QStringList& args) {
    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral("Decode a CAN log with the CANopen dissectors."));
    parser.addPositionalArgument(QStringLiteral("LOG"),
                                 QStringLiteral("Log file (candump, asc, blf, trc, pcap/pcapng, csv, mf4)."));
    parser.addOption({QStringLiteral("dict"),
                      QStringLiteral("Dictionary of a node: bundled name or EDS/DCF/XDD file (repeatable)."),
                      QStringLiteral("NODE=NAME|FILE")});
    parser.addOption({QStringLiteral("format"), QStringLiteral("Output format: text (default), jsonl, csv."),
                      QStringLiteral("FORMAT"), QStringLiteral("text")});
    parser.addOption({QStringLiteral("filter"),
                      QStringLiteral("Only frames matching: node=N, service=NAME, id=0x181 or 0x180-0x1FF, warnings; "
                                     "terms ANDed (repeatable)."),
                      QStringLiteral("EXPR")});
    parser.addOption(
        {QStringLiteral("signal"),
         QStringLiteral(
             "Raw signal of any frame, for devices without a dictionary (repeatable): TYPE u (unsigned), s (signed) "
             "or f (float 32/64) in Intel byte order, with @0 after it for Motorola (DBC start bit: the MSB), e.g. "
             "speed=0x181:16:16:s:0.1:0:rpm or temp=0x281:7:16:u@0:0.5:-40. COBID over 7FFh is a 29-bit id."),
         QStringLiteral("NAME=COBID:START:LEN:TYPE[:FACTOR[:OFFSET[:UNIT]]]")});
    parser.addOption(
        {QStringLiteral("no-identity"), QStringLiteral("Do not pick dictionaries by the identity read in the log.")});
    int code = 0;
    if (!parseArgs(parser, kVerb, args, &code)) return code;
    const QStringList pos = parser.positionalArguments();
    if (pos.size() != 1) return usageError(kVerb, QStringLiteral("expected one LOG file"));
    const QString format = parser.value(QStringLiteral("format")).toLower();
    if (format != QLatin1String("text") && format != QLatin1String("jsonl") && format != QLatin1String("csv"))
        return usageError(kVerb, QStringLiteral("--format must be text, jsonl or csv, not '%1'").arg(format));
    dissect::DecodeFilter filter;
    for (const QString& f : parser.values(QStringLiteral("filter"))) {
        QString error;
        if (!filter.parse(f, &error)) return usageError(kVerb, error);
    }
    std::vector<dissect::RawSignal> raw;
    for (const QString& spec : parser.values(QStringLiteral("signal"))) {
        QString error;
        const auto r = dissect::RawSignal::parse(spec, &error);
        if (!r) return usageError(kVerb, error);
        raw.push_back(*r);
    }
    // Parsing the generic dictionary (names for nodes without one of their own) runs beside the
    // reading of the first batches rather than on the decoding thread when an SDO first needs it.
    std::jthread preload([] { dissect::NetworkContext::genericDictionary(); });
    dissect::NetworkContext ctx;
    ctx.setIdentityMatching(!parser.isSet(QStringLiteral("no-identity")));
    if (!applyDicts(ctx, parser.values(QStringLiteral("dict")), &code)) return code;

    QString error;
    auto reader = logio::LogFormats::openReader(pos[0], &error);
    if (!reader) return failure(kVerb, error);

    const bool json = format == QLatin1String("jsonl");
    const bool csv = format == QLatin1String("csv");
    QByteArray out;
    out.reserve(1 << 20);
    if (csv) out.append(dissect::csvHeader());
    dissect::Dissection d;
    QStringList busNames;
    QString bus0 = QStringLiteral("can0");
    // Parsing the file runs on a second core, a few batches ahead of the decoding; text lines
    // are formatted and written on a third.
    auto ahead = std::make_unique<logio::ReadAhead>(*reader);
    if (!json && !csv) {
        TextWriter writer;
        for (auto batch = ahead->next(); !batch.empty(); batch = ahead->next()) {
            auto job = writer.take();
            job->busNames = ahead->busNames();
            ahead->keepBatch(job->frames);  // `batch` now lives in the job: no copy
            // Without raw signals (which extend the summary afterwards) the dissectors may write
            // their summaries straight into the job.
            d.summarySink = raw.empty() ? &job->summaries : nullptr;
            d.pdoTextSink = raw.empty() ? &job->pdo : nullptr;
            d.wantFields = !raw.empty();  // the raw signals join the PDO signals; text shows no other field
            for (size_t i = 0; i < batch.size(); ++i) {
                const CanFrame& f = batch[i];
                const size_t at = job->summaries.size();
                const size_t pdoAt = job->pdo.records.size();
                ctx.dissect(f, d, dissect::Dissection::Level::Flat);
                if (!raw.empty()) dissect::applyRawSignals(raw, f, d);
                const bool pdoRecord = job->pdo.records.size() != pdoAt;
                if (!filter.isEmpty() && !filter.matches(f, d)) {
                    job->summaries.truncate(at);
                    if (pdoRecord) {
                        job->pdo.values.resize(job->pdo.records.back().valuesAt);
                        job->pdo.records.pop_back();
                    }
                    continue;
                }
                if (job->summaries.size() == at && !pdoRecord) job->summaries += d.summary;  // not written in a sink
                TextWriter::Line& l = job->lines.emplace_back();  // in place: a copy would reload it whole
                l.frame = static_cast<uint32_t>(i);
                l.summaryAt = static_cast<uint32_t>(at);
                l.summaryLength = static_cast<uint32_t>(job->summaries.size() - at);
                if (pdoRecord) l.pdoRecord = static_cast<int>(pdoAt);
                if (!d.warnings.isEmpty()) {
                    l.warningAt = static_cast<int>(job->warnings.size());
                    l.warningCount = static_cast<int>(d.warnings.size());
                    job->warnings.append(d.warnings);
                }
                if (d.hasTransfer) {
                    l.transferAt = static_cast<int>(job->transfers.size());
                    dissect::appendTransferText(job->transfers, d);
                    l.transferLength = static_cast<int>(job->transfers.size()) - l.transferAt;
                }
            }
            d.summarySink = nullptr;
            d.pdoTextSink = nullptr;
            d.wantFields = true;
            writer.submit(std::move(job));
        }
    }  // the writer has written everything
    // jsonl and csv: formatted here.
    for (auto batch = (json || csv) ? ahead->next() : std::span<const CanFrame>(); !batch.empty();
         batch = ahead->next()) {
        if (busNames.size() != ahead->busNames().size()) busNames = ahead->busNames();
        for (const CanFrame& f : batch) {
            ctx.dissect(f, d, dissect::Dissection::Level::Flat);
            if (!raw.empty()) dissect::applyRawSignals(raw, f, d);
            if (!filter.isEmpty() && !filter.matches(f, d)) continue;
            const QString& bus = f.bus < busNames.size() ? busNames[f.bus] : bus0;
            if (json) {
                dissect::appendJson(out, f, d, bus);
                if (d.hasTransfer) dissect::appendTransferJson(out, f, d, bus);
            } else {
                dissect::appendCsv(out, f, d, bus);
            }
        }
        if (out.size() > (1 << 20)) {
            std::fwrite(out.constData(), 1, static_cast<size_t>(out.size()), stdout);
            out.resize(0);
        }
    }
    std::fwrite(out.constData(), 1, static_cast<size_t>(out.size()), stdout);
    std::fflush(stdout);
    ahead.reset();  // the reader is ours again
    int shown = 0;
    for (const auto& diag : reader->diagnostics()) {
        if (++shown > 20) break;
        std::fprintf(stderr, "%s:%lld: warning: %s\n", qPrintable(pos[0]), static_cast<long long>(diag.where),
                     qPrintable(diag.message));
    }
    if (reader->hasError()) return failure(kVerb, QStringLiteral("%1: %2").arg(pos[0], reader->errorString()));
    return Ok;
}

}  // namespace

COSCOPE_CLI_VERB({QStringLiteral("decode"), QStringLiteral("Decode a CAN log as CANopen (text, jsonl, csv)."),
                  runDecode});

}  // namespace coscope::cli
