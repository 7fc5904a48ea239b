// SPDX-License-Identifier: GPL-3.0-or-later
// Folder eds/ owns device descriptions: EDS/DCF (CiA 306) and XDD (CiA 311) reading, DCF writing,
// diagnostics, the standard dictionary and the library of bundled and user dictionaries. QtCore
// only.
#pragma once

#include "core/od/ObjectDictionary.h"
#include "eds/Diagnostic.h"

#include <QByteArray>
#include <QString>

namespace coscope::eds {

// What reading a dictionary file gives: the dictionary, the findings, and whether the file is
// usable (it is rejected only when no object could be read from it).
struct ReadResult {
    od::ObjectDictionary dictionary;
    Diagnostics diagnostics;
    bool usable = false;
    QString encoding;  // text encoding that was detected
    int warningCount() const;
    int errorCount() const;
};

// Reader for CiA 306 EDS and DCF files (v1.3; earlier files are accepted).
//
// Lenient by design, every problem is a "FILE:LINE: warning|error: message":
//  - section names and keys are case-insensitive, section order is irrelevant;
//  - DUPLICATE RULE: the first occurrence of a key or section wins; later duplicates are
//    warned about with their line (a repeated section is merged into the first);
//  - the object set is the union of [MandatoryObjects], [OptionalObjects] and
//    [ManufacturerObjects]; object sections that no list names are read too (warned);
//    without any list every [XXXX] section is an object (one warning);
//  - CompactSubObj (CiA 306 4.5.2.3) with [XXXXName] and [XXXXValue]; CompactPDO (CiA 306
//    4.6.2: missing PDO communication/mapping objects up to NrOfRXPDO/NrOfTXPDO are implied);
//    [DummyUsage]; [DynamicChannels]; [XXXXObjectLinks]; [DeviceCommissioning] and the old
//    spelling [DeviceComissioning]; ParameterValue and Denotation (DCF);
//  - numbers in decimal, 0x hex or (leading 0) octal; $NODEID formulas on either side
//    ("$NODEID+0x180", "0x180+$NODEID") are kept as written and resolved on demand;
//    REAL defaults as decimals or 0x bit patterns;
//  - any byte encoding (UTF-8 with/without BOM, UTF-16 with BOM, else Windows-1252), CR LF;
//  - ';' and '#' comment lines; an inline " # ..." / " ; ..." after a numeric value is
//    dropped with a warning (names keep their '#');
//  - custom data types (DEFTYPE/DEFSTRUCT objects and unknown type codes) are kept; their
//    values are handled as DOMAIN bytes.
// Values that do not fit their data type are warned about and kept as text.
class EdsReader {
public:
    static ReadResult read(const QByteArray& bytes, const QString& fileNameForDiagnostics);
    static ReadResult readFile(const QString& path);  // a missing file is an error, not usable
};

// Reads EDS, DCF or XDD (sniffed from the content: XML goes to XddReader).
ReadResult readDictionaryFile(const QString& path);
ReadResult readDictionary(const QByteArray& bytes, const QString& fileNameForDiagnostics);

}  // namespace coscope::eds
