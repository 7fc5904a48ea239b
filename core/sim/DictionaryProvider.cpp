// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/sim/DictionaryProvider.h"

#include <mutex>

namespace coscope::sim {

namespace {
std::mutex g_mutex;
DictionaryProvider& provider() {
    static DictionaryProvider p;
    return p;
}
}  // namespace

void setDictionaryProvider(DictionaryProvider p) {
    std::lock_guard lock(g_mutex);
    provider() = std::move(p);
}

std::optional<od::ObjectDictionary> loadDictionary(const QString& name, QString* error) {
    DictionaryProvider p;
    {
        std::lock_guard lock(g_mutex);
        p = provider();
    }
    if (!p) {
        if (error)
            *error = QStringLiteral(
                "no dictionary provider installed: call eds::installSimulatorDictionaries() at start-up");
        return std::nullopt;
    }
    return p(name, error);
}

}  // namespace coscope::sim
