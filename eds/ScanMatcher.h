// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/canopen/NetworkScan.h"
#include "eds/DictionaryLibrary.h"

namespace coscope::eds {

// What a scan read from a node, as DictionaryLibrary::match takes it.
DeviceIdentity identityOf(const canopen::ScannedNode& node);
// The scan's dictionary matcher: DictionaryLibrary::shared().match.
canopen::NetworkScan::Matcher scanMatcher();

}  // namespace coscope::eds
