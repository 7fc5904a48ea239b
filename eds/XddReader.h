// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "eds/EdsReader.h"

namespace coscope::eds {

// Reader for CiA 311 XML device descriptions (XDD/XDC) into the same model as the EDS reader.
// Objects come from CANopenObjectList (index, name, objectType, PDOmapping, subNumber and,
// when present, dataType/accessType/defaultValue/lowLimit/highLimit/actualValue/denotation
// attributes); missing attributes are taken from the device profile parameter that
// uniqueIDRef names (IEC 61131 type element such as <UDINT/>, access, defaultValue,
// actualValue). Identity from DeviceIdentity, baud rates from PhysicalLayer, PDO counts and
// LSS from CANopenGeneralFeatures, node-ID/bit rate from deviceCommissioning.
// Malformed XML keeps what was read before the error and reports the line.
class XddReader {
public:
    static ReadResult read(const QByteArray& bytes, const QString& fileNameForDiagnostics);
};

}  // namespace coscope::eds
