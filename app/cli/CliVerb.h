// SPDX-License-Identifier: GPL-3.0-or-later
// Folder app/cli/ owns coscope-cli: one file per verb (VerbNmt.cpp, VerbSdo.cpp, …) registered with
// COSCOPE_CLI_VERB, the shared exit codes and one-line error contract, and BusSession (open a bus
// URL, run services, wait). English output only.
#pragma once

#include <QCommandLineParser>
#include <QString>
#include <QStringList>

#include <functional>
#include <vector>

namespace coscope::cli {

// Exit codes shared by every verb (DESIGN.md "coscope-cli verbs").
enum Exit { Ok = 0, Failure = 1, Usage = 2 };

// One verb of coscope-cli. Each verb lives in its own file and registers itself with
// COSCOPE_CLI_VERB; `name` may have two words ("eds check", "sdo read").
struct Verb {
    QString name;
    QString summary;
    // args[0] is "coscope-cli <name>", the rest are the verb's own arguments.
    std::function<int(const QStringList& args)> run;
};

bool registerVerb(Verb verb);
const std::vector<Verb>& verbs();

// Helpers for the one-line error contract.
int usageError(const QString& verb, const QString& message);  // prints, returns 2
int failure(const QString& verb, const QString& message);     // prints, returns 1

// Parses args with `parser` (adds --help); on error prints one line and returns false with
// *exitCode = 2; on --help prints help and returns false with *exitCode = 0.
bool parseArgs(QCommandLineParser& parser, const QString& verb, const QStringList& args, int* exitCode);

// Installs SIGINT/SIGTERM handling: interrupted() becomes true (for listen/record loops).
void installInterruptHandler();
bool interrupted();

}  // namespace coscope::cli

#define COSCOPE_CLI_CONCAT2(a, b) a##b
#define COSCOPE_CLI_CONCAT(a, b) COSCOPE_CLI_CONCAT2(a, b)
#define COSCOPE_CLI_VERB(...) \
    static const bool COSCOPE_CLI_CONCAT(coscopeVerbRegistered_, __LINE__) = ::coscope::cli::registerVerb(__VA_ARGS__)
