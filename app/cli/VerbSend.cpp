// SPDX-License-Identifier: GPL-3.0-or-later
// coscope-cli send BUS ID#DATA [--every PERIOD [--count N] [--duration S]]: sends one frame
// (cansend syntax: 123#DEADBEEF, 123#R, 123##1AABB), or sends it periodically through the bus's
// transmit list until the count or the duration (default 10 s) is reached or Ctrl+C.
#include "app/cli/BusSession.h"
#include "app/cli/CliVerb.h"
#include "app/cli/PeriodicRun.h"
#include "core/can/CanBus.h"

#include <QDeadlineTimer>
#include <QLoggingCategory>

#include <cstdio>

namespace coscope::cli {

namespace {
const QString kVerb = QStringLiteral("send");
constexpr int kOpenWaitMs = 8000;
}  // namespace

// --every: the frame as row 1 of the bus's transmit list, started on its periodic sender.
static int sendPeriodically(const QString& url, const CanFrame& frame, uint32_t periodUs, uint64_t count,
                            double seconds) {
    QString error;
    BusSession session;
    if (!session.open(url, &error)) return failure(kVerb, error);
    canopen::TransmitList& list = session.master().transmit();
    const int row = list.add({frame, periodUs, {}});
    if (!list.start(row, &error, count)) return failure(kVerb, error);  // listen-only is refused here
    const RunEnd end = waitWhileRunning(
        session.bus(), [&] { return list.isRunning(row); }, seconds, &error);
    const QString why = list.lastError(row);
    list.stop(row);
    std::printf("%llu frames %s sent on %s every %s\n", static_cast<unsigned long long>(list.sentCount(row)),
                qPrintable(formatCansend(frame)), qPrintable(session.bus()->url().toString()),
                qPrintable(formatPeriodUs(periodUs)));
    std::fflush(stdout);
    if (end == RunEnd::BusFailed) return failure(kVerb, error);
    if (!why.isEmpty()) return failure(kVerb, why);
    return Ok;
}

static int runSend(const QStringList& args) {
    // Qt's CAN plugins log to stderr (e.g. peakcan "Cannot load library"); the backend reports
    // the same failure through the bus error, in one line.
    QLoggingCategory::setFilterRules(QStringLiteral("qt.canbus.plugins.*=false"));
    QCommandLineParser parser;
    parser.setApplicationDescription(
        QStringLiteral("Send one frame, or with --every one every PERIOD until --count or --duration is reached "
                       "(default %1 s) or Ctrl+C. "
                       "FRAME uses cansend syntax: 123#DEADBEEF, 1F334455#11.22, 123#R, 123#R4, 123##1AABBCC (CAN FD).")
            .arg(kDefaultRunSeconds));
    parser.addPositionalArgument(QStringLiteral("BUS"), QStringLiteral("Bus URL, e.g. socketcan://can0"));
    parser.addPositionalArgument(QStringLiteral("FRAME"), QStringLiteral("ID#DATA"));
    const QCommandLineOption everyOpt(QStringLiteral("every"),
                                      QStringLiteral("Send periodically: 100ms, 500us, 1s; a plain number is ms."),
                                      QStringLiteral("PERIOD"));
    parser.addOption(everyOpt);
    const PeriodicRunOptions runOpts;
    runOpts.addTo(parser);
    int code = 0;
    if (!parseArgs(parser, kVerb, args, &code)) return code;
    const QStringList pos = parser.positionalArguments();
    if (pos.size() != 2) return usageError(kVerb, QStringLiteral("expected BUS and ID#DATA (see --help)"));

    QString error;
    const auto url = BusUrl::parse(pos[0], &error);
    if (!url) return usageError(kVerb, error);
    const auto frame = parseCansend(pos[1], &error);
    if (!frame) return usageError(kVerb, error);
    if (parser.isSet(everyOpt)) {
        const auto periodUs = parsePeriodUs(parser.value(everyOpt), &error);
        if (!periodUs) return usageError(kVerb, error);
        uint64_t count = 0;
        double seconds = 0;
        if (!runOpts.read(parser, &count, &seconds, &error)) return usageError(kVerb, error);
        return sendPeriodically(pos[0], *frame, *periodUs, count, seconds);
    }
    if (parser.isSet(runOpts.count) || parser.isSet(runOpts.duration))
        return usageError(kVerb, QStringLiteral("--count and --duration go with --every"));
    auto bus = createBus(*url, &error);
    if (!bus) return failure(kVerb, error);

    bus->open();
    if (!bus->waitForOpen(kOpenWaitMs)) {
        const QString why = bus->errorString().isEmpty()
                                ? QStringLiteral("cannot open %1: no answer").arg(url->toString())
                                : bus->errorString();
        bus->close();
        return failure(kVerb, why);
    }
    if (!bus->send(*frame, &error)) {  // listen-only is refused here
        bus->close();
        return failure(kVerb, error);
    }
    // Wait (briefly) for the Tx copy: the frame has left through the backend.
    QDeadlineTimer deadline(1000);
    bool sent = false;
    CanFrame buf[64];
    while (!sent && !deadline.hasExpired() && bus->state() == CanBus::State::Open) {
        bus->waitForFrames(20);
        for (size_t n = bus->read(buf, 64), i = 0; i < n; ++i)
            if (buf[i].isTx()) sent = true;
    }
    const bool failed = bus->state() == CanBus::State::Error;
    const QString why = bus->errorString();
    bus->close();
    if (failed) return failure(kVerb, why);
    return Ok;
}

COSCOPE_CLI_VERB({QStringLiteral("send"),
                  QStringLiteral("Send one frame (cansend syntax), or one every PERIOD with --every."), runSend});

}  // namespace coscope::cli
