// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/od/ObjectDictionary.h"

#include <QByteArray>
#include <QString>

namespace coscope::eds {

// Writes a dictionary as a CiA 306 DCF: [FileInfo], [DeviceInfo], [DeviceCommissioning]
// (NodeID and Baudrate), [DummyUsage], the three object lists, every object and sub-object
// section (CompactSubObj arrays are written out in full), ParameterValue (the device's actual
// values) and Denotation, unknown keys and sections as they were read. ASCII-safe UTF-8, CR LF.
// EdsReader reads the result back into an equal dictionary.
class DcfWriter {
public:
    static QByteArray write(const od::ObjectDictionary& od);
    // nodeId/bitrate (kbit/s) override the commissioning values when non-zero.
    static QByteArray write(const od::ObjectDictionary& od, std::uint8_t nodeId, int bitrateKbit);
    static bool writeFile(const od::ObjectDictionary& od, const QString& path, QString* error = nullptr);
};

}  // namespace coscope::eds
