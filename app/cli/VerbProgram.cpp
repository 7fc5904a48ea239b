// SPDX-License-Identifier: GPL-3.0-or-later
// coscope-cli program: program download to a node (CiA 302-3) through canopen::ProgramDownload,
// with progress on stderr; nothing is sent without --yes. coscope-cli program make-image: wraps a
// binary into the virtual drives' image format (sim/ProgramImage.h).
#include "app/cli/BusSession.h"
#include "app/cli/CliVerb.h"
#include "app/cli/ProgramRun.h"
#include "core/canopen/ProgramDownload.h"
#include "core/sim/ProgramImage.h"

#include <QFile>
#include <QTextStream>

namespace coscope::cli {

namespace {

using canopen::ProgramDownloadOutcome;
using canopen::ProgramDownloadRequest;

bool readFile(const QString& path, QByteArray* data, QString* error) {
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly)) {
        *error = QStringLiteral("%1: %2").arg(path, f.errorString());
        return false;
    }
    *data = f.readAll();
    return true;
}

int runProgram(const QStringList& args) {
    const QString verb = QStringLiteral("program");
    QCommandLineParser p;
    p.setApplicationDescription(
        QStringLiteral("Download a program (firmware) to a node (CiA 302-3): 1F51h = 0 stop program, 1F51h = 3 clear "
                       "program (where the node takes it), "
                       "FILE into 1F50h program data (block SDO, segmented when the node declines), 1F51h = 1 start "
                       "program, wait for the node's boot-up, "
                       "then read 1F56h, 1F57h and 100Ah. The node stops its application for the download. Nothing is "
                       "sent without --yes."));
    p.addPositionalArgument(QStringLiteral("BUS"), QStringLiteral("Bus URL, e.g. socketcan://can0 or sim://"));
    p.addPositionalArgument(QStringLiteral("NODE"), QStringLiteral("Node-ID 1-127"));
    p.addPositionalArgument(QStringLiteral("FILE"), QStringLiteral("The program image, sent as it is"));
    const QCommandLineOption program{QStringLiteral("program"),
                                     QStringLiteral("Program number: the sub-index of 1F50h/1F51h (default 1)."),
                                     QStringLiteral("N"), QStringLiteral("1")};
    const QCommandLineOption noStart{QStringLiteral("no-start"),
                                     QStringLiteral("Download only; do not write 1F51h = 1 (the node stays stopped).")};
    const QCommandLineOption noClear{QStringLiteral("no-clear"),
                                     QStringLiteral("Do not write 1F51h = 3 before the download.")};
    const QCommandLineOption yes{QStringLiteral("yes"), QStringLiteral("Download without asking (required).")};
    const QCommandLineOption block{
        QStringLiteral("block"), QStringLiteral("Block SDO transfer, segmented when the node declines it (default).")};
    const QCommandLineOption segmented{QStringLiteral("segmented"), QStringLiteral("Segmented SDO transfer.")};
    const QCommandLineOption timeout{QStringLiteral("timeout"),
                                     QStringLiteral("SDO timeout per response in ms (default 5000)."),
                                     QStringLiteral("MS"), QStringLiteral("5000")};
    const QCommandLineOption bootTimeout{
        QStringLiteral("boot-timeout"),
        QStringLiteral("How long to wait for the boot-up after the start, in ms (default 10000)."),
        QStringLiteral("MS"), QStringLiteral("10000")};
    p.addOptions({program, noStart, noClear, yes, block, segmented, timeout, bootTimeout});
    int code = 0;
    if (!parseArgs(p, verb, args, &code)) return code;
    const QStringList pos = p.positionalArguments();
    if (pos.size() != 3) return usageError(verb, QStringLiteral("expects BUS NODE FILE"));
    const auto node = parseNodeId(pos[1]);
    if (!node) return usageError(verb, QStringLiteral("node-ID '%1' must be 1-127").arg(pos[1]));
    bool ok = false;
    const int number = p.value(program).toInt(&ok, 0);
    if (!ok || number < 1 || number > 254) return usageError(verb, QStringLiteral("--program must be 1-254"));
    if (p.isSet(block) && p.isSet(segmented))
        return usageError(verb, QStringLiteral("--block and --segmented exclude each other"));
    ProgramDownloadRequest req;
    req.node = *node;
    req.program = static_cast<uint8_t>(number);
    req.block = !p.isSet(segmented);
    req.start = !p.isSet(noStart);
    req.clear = !p.isSet(noClear);
    bool okT = false, okB = false;
    req.sdoTimeoutMs = p.value(timeout).toInt(&okT);
    req.bootTimeoutMs = p.value(bootTimeout).toInt(&okB);
    if (!okT || !okB || req.sdoTimeoutMs <= 0 || req.bootTimeoutMs <= 0)
        return usageError(verb, QStringLiteral("--timeout and --boot-timeout must be positive numbers of ms"));
    QString error;
    if (!readFile(pos[2], &req.image, &error)) return failure(verb, error);
    if (req.image.isEmpty()) return failure(verb, QStringLiteral("%1 is empty").arg(pos[2]));

    QTextStream out(stdout);
    printProgramPlan(out, req, pos[2]);
    if (!p.isSet(yes))
        return failure(verb, QStringLiteral("nothing sent: give --yes to download the program to node %1").arg(*node));

    BusSession s;
    if (!s.open(pos[0], &error)) return failure(verb, error);
    const std::optional<ProgramDownloadOutcome> result = runProgramDownload(s, req, out);
    if (!result) return failure(verb, QStringLiteral("node %1: the download did not end").arg(*node));
    if (result->ok) return Ok;
    return failure(verb, QStringLiteral("node %1: %2").arg(*node).arg(result->summary()));
}

int runMakeImage(const QStringList& args) {
    const QString verb = QStringLiteral("program make-image");
    QCommandLineParser p;
    p.setApplicationDescription(
        QStringLiteral("Wrap a binary into the program image format the virtual drives of sim:// accept: a 32-byte "
                       "header (\"CSPI\", payload length, "
                       "CRC-32 of the payload, 16-byte version string for 100Ah, reserved) and the payload; see README "
                       "\"Program download\"."));
    p.addPositionalArgument(QStringLiteral("IN"), QStringLiteral("The payload (any file)"));
    p.addPositionalArgument(QStringLiteral("OUT"), QStringLiteral("The image to write"));
    const QCommandLineOption version{
        QStringLiteral("version"),
        QStringLiteral("Software version the drive reports in 100Ah after the start (at most 16 ASCII characters)."),
        QStringLiteral("TEXT")};
    p.addOption(version);
    int code = 0;
    if (!parseArgs(p, verb, args, &code)) return code;
    const QStringList pos = p.positionalArguments();
    if (pos.size() != 2) return usageError(verb, QStringLiteral("expects IN OUT"));
    const QString v = p.value(version);
    if (v.isEmpty() || v.size() > sim::programimage::kVersionSize)
        return usageError(verb, QStringLiteral("--version must be 1-16 characters"));
    QByteArray payload;
    QString error;
    if (!readFile(pos[0], &payload, &error)) return failure(verb, error);
    const QByteArray image = sim::makeProgramImage(payload, v);
    QFile f(pos[1]);
    if (!f.open(QIODevice::WriteOnly) || f.write(image) != image.size())
        return failure(verb, QStringLiteral("%1: %2").arg(pos[1], f.errorString()));
    QTextStream(stdout) << pos[1] << ": " << image.size() << " bytes, version " << v << ", CRC-32 0x"
                        << QStringLiteral("%1").arg(sim::crc32(payload), 8, 16, QChar(u'0')).toUpper()
                        << " (the drive's 1F56h after the start)\n";
    return Ok;
}

}  // namespace

COSCOPE_CLI_VERB({QStringLiteral("program"),
                  QStringLiteral("Download a program (firmware) to a node, CiA 302-3 (--yes)."), runProgram});
COSCOPE_CLI_VERB({QStringLiteral("program make-image"), QStringLiteral("Make a program image for the virtual drives."),
                  runMakeImage});

}  // namespace coscope::cli
