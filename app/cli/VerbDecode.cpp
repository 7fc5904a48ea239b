// SPDX-License-Identifier: GPL-3.0-or-later
// coscope-cli decode LOG [--dict NODE=NAME|FILE]... [--signal NAME=COBID:START:LEN:TYPE...]...
//                       [--format text|jsonl|csv] [--filter EXPR]
// Decodes every frame of a log with the CANopen dissectors (formats in dissectors/DecodeOutput.h);
// raw signals (dissectors/RawSignal.h) join the PDO signals of their frames.
#include "app/cli/CliVerb.h"
#include "core/logio/LogFormats.h"
#include "core/logio/ReadAhead.h"
#include "dissectors/DecodeFilter.h"
#include "dissectors/DecodeOutput.h"
#include "dissectors/NetworkContext.h"
#include "dissectors/RawSignal.h"

#include <condition_variable>
#include <cstdio>
#include <cstring>
#include <deque>
#include <memory>
#include <mutex>
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
            *code = usageError(kVerb, QStringLiteral("--dict '%1': expected NODE=NAME|FILE with NODE 1..127").arg(spec));
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

// --format text on a thread of its own: the decoding thread hands over each batch's frames with
// their summaries, warnings and transfer lines; this thread formats the lines with appendText()
// (the same bytes as formatting them in place) and writes them to stdout.
class TextWriter {
public:
    struct Line {
        uint32_t frame = 0;           // index in Job::frames
        uint32_t summaryAt = 0, summaryLength = 0;  // in Job::summaries
        int warningAt = 0, warningCount = 0;        // in Job::warnings
        int transferAt = 0, transferLength = 0;     // in Job::transfers (appendTransferText)
    };
    struct Job {
        std::vector<CanFrame> frames;
        std::vector<Line> lines;
        std::u16string summaries;
        QStringList warnings;
        QByteArray transfers;
        QStringList busNames;
    };

    TextWriter() : thread_([this] { run(); }) {}
    ~TextWriter() { finish(); }
    TextWriter(const TextWriter&) = delete;
    TextWriter& operator=(const TextWriter&) = delete;

    // An empty job to fill (recycled, so its buffers keep their capacity).
    std::unique_ptr<Job> take() {
        std::unique_lock lock(mutex_);
        changed_.wait(lock, [&] { return !free_.empty() || created_ < kDepth; });
        if (free_.empty()) {
            ++created_;
            return std::make_unique<Job>();
        }
        auto job = std::move(free_.back());
        free_.pop_back();
        return job;
    }
    void submit(std::unique_ptr<Job> job) {
        std::lock_guard lock(mutex_);
        queue_.push_back(std::move(job));
        changed_.notify_all();
    }
    // Writes what is queued and ends the thread.
    void finish() {
        {
            std::lock_guard lock(mutex_);
            done_ = true;
            changed_.notify_all();
        }
        if (thread_.joinable()) thread_.join();
    }

private:
    static constexpr size_t kDepth = 4;
    void run() {
        QByteArray out;
        out.reserve(1 << 21);
        dissect::Dissection d;
        const QString bus0 = QStringLiteral("can0");
        for (;;) {
            std::unique_ptr<Job> job;
            {
                std::unique_lock lock(mutex_);
                changed_.wait(lock, [&] { return !queue_.empty() || done_; });
                if (queue_.empty()) break;
                job = std::move(queue_.front());
                queue_.pop_front();
            }
            for (const Line& l : job->lines) {
                const CanFrame& f = job->frames[l.frame];
                d.summary.resize(static_cast<qsizetype>(l.summaryLength));
                if (l.summaryLength) std::memcpy(static_cast<void*>(d.summary.data()), job->summaries.data() + l.summaryAt, l.summaryLength * sizeof(char16_t));
                if (!d.warnings.isEmpty()) d.warnings.clear();
                for (int i = 0; i < l.warningCount; ++i) d.warnings.append(job->warnings[l.warningAt + i]);
                const QString& bus = f.bus < job->busNames.size() ? job->busNames[f.bus] : bus0;
                dissect::appendText(out, f, d, bus);
                if (l.transferLength) out.append(job->transfers.constData() + l.transferAt, l.transferLength);
            }
            if (out.size() > (1 << 20)) {
                std::fwrite(out.constData(), 1, static_cast<size_t>(out.size()), stdout);
                out.resize(0);
            }
            job->lines.clear();
            job->summaries.clear();
            job->warnings.clear();
            job->transfers.resize(0);
            std::lock_guard lock(mutex_);
            free_.push_back(std::move(job));
            changed_.notify_all();
        }
        std::fwrite(out.constData(), 1, static_cast<size_t>(out.size()), stdout);
        std::fflush(stdout);
    }

    std::mutex mutex_;
    std::condition_variable changed_;
    std::deque<std::unique_ptr<Job>> queue_;
    std::vector<std::unique_ptr<Job>> free_;
    size_t created_ = 0;
    bool done_ = false;
    std::thread thread_;  // last: starts when the rest is ready
};

int runDecode(const QStringList& args) {
    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral("Decode a CAN log with the CANopen dissectors."));
    parser.addPositionalArgument(QStringLiteral("LOG"), QStringLiteral("Log file (candump, asc, blf, trc, pcap/pcapng, csv)."));
    parser.addOption({QStringLiteral("dict"), QStringLiteral("Dictionary of a node: bundled name or EDS/DCF/XDD file (repeatable)."), QStringLiteral("NODE=NAME|FILE")});
    parser.addOption({QStringLiteral("format"), QStringLiteral("Output format: text (default), jsonl, csv."), QStringLiteral("FORMAT"), QStringLiteral("text")});
    parser.addOption({QStringLiteral("filter"), QStringLiteral("Only frames matching: node=N, service=NAME, id=0x181 or 0x180-0x1FF, warnings; terms ANDed (repeatable)."), QStringLiteral("EXPR")});
    parser.addOption({QStringLiteral("signal"),
                      QStringLiteral("Raw signal of any frame, for devices without a dictionary (repeatable): TYPE u (unsigned), s (signed) "
                                     "or f (float 32/64) in Intel byte order, with @0 after it for Motorola (DBC start bit: the MSB), e.g. "
                                     "speed=0x181:16:16:s:0.1:0:rpm or temp=0x281:7:16:u@0:0.5:-40. COBID over 7FFh is a 29-bit id."),
                      QStringLiteral("NAME=COBID:START:LEN:TYPE[:FACTOR[:OFFSET[:UNIT]]]")});
    parser.addOption({QStringLiteral("no-identity"), QStringLiteral("Do not pick dictionaries by the identity read in the log.")});
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
            job->frames.assign(batch.begin(), batch.end());
            for (size_t i = 0; i < batch.size(); ++i) {
                const CanFrame& f = batch[i];
                ctx.dissect(f, d, dissect::Dissection::Level::Flat);
                if (!raw.empty()) dissect::applyRawSignals(raw, f, d);
                if (!filter.isEmpty() && !filter.matches(f, d)) continue;
                TextWriter::Line l;
                l.frame = static_cast<uint32_t>(i);
                l.summaryAt = static_cast<uint32_t>(job->summaries.size());
                l.summaryLength = static_cast<uint32_t>(d.summary.size());
                job->summaries.append(reinterpret_cast<const char16_t*>(d.summary.constData()), static_cast<size_t>(d.summary.size()));
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
                job->lines.push_back(l);
            }
            writer.submit(std::move(job));
        }
    }  // the writer has written everything
    // jsonl and csv: formatted here.
    for (auto batch = (json || csv) ? ahead->next() : std::span<const CanFrame>(); !batch.empty(); batch = ahead->next()) {
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
        std::fprintf(stderr, "%s:%lld: warning: %s\n", qPrintable(pos[0]), static_cast<long long>(diag.where), qPrintable(diag.message));
    }
    if (reader->hasError()) return failure(kVerb, QStringLiteral("%1: %2").arg(pos[0], reader->errorString()));
    return Ok;
}

}  // namespace

COSCOPE_CLI_VERB({QStringLiteral("decode"), QStringLiteral("Decode a CAN log as CANopen (text, jsonl, csv)."), runDecode});

}  // namespace coscope::cli
