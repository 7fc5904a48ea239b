// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QByteArray>
#include <QHash>
#include <QString>

#include <cstdint>
#include <optional>

namespace coscope::canopen {

// Vendor meanings of SDO abort codes: the "sdoAborts" list of a vendor alarm table
// (resources/alarms/NAME.json, schema in resources/README.md). CiA 301 texts come from
// sdoAbortText(); a vendor table adds the codes the vendor documents.
class VendorAbortTable {
public:
    // Parses the JSON of an alarm table; false with *error when it is not one.
    bool load(const QByteArray& json, QString* error = nullptr);
    // Loads ":/alarms/NAME.json" (compiled into coscope_eds) or a file path; false when absent.
    bool loadDictionaryTable(const QString& dictionaryName, QString* error = nullptr);

    std::optional<QString> text(uint32_t code) const;
    bool isEmpty() const { return texts_.isEmpty(); }
    const QString& vendor() const { return vendor_; }

private:
    QHash<uint32_t, QString> texts_;
    QString vendor_;
};

// "Object does not exist in the object dictionary (0x06020000)": the vendor's text when its
// table documents the code, else the CiA 301 text, else "Unknown abort code".
QString describeSdoAbort(uint32_t code, const VendorAbortTable* vendor = nullptr);

}  // namespace coscope::canopen
