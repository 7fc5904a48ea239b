// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QString>

#include <cstddef>

namespace coscope::gui {

// The RAM a live trace may hold (issue 16 "Bounded memory"); older frames are paged back from
// the capture journal. QSettings `trace/memoryBudgetMB` (MiB, at least 1); unset or 0: a
// quarter of the physical memory, at most 4 GiB.
inline const QString kMemoryBudgetKey = QStringLiteral("trace/memoryBudgetMB");
size_t traceMemoryBudget();
size_t defaultTraceMemoryBudget();

}  // namespace coscope::gui
