// SPDX-License-Identifier: GPL-3.0-or-later
// coscope-cli: the command line face of CoScope. Each verb is a file in this folder.
#include "app/BuildInfo.h"
#include "app/cli/CliVerb.h"
#include "core/log/Logging.h"
#include "core/logio/LogFormats.h"
#include "eds/SimulatorDictionaries.h"

#include <QCoreApplication>
#include <QLoggingCategory>
#include <QTextStream>

#include <algorithm>
#include <cstdio>

using namespace coscope;

namespace {

void printHelp() {
    QTextStream out(stdout);
    out << "Usage: coscope-cli [--log-level LEVEL] VERB [ARGS...]\n\n"
           "CoScope " COSCOPE_VERSION
           " - CANopen bus analyzer and servo-drive commissioning tool.\n\n"
           "Verbs:\n";
    auto sorted = cli::verbs();
    std::sort(sorted.begin(), sorted.end(), [](const auto& a, const auto& b) { return a.name < b.name; });
    for (const auto& v : sorted) out << "  " << v.name.leftJustified(12) << "  " << v.summary << "\n";
    out << "\nGlobal options:\n"
           "  --version          Print the version and the source revision.\n"
           "  --help             Print this help; VERB --help prints the verb's.\n"
           "  --log-level LEVEL  show log lines on stderr: trace, debug, info, warn, error, critical\n"
           "                     (default: none; the log file keeps info and up).\n"
           "\nBus URLs: socketcan://can0, virtualcan://can0 (any Qt CAN plugin), socketcand://HOST:PORT/CHANNEL,\n"
           "sim://?nodes=1:delta-asda-a2,2:aimotor, replay://PATH?speed=1.0; options bitrate=, fd=1, listen-only=1.\n"
           "Exit status: 0 success, 1 failure (one line on stderr), 2 usage error.\n";
    out << "\nLog formats (detected from the content; r = read, w = write):\n";
    for (const auto& f : logio::LogFormats::all())
        out << "  " << f.name.leftJustified(10) << (f.canRead ? "r" : "-") << (f.canWrite ? "w" : "-") << "  "
            << f.description << "\n";
}

}  // namespace

int main(int argc, char** argv) {
    // The Qt CAN plugin loader complains on stderr about vendor libraries that are not installed
    // (PEAK, Vector, ...); the reason still reaches the user through the bus error.
    QLoggingCategory::setFilterRules(QStringLiteral("qt.canbus.plugins.*=false"));
    QCoreApplication app(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("CoScope"));
    QCoreApplication::setApplicationVersion(QStringLiteral(COSCOPE_VERSION));

    QStringList args = app.arguments();
    args.removeFirst();
    // The console shows log lines only when asked (--log-level or $COSCOPE_LOG_LEVEL): a failing
    // verb prints exactly one line of its own; the log file keeps info and up either way.
    auto level = logging::levelFromEnvironment(spdlog::level::off);
    while (!args.isEmpty() && args.front().startsWith(u'-')) {
        const QString a = args.takeFirst();
        if (a == u"--version" || a == u"-V") {
            std::printf("%s\n", qPrintable(buildinfo::versionLine(QStringLiteral("coscope-cli"))));
            return cli::Ok;
        }
        if (a == u"--help" || a == u"-h") {
            printHelp();
            return cli::Ok;
        }
        if (a == u"--log-level" || a.startsWith(QStringLiteral("--log-level="))) {
            const QString value =
                a.contains(u'=') ? a.section(u'=', 1) : (args.isEmpty() ? QString() : args.takeFirst());
            auto parsed = logging::parseLevel(value);
            if (!parsed) {
                std::fprintf(
                    stderr,
                    "coscope-cli: invalid --log-level '%s'; use trace, debug, info, warn, error, critical or off\n",
                    qPrintable(value));
                return cli::Usage;
            }
            level = *parsed;
            continue;
        }
        std::fprintf(stderr, "coscope-cli: unknown option '%s' (see coscope-cli --help)\n", qPrintable(a));
        return cli::Usage;
    }
    if (args.isEmpty()) {
        printHelp();
        return cli::Usage;
    }
    logging::init(QStringLiteral("coscope-cli"), level);
    eds::installSimulatorDictionaries();  // before any sim:// bus is opened

    // Longest verb name first, so "eds check" wins over a hypothetical "eds".
    const cli::Verb* match = nullptr;
    int words = 0;
    for (const auto& v : cli::verbs()) {
        const QStringList parts = v.name.split(u' ');
        if (parts.size() > args.size()) continue;
        if (args.mid(0, parts.size()) == parts && parts.size() > words) {
            match = &v;
            words = static_cast<int>(parts.size());
        }
    }
    if (!match) {
        QStringList names;
        for (const auto& v : cli::verbs()) names << v.name;
        names.sort();
        std::fprintf(stderr, "coscope-cli: unknown verb '%s'; verbs: %s\n", qPrintable(args.front()),
                     qPrintable(names.join(QStringLiteral(", "))));
        return cli::Usage;
    }
    QStringList verbArgs = args.mid(words);
    verbArgs.prepend(QStringLiteral("coscope-cli ") + match->name);
    return match->run(verbArgs);
}
