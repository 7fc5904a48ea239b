// SPDX-License-Identifier: GPL-3.0-or-later
// coscope-cli eds check FILE...: reads EDS/DCF/XDD files (or bundled dictionary names) and
// prints every finding as FILE:LINE: warning|error: message. Exit 0 when every file is usable.
#include "app/cli/CliVerb.h"
#include "eds/DictionaryLibrary.h"

#include <QTextStream>

namespace coscope::cli {

static int runEdsCheck(const QStringList& args) {
    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral("Check EDS/DCF/XDD files; FILE may be a bundled dictionary name."));
    parser.addPositionalArgument(QStringLiteral("FILE"), QStringLiteral("Dictionary files or names."),
                                 QStringLiteral("FILE..."));
    parser.addOption({QStringLiteral("quiet"), QStringLiteral("Print only errors and the summary.")});
    int code = 0;
    if (!parseArgs(parser, QStringLiteral("eds check"), args, &code)) return code;
    const QStringList files = parser.positionalArguments();
    if (files.isEmpty()) return usageError(QStringLiteral("eds check"), QStringLiteral("needs at least one FILE"));
    QTextStream out(stdout);
    QTextStream err(stderr);
    int unusable = 0;
    for (const QString& file : files) {
        const eds::ReadResult r = eds::loadDictionaryByPathOrName(file);
        for (const auto& d : r.diagnostics) {
            if (parser.isSet(QStringLiteral("quiet")) && d.severity == eds::Diagnostic::Severity::Warning) continue;
            out << d.toString() << "\n";
        }
        out << file << ": " << (r.usable ? "ok" : "NOT USABLE") << ", " << r.dictionary.objectCount() << " objects, "
            << r.dictionary.subObjectCount() << " sub-objects, " << r.warningCount() << " warnings, " << r.errorCount()
            << " errors\n";
        if (!r.usable) ++unusable;
    }
    out.flush();
    if (unusable) {
        err << "coscope-cli eds check: " << unusable << " of " << files.size() << " files not usable\n";
        return Failure;
    }
    return Ok;
}

COSCOPE_CLI_VERB({QStringLiteral("eds check"), QStringLiteral("Check EDS/DCF/XDD dictionary files."), runEdsCheck});

}  // namespace coscope::cli
