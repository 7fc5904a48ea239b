// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/od/ObjectDictionary.h"

#include <QString>

#include <functional>
#include <optional>

namespace coscope::sim {

// The simulator builds virtual devices from dictionaries, but reading EDS files lives in eds/
// (a layer above core). The eds layer installs a provider at start-up
// (eds::installSimulatorDictionaries()); core/sim asks it for a dictionary by name.
using DictionaryProvider = std::function<std::optional<od::ObjectDictionary>(const QString& name, QString* error)>;

void setDictionaryProvider(DictionaryProvider provider);
// Loads a dictionary by name through the installed provider; a clear error when none is.
std::optional<od::ObjectDictionary> loadDictionary(const QString& name, QString* error);

}  // namespace coscope::sim
