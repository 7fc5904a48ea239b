// SPDX-License-Identifier: GPL-3.0-or-later
// Real frames for gui_core_text (test_core_text.cpp) beyond the CiA 402 drive's: CAN error frames
// as SocketCAN reports them, LSS in both directions and EMCY with the vendors' alarm numbers.
#pragma once

#include "core/can/CanFrame.h"
#include "core/canopen/Lss.h"

#include <initializer_list>
#include <vector>

namespace coscope::coretextsamples {

// An error frame as candump -L writes it ("20000040#…"): CAN_ERR_FLAG dropped, `classes` the id
// (include/uapi/linux/can/error.h).
inline CanFrame errorFrame(uint32_t classes, std::initializer_list<uint8_t> bytes) {
    CanFrame f = CanFrame::classic(0, bytes);
    f.flags = CanFrame::Error;
    f.id = classes;
    return f;
}

// Every class, controller state, protocol violation type and location of error.h.
inline std::vector<CanFrame> canErrorFrames() {
    std::vector<CanFrame> out;
    out.push_back(errorFrame(0x040, {0, 0, 0, 0, 0, 0, 0, 0}));                     // bus-off
    for (uint8_t c : {0x01, 0x02, 0x04, 0x08, 0x10, 0x20, 0x40, 0x00, 0x30, 0x0C})  // controller
        out.push_back(errorFrame(0x004, {0, c, 0, 0, 0, 0, 0, 0}));
    for (uint8_t t : {0x01, 0x02, 0x04, 0x08, 0x10, 0x20, 0x40, 0x80, 0x84})  // protocol types
        out.push_back(errorFrame(0x008, {0, 0, t, 0, 0, 0, 0, 0}));
    for (uint8_t loc : {0x03, 0x02, 0x06, 0x04, 0x05, 0x07, 0x0F, 0x0E, 0x0C, 0x0D, 0x09, 0x0B, 0x0A, 0x08, 0x18, 0x19,
                        0x1B, 0x1A, 0x12})
        out.push_back(errorFrame(0x008, {0, 0, 0x02, loc, 0, 0, 0, 0}));  // form error at each location
    out.push_back(errorFrame(0x008, {0, 0, 0x00, 0x00, 0, 0, 0, 0}));     // protocol violation, no detail
    out.push_back(errorFrame(0x088, {0, 0, 0x04, 0x08, 0, 0, 0, 0}));     // stuff error in the CRC sequence + bus error
    out.push_back(errorFrame(0x020, {0, 0, 0, 0, 0, 0, 0, 0}));           // no ACK
    out.push_back(errorFrame(0x010, {0, 0, 0, 0, 0x07, 0, 0, 0}));        // transceiver
    out.push_back(errorFrame(0x002, {5, 0, 0, 0, 0, 0, 0, 0}));           // lost arbitration at bit 5
    out.push_back(errorFrame(0x002, {0, 0, 0, 0, 0, 0, 0, 0}));
    out.push_back(errorFrame(0x001, {0, 0, 0, 0, 0, 0, 0, 0}));           // TX timeout
    out.push_back(errorFrame(0x080, {0, 0, 0, 0, 0, 0, 0, 0}));           // bus error
    out.push_back(errorFrame(0x100, {0, 0, 0, 0, 0, 0, 0, 0}));           // restarted
    out.push_back(errorFrame(0x200, {0, 0, 0, 0, 0, 0, 0x88, 0x00}));     // counters only: passive
    out.push_back(errorFrame(0x204, {0, 0x20, 0, 0, 0, 0, 0x80, 0x10}));  // TX passive with counters
    out.push_back(errorFrame(0x064, {0, 0x20, 0, 0, 0, 0, 0, 0}));        // bus-off + controller + no ACK
    out.push_back(errorFrame(0x400, {0, 0, 0, 0, 0, 0, 0, 0}));           // a class error.h does not name
    return out;
}

// CiA 305 §4: master -> slave on 7E5h, slave -> master on 7E4h.
inline std::vector<CanFrame> lssFrames() {
    namespace l = canopen::lss;
    std::vector<CanFrame> out;
    auto m = [&](std::initializer_list<uint8_t> b) { out.push_back(CanFrame::classic(l::kMasterToSlave, b)); };
    auto s = [&](std::initializer_list<uint8_t> b) { out.push_back(CanFrame::classic(l::kSlaveToMaster, b)); };
    m({l::SwitchStateGlobal, 1, 0, 0, 0, 0, 0, 0});
    m({l::SwitchStateGlobal, 0, 0, 0, 0, 0, 0, 0});
    m({l::SwitchSelectiveVendor, 0xC3, 0x01, 0, 0, 0, 0, 0});
    m({l::SwitchSelectiveProduct, 0x00, 0x01, 0, 0, 0, 0, 0});
    m({l::SwitchSelectiveRevision, 0x02, 0, 0, 0, 0, 0, 0});
    m({l::SwitchSelectiveSerial, 0x78, 0x56, 0x34, 0x12, 0, 0, 0});
    s({l::SwitchSelectiveResponse, 0, 0, 0, 0, 0, 0, 0});
    m({l::ConfigureNodeId, 5, 0, 0, 0, 0, 0, 0});
    s({l::ConfigureNodeId, 0, 0, 0, 0, 0, 0, 0});
    s({l::ConfigureNodeId, 1, 0, 0, 0, 0, 0, 0});
    m({l::ConfigureBitTiming, 0, 4, 0, 0, 0, 0, 0});  // 125 kbit/s
    m({l::ConfigureBitTiming, 1, 2, 0, 0, 0, 0, 0});  // a vendor table
    s({l::ConfigureBitTiming, 0, 0, 0, 0, 0, 0, 0});
    s({l::ConfigureBitTiming, 1, 0, 0, 0, 0, 0, 0});
    m({l::ActivateBitTiming, 100, 0, 0, 0, 0, 0, 0});
    m({l::StoreConfiguration, 0, 0, 0, 0, 0, 0, 0});
    s({l::StoreConfiguration, 0, 0, 0, 0, 0, 0, 0});
    s({l::StoreConfiguration, 2, 0, 0, 0, 0, 0, 0});
    for (uint8_t cs : {l::InquireVendor, l::InquireProduct, l::InquireRevision, l::InquireSerial, l::InquireNodeId}) {
        m({cs, 0, 0, 0, 0, 0, 0, 0});
        s({cs, 0x05, 0x02, 0, 0, 0, 0, 0});
    }
    for (uint8_t cs : {l::IdentifyVendor, l::IdentifyProduct, l::IdentifyRevisionLow, l::IdentifyRevisionHigh,
                       l::IdentifySerialLow, l::IdentifySerialHigh})
        m({cs, 0x01, 0, 0, 0, 0, 0, 0});
    s({l::IdentifySlaveResponse, 0, 0, 0, 0, 0, 0, 0});
    m({l::IdentifyNonConfigured, 0, 0, 0, 0, 0, 0, 0});
    s({l::IdentifyNonConfiguredResponse, 0, 0, 0, 0, 0, 0, 0});
    m({l::Fastscan, 0, 0, 0, 0, 0x80, 0, 0});  // reset of the scan (bit checked 80h)
    m({l::Fastscan, 0x00, 0x00, 0x00, 0x10, 0x1C, 0, 0});
    m({l::Fastscan, 0xC3, 0x01, 0, 0, 0, 3, 0});
    m({0x99, 0, 0, 0, 0, 0, 0, 0});  // a command specifier CiA 305 does not define
    m({l::SwitchStateGlobal, 1});    // short frame
    return out;
}

// EMCY (CiA 301 §7.2.7.3.1) of node 2 (Delta ASDA-A2: alarm number in bytes 3-4, the panel's
// digits as hex) and node 3 (AIMOTOR: fault code in bytes 3-4, taken only with its error code).
inline std::vector<CanFrame> vendorEmcyFrames() {
    std::vector<CanFrame> out;
    auto e = [&](uint32_t node, uint16_t code, uint8_t reg, uint16_t alarm) {
        out.push_back(CanFrame::classic(
            0x080 + node, {uint8_t(code), uint8_t(code >> 8), reg, uint8_t(alarm), uint8_t(alarm >> 8), 0, 0, 0}));
    };
    e(2, 0x2310, 0x03, 0x0001);  // AL001
    e(2, 0x5441, 0x81, 0x0013);  // AL013
    e(2, 0x7305, 0x81, 0x0025);  // AL025
    e(2, 0x3300, 0x81, 0x0031);  // AL031
    e(2, 0x6100, 0x81, 0x0044);  // AL044
    e(2, 0x7305, 0x81, 0x0185);  // AL185
    e(2, 0xFF00, 0x81, 0x0999);  // not in the table
    e(2, 0x0000, 0x00, 0x0000);  // reset
    e(3, 0x6320, 0x81, 0x0101);  // Er.101
    e(3, 0x2311, 0x03, 0x0207);  // Er.207
    e(3, 0x3230, 0x81, 0x0620);  // Er.620
    e(3, 0x7306, 0x81, 0x0A33);  // Er.A33
    e(3, 0x7306, 0x81, 0x0101);  // Er.101's number with another error code: not taken
    return out;
}

}  // namespace coscope::coretextsamples
