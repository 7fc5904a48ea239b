// SPDX-License-Identifier: GPL-3.0-or-later
// coscope-cli listen BUS [--count N] [--duration S]: prints frames as candump -L lines.
#include "app/cli/BusOffWatch.h"
#include "app/cli/CliVerb.h"
#include "app/cli/LostWatch.h"
#include "core/can/BusInterfaceName.h"
#include "core/can/CanBus.h"

#include <QDeadlineTimer>
#include <QLoggingCategory>

#include <cstdio>
#include <vector>

namespace coscope::cli {

namespace {
const QString kVerb = QStringLiteral("listen");
constexpr int kOpenWaitMs = 8000;  // backends give up on their own before this (socketcand: 3 s)
}  // namespace

static int runListen(const QStringList& args) {
    // Qt's CAN plugins log to stderr (e.g. peakcan "Cannot load library"); the backend reports
    // the same failure through the bus error, in one line.
    QLoggingCategory::setFilterRules(QStringLiteral("qt.canbus.plugins.*=false"));
    QCommandLineParser parser;
    parser.setApplicationDescription(
        QStringLiteral("Print the frames of a bus as candump -L lines until --count, --duration or Ctrl-C."));
    parser.addPositionalArgument(QStringLiteral("BUS"),
                                 QStringLiteral("Bus URL, e.g. socketcan://can0, sim://, socketcand://HOST:PORT/can0"));
    const QCommandLineOption countOpt(QStringLiteral("count"), QStringLiteral("Stop after N frames."),
                                      QStringLiteral("N"));
    const QCommandLineOption durationOpt(QStringLiteral("duration"), QStringLiteral("Stop after S seconds."),
                                         QStringLiteral("S"));
    const QCommandLineOption restartOpt(QStringLiteral("restart-on-bus-off"), BusOffWatch::optionHelp());
    parser.addOption(countOpt);
    parser.addOption(durationOpt);
    parser.addOption(restartOpt);
    int code = 0;
    if (!parseArgs(parser, kVerb, args, &code)) return code;
    if (parser.positionalArguments().size() != 1)
        return usageError(kVerb, QStringLiteral("expected one BUS argument (see --help)"));

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
    const auto url = BusUrl::parse(parser.positionalArguments().front(), &error);
    if (!url) return usageError(kVerb, error);
    auto bus = createBus(*url, &error);
    if (!bus) return failure(kVerb, error);

    installInterruptHandler();
    bus->open();
    if (!bus->waitForOpen(kOpenWaitMs)) {
        const QString why = bus->errorString().isEmpty()
                                ? QStringLiteral("cannot open %1: no answer").arg(url->toString())
                                : bus->errorString();
        bus->close();
        return failure(kVerb, why);
    }

    const QString iface = busInterfaceName(*url);
    QDeadlineTimer deadline =
        duration > 0 ? QDeadlineTimer(static_cast<qint64>(duration * 1000)) : QDeadlineTimer(QDeadlineTimer::Forever);
    std::vector<CanFrame> batch(256);
    BusOffWatch busOff(bus.get(), kVerb, parser.isSet(restartOpt));
    LostWatch lost(bus.get(), kVerb);  // a lost adapter reconnects by itself: capturing goes on
    qint64 printed = 0;
    auto drain = [&] {
        for (;;) {
            size_t n = bus->read(batch.data(), batch.size());
            if (n == 0) return;
            for (size_t i = 0; i < n && (count < 0 || printed < count); ++i, ++printed)
                std::printf("%s\n", qPrintable(formatCandumpL(batch[i], iface)));
            std::fflush(stdout);
            if (count >= 0 && printed >= count) return;
        }
    };
    while (!interrupted() && !deadline.hasExpired() && (count < 0 || printed < count)) {
        bus->waitForFrames(50);
        drain();
        busOff.poll();
        lost.poll();
        if (bus->state() == CanBus::State::Closed) {  // the input ended (replay finished)
            drain();
            break;
        }
        if (bus->state() == CanBus::State::Error) {
            drain();                                    // whatever arrived before the failure
            if (count >= 0 && printed >= count) break;  // e.g. a replay that ended with its last frame
            const QString why = bus->errorString();
            bus->close();
            return failure(kVerb, why);
        }
    }
    const auto c = bus->counters();
    bus->close();
    if (c.dropped)
        std::fprintf(stderr, "coscope-cli listen: %llu frames dropped (reader too slow)\n",
                     static_cast<unsigned long long>(c.dropped));
    return Ok;
}

COSCOPE_CLI_VERB({QStringLiteral("listen"), QStringLiteral("Print a bus's frames as candump -L lines."), runListen});

}  // namespace coscope::cli
