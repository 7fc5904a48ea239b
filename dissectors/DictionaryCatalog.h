// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/od/ObjectDictionary.h"

#include <QString>

#include <cstdint>
#include <memory>
#include <optional>

namespace coscope::dissect {

using DictionaryPtr = std::shared_ptr<const od::ObjectDictionary>;

// Dictionaries for the network context: the bundled ones by name (read once, shared, thread
// safe) and user files (EDS/DCF/XDD). Identity matching uses the bundled sidecars
// (resources/dictionaries/NAME.json "identity": vendorId/productCode/variants, or a
// software-version / device-name string object when 1018h is not documented).
namespace catalog {

DictionaryPtr bundled(const QString& name, QString* error = nullptr);
DictionaryPtr fromFile(const QString& path, QString* error = nullptr);
// A bundled name, or a file path: what --dict NODE=NAME|FILE accepts. *name gets the
// dictionary's name (bundled name, or the file's base name).
DictionaryPtr load(const QString& nameOrFile, QString* name, QString* error);

// Name of the bundled dictionary whose identity matches, or empty. Placeholder identities
// (generic-cia402) never match.
QString matchIdentity(uint32_t vendorId, uint32_t productCode);
// Match by a string object (1008h device name, 100Ah software version).
QString matchStringObject(uint16_t index, const QString& value);

// Alarm-table/personality name of a dictionary name ("delta-asda-a2" -> "delta-asda-a2"
// when resources/alarms/NAME.json exists), else empty.
QString alarmTableFor(const QString& dictionaryName);

}  // namespace catalog
}  // namespace coscope::dissect
