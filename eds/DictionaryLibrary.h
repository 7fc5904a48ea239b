// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "eds/DocumentedIdentity.h"
#include "eds/EdsReader.h"

#include <QString>
#include <QStringList>

#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <vector>

namespace coscope::eds {

using DictionaryPtr = std::shared_ptr<const od::ObjectDictionary>;

// What a node tells about itself (CiA 301 §7.5.2), the objects a dictionary is matched by.
// nullopt = not read (or the node does not have the object).
struct DeviceIdentity {
    std::optional<std::uint32_t> deviceType;                       // 1000h
    std::optional<std::uint32_t> vendorId, productCode, revision;  // 1018h:01..03
    std::optional<QString> deviceName, softwareVersion;            // 1008h, 100Ah
    // Vendor-ID and product code both read and not both 0 (drives without 1018h answer 0/0).
    bool hasIdentity() const { return vendorId && productCode && (*vendorId != 0 || *productCode != 0); }
};

// The dictionaries CoScope knows, the one place that finds, loads, caches and matches them
// (DESIGN.md "eds/"): the bundled ones (resources/dictionaries, compiled in at
// :/dictionaries/NAME.eds) and the user's folder (QStandardPaths::GenericDataLocation +
// "/CoScope/dictionaries", files *.eds, *.dcf, *.xdd). A user file with the same base name as
// a bundled one replaces it. A sidecar NAME.json next to a dictionary adds units and identity:
//   {"units": {"6064:00": {"unit": "counts", "factor": 1.0}},
//    "identity": {"variants": [{"productCode": "0x6030"}], "placeholder": false,
//                 "deviceName": {"object": "1008:00", "value": "DLV-N050CQE"}}}
class DictionaryLibrary {
public:
    struct Entry {
        QString name;  // base file name, e.g. "delta-asda-a2"
        QString path;  // file or resource path
        bool bundled = false;
        std::optional<std::uint32_t> vendorId, productCode, revision;  // identity (1018h)
        std::vector<std::uint32_t> variantProducts;                    // sidecar: more product codes of the vendor
        bool placeholder = false;                                      // sidecar: a stand-in identity (generic-cia402)
        std::optional<std::uint32_t> deviceType;                       // 1000h default
        QString deviceName;                                            // 1008h default
        std::uint16_t stringIndex = 0;                                 // sidecar: 1008h or 100Ah names the device
        QString stringValue;                                           //   by this text (prefix, case-insensitive)
        // Vendor-ID and product code described and not both 0.
        bool hasIdentity() const { return vendorId && productCode && (*vendorId != 0 || *productCode != 0); }
    };

    // Scans the bundled resources and userFolder() (or `userFolder` when given). The identity
    // of the bundled dictionaries is read on first need (entries(), findByIdentity(), match()):
    // loading one by name, as `decode` does, does not parse the others.
    explicit DictionaryLibrary(const QString& userFolder = QString());
    // The library of the default user folder, scanned once (thread safe).
    static const DictionaryLibrary& shared();

    static QString defaultUserFolder();
    const QString& userFolder() const { return userFolder_; }
    const std::vector<Entry>& entries() const {
        readBundledIdentities();
        return entries_;
    }
    QStringList names() const;
    const Entry* find(const QString& name) const;

    // Loads a dictionary by name (with its unit sidecar); an unknown name is an error result.
    ReadResult load(const QString& name) const;

    // The best dictionary for a device's identity (1018h sub 1..3), or nullptr.
    // Rules: the vendor-ID and product code must both match; among those, an exact revision
    // wins, then the highest revision with the same major revision (bits 16..31; CiA 301
    // 7.5.2.21: same major = same CANopen behaviour), then the highest revision overall.
    // On a tie a user dictionary beats a bundled one. 0/0 is no identity: nullptr.
    const Entry* findByIdentity(std::uint32_t vendorId, std::uint32_t productCode,
                                std::optional<std::uint32_t> revision = std::nullopt) const;

    // The dictionary for what a node answered, or nullptr. With a real identity (1018h, not
    // 0/0): findByIdentity, the sidecar's product variants included. Identity 0/0 or unknown
    // never matches by identity: among the dictionaries without one, the device name (1008h)
    // or software version (100Ah) the dictionary documents, then its device type (1000h),
    // decide (the device type alone only when 1018h was read as 0/0); a device name that
    // differs rules a dictionary out; a tie matches nothing.
    const Entry* match(const DeviceIdentity& device) const;

    // A dictionary by library name or file path, loaded once and shared (thread safe; files
    // are read again each time, they may have changed). *name gets the library name or the
    // file's base name. nullptr with *error (one line) when unknown or unusable.
    DictionaryPtr loadShared(const QString& nameOrFile, QString* name = nullptr, QString* error = nullptr) const;

    // Reads a file (EDS/DCF/XDD) and applies NAME.json next to it when present.
    static ReadResult loadFile(const QString& path);
    // Applies a units sidecar (JSON bytes) to `od`; problems are reported to `diagnostics`.
    static void applyUnits(od::ObjectDictionary& od, const QByteArray& json, const QString& jsonName,
                           Diagnostics& diagnostics);

private:
    void scan(const QString& folder, bool bundled);
    static bool readIdentity(Entry& e);                                 // false: not a usable dictionary
    static void applyIdentity(Entry& e, const DocumentedIdentity& id);  // and the sidecar's
    static void readSidecarIdentity(Entry& e);
    void readBundledIdentities() const;  // once (thread safe)
    QString userFolder_;
    mutable std::vector<Entry> entries_;  // the identity of bundled entries filled in lazily
    std::unique_ptr<std::once_flag> bundledIdentitiesRead_ = std::make_unique<std::once_flag>();
};

// "FILE" as given on a command line: an existing path, or else a dictionary library name.
ReadResult loadDictionaryByPathOrName(const QString& fileOrName);

}  // namespace coscope::eds
