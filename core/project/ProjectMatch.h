// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/canopen/NetworkScan.h"
#include "core/od/ObjectDictionary.h"
#include "core/project/Project.h"

#include <functional>
#include <optional>
#include <vector>

namespace coscope::project {

// How a node found on the bus stands against the project, by node-ID and identity 1018h:01..04
// (CiA 301 7.5.2.24).
enum class NodeMatch : uint8_t {
    Same,             // node-ID and identity as in the project
    Replaced,         // same vendor and product, another serial number: a drive of the same type
    DifferentDevice,  // another vendor or product code at this node-ID
    Missing,          // in the project, no answer on the bus
    NotInProject,     // answers on the bus, not in the project
};
QString nodeMatchName(NodeMatch m);  // "same", "replaced", "different device", "missing", "not in project"

struct MatchedNode {
    uint8_t node = 0;
    NodeMatch match = NodeMatch::Missing;
    const ProjectNode* project = nullptr;       // null: not in the project
    std::optional<canopen::ScannedNode> found;  // null: no answer
    QString detail;                             // "serial 0x51000099, project 0x51000003"
};

// Pairs the project's nodes with a scan's, in node-ID order.
std::vector<MatchedNode> matchNodes(const Project& project, const std::vector<canopen::ScannedNode>& found);

// The node's dictionary for a project node (the app resolves bundled names and files: core cannot
// read EDS). nullopt with *error when there is none.
using DictionaryResolver = std::function<std::optional<od::ObjectDictionary>(const ProjectNode& node, QString* error)>;

// Configuration objects of a dictionary: readable and writable, not DOMAIN, not a command object
// (DeviceConfiguration::isCommandObject).
bool isConfigurationEntry(const od::SubObject& s);

// The value text read back in the project's notation, and whether two value texts are the same
// value of `entry`'s type (compared encoded, $NODEID resolved with `node`).
bool sameValue(const od::SubObject& entry, const QString& a, const QString& b, uint8_t node);
// The dictionary default of `entry` as DCF text ("" = none).
QString defaultText(const od::SubObject& entry, uint8_t node);

// What the project expects of a node: its parameters, and every other configuration entry of the
// dictionary at its default (an entry without a default is not expected to hold anything).
struct ExpectedValue {
    uint16_t index = 0;
    uint8_t sub = 0;
    QString value;            // DCF text
    bool configured = false;  // from the project's parameters (else the default)
};
std::vector<ExpectedValue> expectedValues(const od::ObjectDictionary& dictionary, const ProjectNode& node);

// Scans nodes `first..last` (NetworkScan, 1000h and 1018h) and hands back the matches. The scan
// writes what it found into the bus's node table: `matcher` (eds::scanMatcher()) names the
// dictionaries there, as any scan does.
void scanMachine(canopen::SdoClient& sdo, const Project& project, uint8_t first, uint8_t last, int timeoutMs,
                 canopen::NetworkScan::Matcher matcher, std::function<void(std::vector<MatchedNode>)> done,
                 QObject* owner);

}  // namespace coscope::project
