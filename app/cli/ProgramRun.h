// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "app/cli/BusSession.h"
#include "core/canopen/ProgramDownload.h"

#include <QTextStream>

#include <optional>

namespace coscope::cli {

// What a program download (CiA 302-3 §4: 1F51h program control, 1F50h program data) will send,
// step by step, for the CLI's confirmation text.
void printProgramPlan(QTextStream& out, const canopen::ProgramDownloadRequest& request, const QString& file);

// Runs the download on `session` with the steps and progress on stderr; Ctrl+C cancels it. Prints
// the node's program before and after (or the failure) to `out`. nullopt when it did not end.
std::optional<canopen::ProgramDownloadOutcome> runProgramDownload(BusSession& session,
                                                                  const canopen::ProgramDownloadRequest& request,
                                                                  QTextStream& out);

}  // namespace coscope::cli
