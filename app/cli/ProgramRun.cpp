// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/cli/ProgramRun.h"

#include "app/cli/CliVerb.h"
#include "core/canopen/ServiceWait.h"

#include <cstdio>

namespace coscope::cli {

using canopen::ProgramDownload;
using canopen::ProgramDownloadOutcome;
using canopen::ProgramDownloadRequest;
using canopen::ProgramStep;

void printProgramPlan(QTextStream& out, const ProgramDownloadRequest& req, const QString& file) {
    const QString sub = QStringLiteral("%1").arg(req.program, 2, 16, QChar(u'0')).toUpper();
    out << "node " << req.node << ": program download of " << file << " (" << req.image.size() << " bytes), program "
        << req.program << ":\n"
        << "  1F51h:" << sub
        << " = 0  stop program (the node stops its application; a drive CoScope enabled is disabled first)\n";
    if (req.clear) out << "  1F51h:" << sub << " = 3  clear program (skipped if the node does not take it)\n";
    out << "  1F50h:" << sub << " <- " << req.image.size() << " bytes by " << (req.block ? "block" : "segmented")
        << " SDO\n";
    if (req.start)
        out << "  1F51h:" << sub << " = 1  start program, then wait for the boot-up and read 1F56h, 1F57h, 100Ah\n";
    out.flush();
}

std::optional<ProgramDownloadOutcome> runProgramDownload(BusSession& s, const ProgramDownloadRequest& req,
                                                         QTextStream& out) {
    ProgramDownload download(s.context(), s.sdo());
    std::optional<ProgramDownloadOutcome> result;
    auto step = [&](ProgramStep st) {
        if (st == ProgramStep::Done) return;
        std::fprintf(stderr, "%s\n", qPrintable(canopen::programStepName(st, req.program)));
    };
    auto progress = [](qint64 done, qint64 total, double rate) {
        std::fprintf(stderr, "  %lld / %lld bytes (%.0f%%), %.1f KiB/s\n", static_cast<long long>(done),
                     static_cast<long long>(total), total > 0 ? 100.0 * double(done) / double(total) : 0.0,
                     rate / 1024.0);
    };
    installInterruptHandler();
    download.run(req, step, progress, [&](const ProgramDownloadOutcome& o) { result = o; });
    bool cancelAsked = false;
    canopen::waitUntil(
        [&] {
            if (interrupted() && !cancelAsked) {
                cancelAsked = true;
                download.cancel();
            }
            return result.has_value();
        },
        24 * 3600 * 1000);
    if (!result) return std::nullopt;
    out << "before: " << result->before.summary() << "\n";
    if (result->ok) {
        if (!result->notes.isEmpty()) out << "note: " << result->notes << "\n";
        if (result->started) out << "after:  " << result->after.summary() << "\n";
        out << "node " << req.node << ": " << result->summary() << "\n";
    }
    out.flush();
    return result;
}

}  // namespace coscope::cli
