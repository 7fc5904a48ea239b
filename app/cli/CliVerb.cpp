// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/cli/CliVerb.h"

#include <QTextStream>

#include <atomic>
#include <csignal>
#include <cstdio>

namespace coscope::cli {

namespace {
std::vector<Verb>& registry() {
    static std::vector<Verb> v;
    return v;
}
std::atomic<bool> g_interrupted{false};
void onSignal(int) { g_interrupted.store(true); }
}  // namespace

bool registerVerb(Verb verb) {
    registry().push_back(std::move(verb));
    return true;
}

const std::vector<Verb>& verbs() { return registry(); }

int usageError(const QString& verb, const QString& message) {
    std::fprintf(stderr, "coscope-cli %s: %s\n", qPrintable(verb), qPrintable(message));
    return Usage;
}

int failure(const QString& verb, const QString& message) {
    std::fprintf(stderr, "coscope-cli %s: %s\n", qPrintable(verb), qPrintable(message));
    return Failure;
}

bool parseArgs(QCommandLineParser& parser, const QString& verb, const QStringList& args, int* exitCode) {
    const QCommandLineOption help({QStringLiteral("h"), QStringLiteral("help")}, QStringLiteral("Show this help."));
    parser.addOption(help);
    parser.setSingleDashWordOptionMode(QCommandLineParser::ParseAsLongOptions);
    if (!parser.parse(args)) {
        *exitCode = usageError(verb, parser.errorText());
        return false;
    }
    if (parser.isSet(help)) {
        // QCommandLineParser names the program by argv[0]; the usage line names the verb too.
        QString text = parser.helpText();
        const QString usage = QStringLiteral("Usage: ");
        if (text.startsWith(usage)) text.replace(0, text.indexOf(u' ', usage.size()), usage + args.value(0));
        QTextStream(stdout) << text;
        *exitCode = Ok;
        return false;
    }
    return true;
}

void installInterruptHandler() {
    std::signal(SIGINT, onSignal);
    std::signal(SIGTERM, onSignal);
}

bool interrupted() { return g_interrupted.load(); }

}  // namespace coscope::cli
