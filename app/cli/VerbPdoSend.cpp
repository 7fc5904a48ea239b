// SPDX-License-Identifier: GPL-3.0-or-later
// coscope-cli pdo send BUS NODE RPDOn INDEX[:SUB]=VALUE... [--every 10ms | --with-sync [--sync-period P]]
//             [--duration S] [--yes] [--dict D]
#include "app/cli/BusSession.h"
#include "app/cli/CliVerb.h"
#include "app/cli/PeriodicRun.h"
#include "core/canopen/Ds402Controller.h"
#include "core/canopen/PdoMapping.h"
#include "core/canopen/ProcessData.h"
#include "core/canopen/ServiceWait.h"

#include <QElapsedTimer>
#include <QTextStream>

#include <cstdio>

namespace coscope::cli {

namespace {
QString frameText(const CanFrame& f) {
    QString s = QStringLiteral("%1#").arg(f.id, f.isExtended() ? 8 : 3, 16, QChar(u'0')).toUpper();
    for (int i = 0; i < f.len; ++i) s += QStringLiteral("%1").arg(f.data[i], 2, 16, QChar(u'0')).toUpper();
    return s;
}
}  // namespace

static int runPdoSend(const QStringList& args) {
    const QString verb = QStringLiteral("pdo send");
    QCommandLineParser p;
    p.setApplicationDescription(QStringLiteral(
        "Send a node's RPDO with values set by object (process data): the mapping comes from the node's dictionary "
        "(140xh/160xh), objects not given repeat the values read from the node over SDO. Sent once, every period "
        "(--every) or right after each SYNC (--with-sync, which runs the SYNC producer). An RPDO that maps a motion "
        "object (6040h, 6060h, 607Ah, 60FFh, 6071h...) CAN MOVE A MOTOR: asks unless --yes, runs for --duration "
        "(default 1 s), then is sent with halt and velocity/torque 0, and the controlword is set to Disable voltage "
        "when it was given."));
    p.addPositionalArgument(QStringLiteral("BUS"), QStringLiteral("Bus URL"));
    p.addPositionalArgument(QStringLiteral("NODE"), QStringLiteral("Node-ID 1-127"));
    p.addPositionalArgument(QStringLiteral("RPDO"), QStringLiteral("RPDO1..RPDO4 (or any the dictionary maps)"));
    p.addPositionalArgument(
        QStringLiteral("VALUES"),
        QStringLiteral("INDEX[:SUB]=VALUE, e.g. 6040=0x000F 607A=1000 60FF=-500 (decimal, 0x1F or 1Fh)"));
    const QCommandLineOption every(QStringLiteral("every"), QStringLiteral("Send every period (10ms, 500us, 1s)."),
                                   QStringLiteral("PERIOD"));
    const QCommandLineOption withSync(QStringLiteral("with-sync"),
                                      QStringLiteral("Send right after each SYNC; runs the SYNC producer."));
    const QCommandLineOption syncPeriod(QStringLiteral("sync-period"),
                                        QStringLiteral("SYNC period with --with-sync (default 10ms)."),
                                        QStringLiteral("PERIOD"), QStringLiteral("10ms"));
    const QCommandLineOption duration(QStringLiteral("duration"),
                                      QStringLiteral("How long to send, in seconds (default 1, at most 30)."),
                                      QStringLiteral("S"), QStringLiteral("1"));
    const QCommandLineOption yes(QStringLiteral("yes"), QStringLiteral("Do not ask for confirmation of motion."));
    const QCommandLineOption dict(
        QStringLiteral("dict"),
        QStringLiteral("Dictionary file or library name (default: matched by the node's identity)."),
        QStringLiteral("D"));
    p.addOptions({every, withSync, syncPeriod, duration, yes, dict});
    int code = 0;
    if (!parseArgs(p, verb, args, &code)) return code;
    const QStringList pos = p.positionalArguments();
    if (pos.size() < 4) return usageError(verb, QStringLiteral("expects BUS NODE RPDO INDEX=VALUE..."));
    const auto node = parseNodeId(pos[1]);
    if (!node) return usageError(verb, QStringLiteral("node-ID '%1' must be 1-127").arg(pos[1]));
    const auto pdoId = canopen::parsePdoName(pos[2]);
    if (!pdoId || pdoId->transmit)
        return usageError(verb, QStringLiteral("'%1' is not an RPDO (RPDO1..RPDO4)").arg(pos[2]));
    if (p.isSet(every) && p.isSet(withSync))
        return usageError(verb, QStringLiteral("--every and --with-sync exclude each other"));
    QString error;
    uint32_t periodUs = 0, syncUs = 0;
    if (p.isSet(every)) {
        const auto v = parsePeriodUs(p.value(every), &error);
        if (!v || *v < 1000) return usageError(verb, v ? QStringLiteral("--every must be at least 1ms") : error);
        periodUs = *v;
    }
    if (p.isSet(withSync)) {
        const auto v = parsePeriodUs(p.value(syncPeriod), &error);
        if (!v) return usageError(verb, error);
        syncUs = *v;
    }
    bool ok = false;
    const double seconds = p.value(duration).toDouble(&ok);
    if (!ok || seconds < 0 || seconds > 30) return usageError(verb, QStringLiteral("--duration must be 0-30 seconds"));
    struct Assignment {
        uint16_t index;
        uint8_t sub;
        QString value;
    };
    std::vector<Assignment> assignments;
    for (int i = 3; i < pos.size(); ++i) {
        const int eq = static_cast<int>(pos[i].indexOf(u'='));
        Assignment a{};
        if (eq <= 0 || !parseObjectRef(pos[i].left(eq), &a.index, &a.sub))
            return usageError(verb, QStringLiteral("'%1' is not INDEX[:SUB]=VALUE").arg(pos[i]));
        a.value = pos[i].mid(eq + 1);
        assignments.push_back(a);
    }

    BusSession s;
    if (!s.open(pos[0], &error)) return failure(verb, error);
    QString dictName;
    const auto dictionary = s.nodeDictionary(*node, p.value(dict), &dictName, &error);
    if (!dictionary)
        return failure(verb,
                       QStringLiteral("no dictionary for node %1 (%2); give one with --dict").arg(*node).arg(error));
    canopen::ProcessData data(s.context(), s.master().sync());
    if (!data.setNode(*node, *dictionary, &error)) return failure(verb, error);
    const canopen::ProcessDataPdo* pdo = data.pdo(pdoId->number);
    if (!pdo)
        return failure(verb, QStringLiteral("%1 of node %2 is not valid or not mapped in %3")
                                 .arg(pdoId->name())
                                 .arg(*node)
                                 .arg(dictName));
    for (const canopen::ProcessDataPdo& other : data.pdos())
        data.setEnabled(other.layout.number, other.layout.number == pdoId->number);
    // The objects not given repeat what the node has now.
    QStringList unread;
    auto read = canopen::waitForResult<QStringList>(
        [&](std::function<void(const QStringList&)> cb) { data.readValues(s.sdo(), cb); }, 20000);
    if (!read) unread << QStringLiteral("no answer");
    else unread = *read;
    QTextStream out(stdout);
    for (const QString& u : unread) out << "warning: could not read " << u << "; 0 is sent\n";
    bool controlword = false;
    for (const Assignment& a : assignments) {
        bool inPdo = false;
        for (const canopen::ProcessDataObject& o : pdo->objects)
            inPdo |= !o.dummy && o.entry.index == a.index && o.entry.sub == a.sub;
        if (!inPdo)
            return failure(verb, QStringLiteral("%1h:%2 is not mapped in %3 of node %4")
                                     .arg(a.index, 4, 16, QChar(u'0'))
                                     .arg(a.sub)
                                     .arg(pdoId->name())
                                     .arg(*node));
        if (!data.setValueText(a.index, a.sub, a.value, &error)) return failure(verb, error);
        controlword |= (a.index - 0x6000) % 0x800 == 0x40 && a.index >= 0x6000 && a.index < 0xA000;
    }
    out << pdoId->name() << " of node " << *node << ":";
    for (const canopen::ProcessDataObject& o : pdo->objects)
        if (!o.dummy)
            out << " " << QStringLiteral("%1").arg(o.entry.index, 4, 16, QChar(u'0')).toUpper() << "h "
                << (o.name.isEmpty() ? QStringLiteral("?") : o.name) << " = " << *data.value(o.entry.index, o.entry.sub)
                << ";";
    out << "\nframe " << frameText(data.frame(pdoId->number)) << "\n";
    out.flush();
    const bool motion = pdo->carriesMotion();
    if (motion && !p.isSet(yes)) {
        out << pdoId->name() << " maps motion objects: this can move node " << *node << "'s motor for " << seconds
            << " s.\n"
            << "Make sure the axis is free to move. Type yes to continue: ";
        out.flush();
        char line[64] = {};
        if (!std::fgets(line, sizeof line, stdin) || QString::fromLatin1(line).trimmed().toLower() != u"yes")
            return failure(verb, QStringLiteral("not confirmed; nothing was sent (use --yes to skip the question)"));
    }
    if (syncUs) {
        s.master().sync().setPeriodUs(syncUs);
        data.setMode(canopen::ProcessData::Mode::WithSync);
    } else if (periodUs) {
        data.setMode(canopen::ProcessData::Mode::Every, static_cast<int>(periodUs / 1000));
    } else {
        data.setMode(canopen::ProcessData::Mode::Once);
    }
    // Whatever happens below, motion ends stopped, and a controlword given ends at Disable voltage.
    auto finish = [&](const QString& failed) {
        data.releaseHold();
        data.stop();
        if (syncUs) s.master().sync().stop();
        QString end = failed;
        if (controlword) {
            canopen::Ds402Controller ctl(s.sdo(), *node);
            auto r = canopen::waitForResult<canopen::Ds402Result>(
                [&](canopen::Ds402Callback cb) { ctl.disableVoltage(cb); }, 5000);
            if (!r || !r->ok)
                end += (end.isEmpty() ? QString() : QStringLiteral("; ")) + QStringLiteral("DISABLING FAILED: ") +
                       (r ? r->error : QStringLiteral("no answer"));
            else out << "node " << *node << ": controlword 6040h = 0000h (Disable voltage)\n";
        }
        out << "sent " << data.sent() << " frame(s)\n";
        out.flush();
        return end.isEmpty() ? int(Ok) : failure(verb, end);
    };
    if (motion) data.feedHold();
    if (!data.start(&error)) return finish(error);
    if (syncUs && !s.master().sync().start(&error)) return finish(error);
    if (data.mode() == canopen::ProcessData::Mode::Once && !motion) return finish({});
    QElapsedTimer t;
    t.start();
    const RunEnd e = waitWhileRunning(
        s.bus(),
        [&] {
            if (motion) data.feedHold();  // the CLI holds the "button" for --duration
            return data.lastError().isEmpty();
        },
        seconds > 0 ? seconds : 0.001, &error);
    if (e == RunEnd::BusFailed) return finish(error);
    if (!data.lastError().isEmpty()) return finish(data.lastError());
    return finish({});
}

COSCOPE_CLI_VERB({QStringLiteral("pdo send"),
                  QStringLiteral("Send a node's RPDO with values by object (asks before motion; ends stopped)."),
                  runPdoSend});

}  // namespace coscope::cli
