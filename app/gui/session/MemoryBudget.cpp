// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/session/MemoryBudget.h"

#include <QSettings>

#include <unistd.h>
#include <algorithm>

namespace coscope::gui {

size_t defaultTraceMemoryBudget() {
    constexpr size_t kMax = size_t{4} << 30;
    const long pages = ::sysconf(_SC_PHYS_PAGES);
    const long pageSize = ::sysconf(_SC_PAGE_SIZE);
    if (pages <= 0 || pageSize <= 0) return kMax;
    return std::min(kMax, static_cast<size_t>(pages) * static_cast<size_t>(pageSize) / 4);
}

size_t traceMemoryBudget() {
    const qlonglong mb = QSettings().value(kMemoryBudgetKey, 0).toLongLong();
    if (mb <= 0) return defaultTraceMemoryBudget();
    return static_cast<size_t>(mb) << 20;
}

}  // namespace coscope::gui
