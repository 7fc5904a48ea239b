// SPDX-License-Identifier: GPL-3.0-or-later
// coscope-cli record BUS OUT [--count N] [--duration S]: streams the bus to a log in the format
// OUT's extension names (.log candump -L, .asc, .blf, .trc, .pcapng, .csv; core/logio's writers); an
// extension without a writer is a usage error. The file is flushed at least every 100 ms and
// synced to the disk every second, so a crash, a SIGKILL or an unplugged adapter loses nothing
// that was received (text formats and pcapng, whose blocks stand alone; BLF gets its footer at
// the end); Ctrl-C / SIGTERM close the file cleanly. A write error (full disk) stops the
// recording with the frames written so far kept.
#include "app/cli/BusOffWatch.h"
#include "app/cli/CliVerb.h"
#include "app/cli/LostWatch.h"
#include "core/can/BusInterfaceName.h"
#include "core/can/CanBus.h"
#include "core/logio/LogFormats.h"

#include <QDeadlineTimer>
#include <QElapsedTimer>
#include <QLoggingCategory>

#include <cstdio>
#include <vector>

namespace coscope::cli {

namespace {
const QString kVerb = QStringLiteral("record");
constexpr int kOpenWaitMs = 8000;
constexpr int kFlushMs = 100;
constexpr int kSyncMs = 1000;
}  // namespace

static int runRecord(const QStringList& args) {
    // Qt's CAN plugins log to stderr (e.g. peakcan "Cannot load library"); the backend reports
    // the same failure through the bus error, in one line.
    QLoggingCategory::setFilterRules(QStringLiteral("qt.canbus.plugins.*=false"));
    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral(
        "Record a bus to a log file until --count, --duration, Ctrl-C or SIGTERM. The format is the one OUT's "
        "extension names: .log (candump -L), .asc, .blf, .trc, .pcapng, .csv."));
    parser.addPositionalArgument(QStringLiteral("BUS"), QStringLiteral("Bus URL, e.g. socketcan://can0, sim://"));
    parser.addPositionalArgument(QStringLiteral("OUT"),
                                 QStringLiteral("Log file to write: .log, .asc, .blf, .trc, .pcapng or .csv"));
    const QCommandLineOption countOpt(QStringLiteral("count"), QStringLiteral("Stop after N frames."),
                                      QStringLiteral("N"));
    const QCommandLineOption durationOpt(QStringLiteral("duration"), QStringLiteral("Stop after S seconds."),
                                         QStringLiteral("S"));
    const QCommandLineOption toOpt(
        QStringLiteral("to"),
        QStringLiteral("Output format: candump, asc, blf, trc, pcapng, csv (default: from OUT's extension)."),
        QStringLiteral("FORMAT"));
    const QCommandLineOption restartOpt(QStringLiteral("restart-on-bus-off"), BusOffWatch::optionHelp());
    parser.addOption(countOpt);
    parser.addOption(durationOpt);
    parser.addOption(toOpt);
    parser.addOption(restartOpt);
    int code = 0;
    if (!parseArgs(parser, kVerb, args, &code)) return code;
    const QStringList pos = parser.positionalArguments();
    if (pos.size() != 2) return usageError(kVerb, QStringLiteral("expected BUS and OUT (see --help)"));

    qint64 count = -1;
    if (parser.isSet(countOpt)) {
        bool ok = false;
        count = parser.value(countOpt).toLongLong(&ok);
        if (!ok || count <= 0)
            return usageError(
                kVerb, QStringLiteral("--count must be a positive number, not '%1'").arg(parser.value(countOpt)));
    }
    double duration = -1;
    if (parser.isSet(durationOpt)) {
        bool ok = false;
        duration = parser.value(durationOpt).toDouble(&ok);
        if (!ok || duration <= 0)
            return usageError(kVerb, QStringLiteral("--duration must be a positive number of seconds, not '%1'")
                                         .arg(parser.value(durationOpt)));
    }

    QString error;
    const auto url = BusUrl::parse(pos[0], &error);
    if (!url) return usageError(kVerb, error);
    const QString format = logio::LogFormats::writerFormatFor(pos[1], parser.value(toOpt), &error);
    if (format.isEmpty()) return usageError(kVerb, error);
    auto bus = createBus(*url, &error);
    if (!bus) return failure(kVerb, error);

    auto out = logio::LogFormats::createWriter(format);
    if (!out->open(pos[1])) return failure(kVerb, out->errorString());
    out->setBusNames({busInterfaceName(*url)});

    installInterruptHandler();
    bus->open();
    if (!bus->waitForOpen(kOpenWaitMs)) {
        const QString why = bus->errorString().isEmpty()
                                ? QStringLiteral("cannot open %1: no answer").arg(url->toString())
                                : bus->errorString();
        bus->close();
        out->close();
        return failure(kVerb, why);
    }

    QDeadlineTimer deadline =
        duration > 0 ? QDeadlineTimer(static_cast<qint64>(duration * 1000)) : QDeadlineTimer(QDeadlineTimer::Forever);
    std::vector<CanFrame> batch(512);
    BusOffWatch busOff(bus.get(), kVerb, parser.isSet(restartOpt));
    LostWatch lost(bus.get(), kVerb);  // a lost adapter reconnects by itself: capturing goes on
    lost.setOnBack([&](int64_t lostNs, int64_t backNs) {
        out->markGap(lostNs, backNs);  // on the next frame written
        if (!out->keepsGaps())
            std::fprintf(stderr,
                         "coscope-cli record: warning: the %s format cannot hold the gap in the capture (adapter lost "
                         "for %.1f s); "
                         "%s will not show it (pcapng, asc, trc and csv keep gaps)\n",
                         qPrintable(format), double(backNs - lostNs) / 1e9, qPrintable(pos[1]));
    });
    qint64 written = 0;
    bool writeFailed = false;
    QElapsedTimer sinceFlush, sinceSync;
    sinceFlush.start();
    sinceSync.start();
    auto drain = [&] {
        for (;;) {
            const size_t n = bus->read(batch.data(), batch.size());
            if (n == 0) break;
            for (size_t i = 0; i < n && (count < 0 || written < count); ++i, ++written)
                if (!out->write(batch[i])) writeFailed = true;
            if (count >= 0 && written >= count) break;
        }
        if (sinceFlush.elapsed() >= kFlushMs / 2) {  // waits are 50 ms: at most ~100 ms unflushed
            const bool toDisk = sinceSync.elapsed() >= kSyncMs - kFlushMs;
            if (!(toDisk ? out->sync() : out->flush())) writeFailed = true;
            sinceFlush.restart();
            if (toDisk) sinceSync.restart();
        }
    };
    auto finish = [&](int exitCode, const QString& why) {
        drain();
        if (!out->close()) writeFailed = true;
        bus->close();
        if (exitCode == Ok && writeFailed)
            return failure(kVerb, QStringLiteral("cannot write %1: %2").arg(pos[1], out->errorString()));
        if (exitCode != Ok) return failure(kVerb, why);
        std::fprintf(stderr, "coscope-cli record: %lld frames written to %s\n", static_cast<long long>(written),
                     qPrintable(pos[1]));
        return exitCode;
    };

    while (!interrupted() && !deadline.hasExpired() && (count < 0 || written < count)) {
        bus->waitForFrames(50);
        drain();
        busOff.poll();
        lost.poll();
        if (writeFailed)
            return finish(
                Failure,
                QStringLiteral("cannot write %1: %2; %3 frames kept").arg(pos[1], out->errorString()).arg(written));
        if (bus->state() == CanBus::State::Closed) {  // the input ended (replay finished)
            drain();
            break;
        }
        if (bus->state() == CanBus::State::Error) {
            drain();
            if (count >= 0 && written >= count) break;  // e.g. a replay that ended with its last frame
            return finish(Failure,
                          QStringLiteral("%1; %2 frames kept in %3").arg(bus->errorString()).arg(written).arg(pos[1]));
        }
    }
    return finish(Ok, {});
}

COSCOPE_CLI_VERB({QStringLiteral("record"),
                  QStringLiteral("Record a bus to a log file (.log, .asc, .blf, .trc, .pcapng, .csv)."), runRecord});

}  // namespace coscope::cli
