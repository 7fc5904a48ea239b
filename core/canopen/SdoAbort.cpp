// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/canopen/SdoAbort.h"

namespace coscope::canopen {

QString sdoAbortText(uint32_t code) {
    using namespace sdoabort;
    switch (code) {
    case ToggleBit: return QStringLiteral("Toggle bit not alternated");
    case Timeout: return QStringLiteral("SDO protocol timed out");
    case InvalidCommand: return QStringLiteral("Client/server command specifier not valid or unknown");
    case InvalidBlockSize: return QStringLiteral("Invalid block size (block mode only)");
    case InvalidSequence: return QStringLiteral("Invalid sequence number (block mode only)");
    case CrcError: return QStringLiteral("CRC error (block mode only)");
    case OutOfMemory: return QStringLiteral("Out of memory");
    case UnsupportedAccess: return QStringLiteral("Unsupported access to an object");
    case WriteOnly: return QStringLiteral("Attempt to read a write-only object");
    case ReadOnly: return QStringLiteral("Attempt to write a read-only object");
    case NoObject: return QStringLiteral("Object does not exist in the object dictionary");
    case NotMappable: return QStringLiteral("Object cannot be mapped to the PDO");
    case PdoLengthExceeded:
        return QStringLiteral("The number and length of the objects to be mapped would exceed the PDO length");
    case ParameterIncompatible: return QStringLiteral("General parameter incompatibility reason");
    case InternalIncompatible: return QStringLiteral("General internal incompatibility in the device");
    case HardwareError: return QStringLiteral("Access failed due to a hardware error");
    case TypeMismatch: return QStringLiteral("Data type does not match, length of service parameter does not match");
    case LengthTooHigh: return QStringLiteral("Data type does not match, length of service parameter too high");
    case LengthTooLow: return QStringLiteral("Data type does not match, length of service parameter too low");
    case NoSubIndex: return QStringLiteral("Sub-index does not exist");
    case InvalidValue: return QStringLiteral("Invalid value for parameter (download only)");
    case ValueTooHigh: return QStringLiteral("Value of parameter written too high (download only)");
    case ValueTooLow: return QStringLiteral("Value of parameter written too low (download only)");
    case MaxLessThanMin: return QStringLiteral("Maximum value is less than minimum value");
    case NoResource: return QStringLiteral("Resource not available: SDO connection");
    case GeneralError: return QStringLiteral("General error");
    case CannotStore: return QStringLiteral("Data cannot be transferred or stored to the application");
    case LocalControl:
        return QStringLiteral("Data cannot be transferred or stored to the application because of local control");
    case DeviceState:
        return QStringLiteral(
            "Data cannot be transferred or stored to the application because of the present device state");
    case NoDictionary:
        return QStringLiteral("Object dictionary dynamic generation fails or no object dictionary is present");
    case NoData: return QStringLiteral("No data available");
    // Not in CiA 301's table (§7.2.4.3.17): some devices abort with 0, which names no reason.
    case 0: return QStringLiteral("No reason given");
    default: return {};
    }
}

}  // namespace coscope::canopen
