// SPDX-License-Identifier: GPL-3.0-or-later
// coscope-cli convert IN OUT [--to FORMAT]: converts a CAN log between formats.
#include "app/cli/CliVerb.h"
#include "core/logio/LogFormats.h"

#include <QCommandLineParser>

#include <unistd.h>
#include <cstdio>

namespace coscope::cli {

static int runConvert(const QStringList& args) {
    const QString verb = QStringLiteral("convert");
    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral(
        "Convert a CAN log. Reads candump (-L and text), Vector ASC/BLF, PEAK TRC 1.0-2.1, pcap/pcapng, ASAM MDF4\n"
        "(detected from the content); writes candump -L (.log), ASC (.asc), TRC 2.1 (.trc),\n"
        "pcapng (.pcapng) or CSV (.csv), chosen by OUT's extension or --to."));
    parser.addPositionalArgument(QStringLiteral("IN"),
                                 QStringLiteral("Input log file: candump, asc, blf, trc, pcap, csv, gvret, busmaster, "
                                                "ixxat, kvaser or mf4, found by its content."));
    parser.addPositionalArgument(QStringLiteral("OUT"), QStringLiteral("Output file."));
    parser.addOption({QStringLiteral("to"), QStringLiteral("Output format: candump, asc, blf, trc, pcapng, csv."),
                      QStringLiteral("FORMAT")});
    int code = 0;
    if (!parseArgs(parser, verb, args, &code)) return code;
    const QStringList pos = parser.positionalArguments();
    if (pos.size() != 2) return usageError(verb, QStringLiteral("expected IN and OUT (see --help)"));
    const QString in = pos[0], outPath = pos[1];

    QString error;
    const QString format = logio::LogFormats::writerFormatFor(outPath, parser.value(QStringLiteral("to")), &error);
    if (format.isEmpty()) return usageError(verb, error);

    auto reader = logio::LogFormats::openReader(in, &error);
    if (!reader) return failure(verb, error);
    auto writer = logio::LogFormats::createWriter(format);
    if (!writer->open(outPath)) return failure(verb, writer->errorString());

    installInterruptHandler();
    const bool showProgress = isatty(fileno(stderr));
    int lastPercent = -1;
    std::vector<CanFrame> batch(4096);
    bool namesSet = false;
    size_t nextGap = 0;
    while (size_t n = reader->read(batch.data(), batch.size())) {
        if (!namesSet || reader->busNames().size() > 0) {
            writer->setBusNames(reader->busNames());
            namesSet = true;
        }
        // Gaps of the capture (issue 16 "Lost adapter") go before their first frame; a format
        // that cannot hold them counts them (warned about below).
        const auto& gaps = reader->gaps();
        const uint64_t first = reader->framesRead() - n;
        for (size_t i = 0; i < n; ++i) {
            for (; nextGap < gaps.size() && gaps[nextGap].frame <= first + i; ++nextGap)
                writer->markGap(gaps[nextGap].lostNs, gaps[nextGap].backNs);
            if (!writer->write(batch[i])) break;
        }
        if (writer->hasError() || interrupted()) break;
        if (showProgress) {
            const int percent = int(reader->progress() * 100);
            if (percent != lastPercent) {
                std::fprintf(stderr, "\rconverting %s: %d%%", qPrintable(in), percent);
                lastPercent = percent;
            }
        }
    }
    if (showProgress) std::fprintf(stderr, "\r\033[K");
    writer->close();

    for (const auto& d : reader->diagnostics())
        std::fprintf(stderr, "%s:%lld: warning: %s\n", qPrintable(in), static_cast<long long>(d.where),
                     qPrintable(d.message));
    if (reader->diagnosticCount() > reader->diagnostics().size())
        std::fprintf(stderr, "%s: warning: %llu more problems not shown\n", qPrintable(in),
                     static_cast<unsigned long long>(reader->diagnosticCount() - reader->diagnostics().size()));

    if (writer->gapsDropped())
        std::fprintf(
            stderr,
            "%s: warning: the input has %llu gap(s) in the capture (adapter lost) that the %s format cannot hold; "
            "they are not in the output (pcapng, asc, trc and csv keep them)\n",
            qPrintable(outPath), static_cast<unsigned long long>(writer->gapsDropped()), qPrintable(format));

    if (writer->hasError()) return failure(verb, QStringLiteral("%1: %2").arg(outPath, writer->errorString()));
    if (interrupted()) return failure(verb, QStringLiteral("interrupted after %1 frames").arg(writer->framesWritten()));
    if (reader->hasError() && reader->framesRead() == 0)
        return failure(verb, QStringLiteral("%1: %2").arg(in, reader->errorString()));
    if (reader->hasError())
        std::fprintf(stderr, "%s: warning: %s (the %llu frames before were converted)\n", qPrintable(in),
                     qPrintable(reader->errorString()), static_cast<unsigned long long>(reader->framesRead()));
    if (reader->framesRead() == 0) return failure(verb, QStringLiteral("%1: no frames could be read").arg(in));
    return Ok;
}

COSCOPE_CLI_VERB({QStringLiteral("convert"), QStringLiteral("Convert a CAN log between formats."), runConvert});

}  // namespace coscope::cli
