// SPDX-License-Identifier: GPL-3.0-or-later
// coscope-cli sync BUS --period 10ms [--counter N] [--cob-id 80h] [--count N] [--duration S]:
// produces SYNC (CiA 301 §7.2.5) on the bus's periodic sender until the count or the duration
// (default 10 s) is reached or Ctrl+C, then prints how many went out.
#include "app/cli/BusSession.h"
#include "app/cli/CliVerb.h"
#include "app/cli/PeriodicRun.h"
#include "core/od/NumberText.h"

#include <QLoggingCategory>

#include <cstdio>

namespace coscope::cli {

namespace {
const QString kVerb = QStringLiteral("sync");

// "80h", "0x80", "128"; 29-bit COB-IDs as 1005h writes them (bit 29 set) or as "1F000080h".
std::optional<uint32_t> parseCobId(QString text) {
    text = text.trimmed();
    const bool hSuffix = text.endsWith(u'h', Qt::CaseInsensitive);
    if (hSuffix) text = QStringLiteral("0x") + text.chopped(1);
    const auto v = od::parseIntegerText(text, od::TextStyle::Person);
    if (!v || v->negative || v->magnitude > 0xFFFFFFFFu) return std::nullopt;
    return static_cast<uint32_t>(v->magnitude);
}
}  // namespace

static int runSync(const QStringList& args) {
    QLoggingCategory::setFilterRules(QStringLiteral("qt.canbus.plugins.*=false"));
    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral("Produce SYNC (CiA 301 7.2.5) every PERIOD until --count or "
                                                    "--duration is reached (default %1 s) or Ctrl+C; "
                                                    "prints how many SYNC frames were sent.")
                                         .arg(kDefaultRunSeconds));
    parser.addPositionalArgument(QStringLiteral("BUS"), QStringLiteral("Bus URL, e.g. socketcan://can0, sim://"));
    const QCommandLineOption periodOpt(
        QStringLiteral("period"),
        QStringLiteral("Communication cycle period (1006h): 10ms, 500us, 1s; a plain number is ms."),
        QStringLiteral("PERIOD"));
    const QCommandLineOption counterOpt(
        QStringLiteral("counter"),
        QStringLiteral(
            "Synchronous counter overflow value (1019h): 2..240 adds a counter byte 1..N; 0 = none (default)."),
        QStringLiteral("N"));
    const QCommandLineOption cobOpt(
        QStringLiteral("cob-id"),
        QStringLiteral("COB-ID of SYNC (1005h, default 80h); bit 29 set = 29-bit identifier."), QStringLiteral("ID"));
    parser.addOption(periodOpt);
    parser.addOption(counterOpt);
    parser.addOption(cobOpt);
    const PeriodicRunOptions runOpts;
    runOpts.addTo(parser);
    int code = 0;
    if (!parseArgs(parser, kVerb, args, &code)) return code;
    const QStringList pos = parser.positionalArguments();
    if (pos.size() != 1) return usageError(kVerb, QStringLiteral("expected BUS (see --help)"));
    if (!parser.isSet(periodOpt)) return usageError(kVerb, QStringLiteral("--period is required, e.g. --period 10ms"));

    QString error;
    const auto periodUs = parsePeriodUs(parser.value(periodOpt), &error);
    if (!periodUs) return usageError(kVerb, error);
    uint64_t count = 0;
    double seconds = 0;
    if (!runOpts.read(parser, &count, &seconds, &error)) return usageError(kVerb, error);

    BusSession session;
    if (!session.open(pos[0], &error)) return failure(kVerb, error);
    canopen::SyncProducer& sync = session.master().sync();
    sync.setPeriodUs(*periodUs);
    if (parser.isSet(counterOpt)) {
        bool ok = false;
        const uint n = parser.value(counterOpt).toUInt(&ok);
        if (!ok || n > 255 || !sync.setCounterOverflow(static_cast<uint8_t>(n)))
            return usageError(
                kVerb, QStringLiteral("--counter must be 0 or 2..240 (1019h), not '%1'").arg(parser.value(counterOpt)));
    }
    if (parser.isSet(cobOpt)) {
        const auto cob = parseCobId(parser.value(cobOpt));
        if (!cob || !sync.setCobId(*cob))
            return usageError(
                kVerb,
                QStringLiteral(
                    "--cob-id must be an 11-bit CAN-ID (e.g. 80h) or a 1005h value with bit 29 for 29 bits, not '%1'")
                    .arg(parser.value(cobOpt)));
    }
    if (!sync.start(&error, count)) return failure(kVerb, error);  // listen-only is refused here

    // A count limit ends the job on the sender thread; otherwise the duration or Ctrl+C does.
    const RunEnd end = waitWhileRunning(
        session.bus(), [&] { return sync.isRunning(); }, seconds, &error);
    const QString why = sync.lastError();
    sync.stop();
    std::printf("%llu SYNC frames sent on %s every %s\n", static_cast<unsigned long long>(sync.sent()),
                qPrintable(session.bus()->url().toString()), qPrintable(formatPeriodUs(*periodUs)));
    std::fflush(stdout);
    if (end == RunEnd::BusFailed) return failure(kVerb, error);
    if (!why.isEmpty()) return failure(kVerb, why);
    return Ok;
}

COSCOPE_CLI_VERB({QStringLiteral("sync"),
                  QStringLiteral("Produce SYNC every period (--period 10ms) until --count/--duration."), runSync});

}  // namespace coscope::cli
