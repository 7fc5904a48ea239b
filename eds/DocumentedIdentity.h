// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/od/ObjectDictionary.h"

#include <QString>

#include <cstdint>
#include <optional>

namespace coscope::eds {

// The identity a dictionary documents, by which the library matches it to a device (CiA 301
// §7.5.2: 1018h:01..03 or [DeviceInfo]'s numbers, the defaults of 1000h and 1008h).
struct DocumentedIdentity {
    std::optional<std::uint32_t> vendorId, productCode, revision;  // 1018h:01..03
    std::optional<std::uint32_t> deviceType;                       // 1000h default
    QString deviceName;                                            // 1008h default, trimmed
    bool operator==(const DocumentedIdentity&) const = default;
};

DocumentedIdentity documentedIdentity(const od::ObjectDictionary& d);

// The same, read from an EDS/DCF file's few sections that hold it ([FileInfo], [DeviceInfo],
// [DeviceCommissioning] for $NODEID, the data type definitions and the 1000h, 1008h and 1018h
// sections), which the EDS reader then reads as it reads the whole file: the library
// learns the bundled dictionaries' identities so, without parsing each of them whole (30 ms of
// a `decode` or `stats` whose log reads a drive's identity; test_eds_library checks it finds
// what the whole file says). nullopt when the file cannot be read or is not an EDS/DCF.
std::optional<DocumentedIdentity> readDocumentedIdentity(const QString& path);

}  // namespace coscope::eds
