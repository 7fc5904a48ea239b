// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QString>

#include <cstdint>
#include <optional>
#include <vector>

namespace coscope::canopen {

// When a new node-ID or bit rate written to a vendor parameter is used by the device.
enum class TakesEffect : uint8_t {
    ResetNode,   // NMT Reset Node (CiA 301 §7.2.8.3.1) or a power cycle
    PowerCycle,  // only after switching the device off and on (the wizard also tries Reset Node)
};

// A vendor parameter holding the node-ID or the CAN bit rate, and how its value is encoded.
struct VendorSettingObject {
    uint16_t index = 0;
    uint8_t sub = 0;
    int size = 2;       // bytes on the bus (SDO expedited)
    QString parameter;  // the vendor's name, e.g. "P3-00"
    // Bit rate only: value = (code << shift) within mask; code i means bitRates[i] (bit/s).
    uint32_t mask = 0;
    int shift = 0;
    std::vector<int> bitRates;
    bool storedOnWrite = false;  // the device saves it at once (no 1010h "save" needed)
    TakesEffect takesEffect = TakesEffect::ResetNode;
    bool inferred = false;  // the manual does not state this object plainly
    QString source;         // manual section, for the technician
};

// Where a device keeps its node-ID and bit rate besides LSS (CiA 305), by the bundled
// dictionary's name (the sidecar's "name": delta-asda-a2, aimotor, dexmart-dev). The one place
// this knowledge lives: the simulator's personalities and the node-settings service read it.
struct VendorNodeSettings {
    QString dictionary;
    std::optional<VendorSettingObject> nodeId;
    std::optional<VendorSettingObject> bitRate;
    int minNodeId = 1, maxNodeId = 127;
    QString note;  // what a technician should know (plain words)
};

// nullopt when the dictionary is not known to have such parameters (then: LSS only).
std::optional<VendorNodeSettings> vendorNodeSettings(const QString& dictionary);

// Bit-rate parameter: the value to write for `bitRate` keeping the other digits of `current`
// (nullopt when the rate has no code); the bit rate a value means (0 when unknown).
std::optional<uint32_t> encodeVendorBitRate(const VendorSettingObject& o, int bitRate, uint32_t current);
int decodeVendorBitRate(const VendorSettingObject& o, uint32_t value);

// "500 kbit/s", "1 Mbit/s"
QString bitRateText(int bitRate);

}  // namespace coscope::canopen
