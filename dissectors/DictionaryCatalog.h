// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "eds/DictionaryLibrary.h"

namespace coscope::dissect {

// Which dictionary each node of each bus uses is the network context's (NodeState::dictionary,
// per bus, NetworkContext.h). Finding, loading, caching and matching dictionaries by identity
// belong to eds::DictionaryLibrary; the dissectors only hold the shared, immutable result.
using DictionaryPtr = eds::DictionaryPtr;

}  // namespace coscope::dissect
