// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/project/ProjectCompare.h"

namespace coscope::project {

// The comparison as the CLI prints it and the GUI exports it (English, like the CLI).
QString compareText(const CompareReport& report, bool onlyDifferences);
QByteArray compareJson(const CompareReport& report);
QString compareHtml(const CompareReport& report, bool onlyDifferences);
// RFC 4180 CSV: node,object,name,project,drive,default,state,note
QString compareCsv(const CompareReport& report, bool onlyDifferences);

}  // namespace coscope::project
