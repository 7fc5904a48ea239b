// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/can/CanFrame.h"

#include <QString>
#include <QStringList>

#include <cstdint>
#include <optional>

namespace coscope {

// What a CAN error frame says, in the SocketCAN layout every backend and log reader delivers
// (linux/can/error.h): class bits in the identifier, details in the 8 data bytes.
struct CanErrorReport {
    // The controller's fault confinement state (ISO 11898-1 §12.1.4: error active, error passive
    // from 128 errors, bus-off from 256 transmit errors; "warning" is the controllers' 96 level).
    enum class BusState : uint8_t { Unknown, Active, Warning, Passive, BusOff };

    uint32_t classes = 0;                // CAN_ERR_* class bits
    uint8_t controller = 0;              // CAN_ERR_CRTL_* details (data[1]) when classes has CRTL
    BusState state = BusState::Unknown;  // the state this frame reports, Unknown when it says none
    std::optional<uint8_t> txErrors;     // transmit / receive error counters (CAN_ERR_CNT)
    std::optional<uint8_t> rxErrors;
    QStringList problems;  // one short text per reported problem, worst first

    // "bus-off", "controller: RX error passive; TX error counter 130", …
    QString summary() const;
    // Bus-off, error passive or lost frames: worth a warning in the trace and the Events.
    bool isSevere() const;
};

// Decodes `frame` (which must be an error frame: frame.isError()).
CanErrorReport decodeCanError(const CanFrame& frame);

// "error active", "error warning", "error passive", "bus-off", "" for Unknown.
QString busStateName(CanErrorReport::BusState state);

}  // namespace coscope
