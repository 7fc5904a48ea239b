// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/project/ProjectMatch.h"

namespace coscope::eds {

// Resolves a project node's "dictionary": a file (relative to `projectFolder` or absolute) or a
// dictionary library name (DictionaryLibrary::shared()). Empty: none, with an error naming the node.
project::DictionaryResolver projectDictionaryResolver(const QString& projectFolder);

}  // namespace coscope::eds
