// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "eds/EdsReader.h"

#include <QString>
#include <QStringList>

#include <cstdint>
#include <optional>
#include <vector>

namespace coscope::eds {

// The dictionaries CoScope knows: the bundled ones (resources/dictionaries, compiled in at
// :/dictionaries/NAME.eds) and the user's folder (QStandardPaths::GenericDataLocation +
// "/CoScope/dictionaries", files *.eds, *.dcf, *.xdd). A user file with the same base name as
// a bundled one replaces it. A sidecar NAME.json next to a dictionary adds units:
//   {"units": {"6064:00": {"unit": "counts", "factor": 1.0}}}
class DictionaryLibrary {
public:
    struct Entry {
        QString name;  // base file name, e.g. "delta-asda-a2"
        QString path;  // file or resource path
        bool bundled = false;
        std::optional<std::uint32_t> vendorId, productCode, revision;  // identity (1018h)
    };

    // Scans the bundled resources and userFolder() (or `userFolder` when given).
    explicit DictionaryLibrary(const QString& userFolder = QString());

    static QString defaultUserFolder();
    const QString& userFolder() const { return userFolder_; }
    const std::vector<Entry>& entries() const { return entries_; }
    QStringList names() const;
    const Entry* find(const QString& name) const;

    // Loads a dictionary by name (with its unit sidecar); an unknown name is an error result.
    ReadResult load(const QString& name) const;

    // The best dictionary for a device's identity (1018h sub 1..3), or nullptr.
    // Rules: the vendor-ID and product code must both match; among those, an exact revision
    // wins, then the highest revision with the same major revision (bits 16..31; CiA 301
    // 7.5.2.21: same major = same CANopen behaviour), then the highest revision overall.
    // On a tie a user dictionary beats a bundled one.
    const Entry* findByIdentity(std::uint32_t vendorId, std::uint32_t productCode, std::optional<std::uint32_t> revision = std::nullopt) const;

    // Reads a file (EDS/DCF/XDD) and applies NAME.json next to it when present.
    static ReadResult loadFile(const QString& path);
    // Applies a units sidecar (JSON bytes) to `od`; problems are reported to `diagnostics`.
    static void applyUnits(od::ObjectDictionary& od, const QByteArray& json, const QString& jsonName, Diagnostics& diagnostics);

private:
    void scan(const QString& folder, bool bundled);
    QString userFolder_;
    std::vector<Entry> entries_;
};

// "FILE" as given on a command line: an existing path, or else a dictionary library name.
ReadResult loadDictionaryByPathOrName(const QString& fileOrName);

}  // namespace coscope::eds
