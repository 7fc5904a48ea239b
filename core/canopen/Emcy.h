// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QString>
#include <QStringList>

#include <cstdint>

namespace coscope::canopen {

// EMCY message (CiA 301 §7.2.7.3.1): bytes 0-1 error code (LE), byte 2 error register (1001h),
// bytes 3-7 manufacturer-specific error field. Error code 0000h = error reset / no error.
struct EmcyMessage {
    uint16_t code = 0;
    uint8_t errorRegister = 0;
    uint8_t vendor[5] = {};
};
EmcyMessage parseEmcy(const uint8_t* data, int len);

// Text of a standard error code: the exact CiA 301 / CiA 402 entry when known, otherwise the
// class of its high byte(s) ("Current, device output side", "Device specific", ...).
QString emcyCodeText(uint16_t code);
// Names of the bits set in the error register 1001h (CiA 301 §7.5.2.2, Table 47).
QStringList errorRegisterBits(uint8_t reg);

}  // namespace coscope::canopen
