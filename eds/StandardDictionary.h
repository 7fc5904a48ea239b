// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/od/ObjectDictionary.h"

namespace coscope::eds {

// The objects every CANopen device has by standard, by name and type, for nodes whose own
// dictionary is unknown (and for objects their dictionary leaves out):
//  - the bundled generic-cia402 dictionary (CiA 301 communication objects 1000h-1029h and the
//    CiA 402 objects, written from CiA 301 and CiA 402-2);
//  - completed with the CiA 301 v4.2 section 7.5 objects it lacks: 1002h, 1012h, 1013h,
//    1020h-1028h, SDO server/client parameters 1200h-12FFh, RPDO/TPDO communication and
//    mapping parameters 1400h-1BFFh (all 512 of each, mapping entries 1-40h).
// Limits are dropped (they are a device's, not the standard's); default values are those of the
// generic drive and mean nothing for another device. Built once, on first use; thread safe.
const od::ObjectDictionary& standardDictionary();

// The entry a node's dictionary gives for (index, sub), else the standard one (nullptr when
// neither has it). A device's own entry wins: e.g. AIMOTOR's 1017h is UNSIGNED32 in its EDS
// where CiA 301 says UNSIGNED16. *names gets the dictionary that answered.
const od::SubObject* entryWithStandard(const od::ObjectDictionary* device, std::uint16_t index, std::uint8_t sub,
                                       const od::ObjectDictionary** names = nullptr);

}  // namespace coscope::eds
