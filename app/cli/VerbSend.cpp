// SPDX-License-Identifier: GPL-3.0-or-later
// coscope-cli send BUS ID#DATA: sends one frame (cansend syntax: 123#DEADBEEF, 123#R, 123##1AABB).
#include "app/cli/CliVerb.h"
#include "core/can/CanBus.h"

#include <QDeadlineTimer>
#include <QLoggingCategory>

namespace coscope::cli {

namespace {
const QString kVerb = QStringLiteral("send");
constexpr int kOpenWaitMs = 8000;
}  // namespace

static int runSend(const QStringList& args) {
    // Qt's CAN plugins log to stderr (e.g. peakcan "Cannot load library"); the backend reports
    // the same failure through the bus error, in one line.
    QLoggingCategory::setFilterRules(QStringLiteral("qt.canbus.plugins.*=false"));
    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral("Send one frame. FRAME uses cansend syntax: 123#DEADBEEF, 1F334455#11.22, 123#R, 123#R4, 123##1AABBCC (CAN FD)."));
    parser.addPositionalArgument(QStringLiteral("BUS"), QStringLiteral("Bus URL, e.g. socketcan://can0"));
    parser.addPositionalArgument(QStringLiteral("FRAME"), QStringLiteral("ID#DATA"));
    int code = 0;
    if (!parseArgs(parser, kVerb, args, &code)) return code;
    const QStringList pos = parser.positionalArguments();
    if (pos.size() != 2) return usageError(kVerb, QStringLiteral("expected BUS and ID#DATA (see --help)"));

    QString error;
    const auto url = BusUrl::parse(pos[0], &error);
    if (!url) return usageError(kVerb, error);
    const auto frame = parseCansend(pos[1], &error);
    if (!frame) return usageError(kVerb, error);
    auto bus = createBus(*url, &error);
    if (!bus) return failure(kVerb, error);

    bus->open();
    if (!bus->waitForOpen(kOpenWaitMs)) {
        const QString why = bus->errorString().isEmpty() ? QStringLiteral("cannot open %1: no answer").arg(url->toString()) : bus->errorString();
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

COSCOPE_CLI_VERB({QStringLiteral("send"), QStringLiteral("Send one frame (cansend syntax)."), runSend});

}  // namespace coscope::cli
