// SPDX-License-Identifier: GPL-3.0-or-later
#include "eds/ScanMatcher.h"

namespace coscope::eds {

DeviceIdentity identityOf(const canopen::ScannedNode& node) {
    DeviceIdentity d;
    d.deviceType = node.deviceType;
    d.vendorId = node.vendorId;
    d.productCode = node.productCode;
    d.revision = node.revision;
    d.deviceName = node.deviceName;
    d.softwareVersion = node.softwareVersion;
    return d;
}

canopen::NetworkScan::Matcher scanMatcher() {
    return [](const canopen::ScannedNode& node) {
        const auto* e = DictionaryLibrary::shared().match(identityOf(node));
        return e ? e->name : QString();
    };
}

}  // namespace coscope::eds
