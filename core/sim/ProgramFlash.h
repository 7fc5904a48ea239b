// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QByteArray>
#include <QString>

#include <cstdint>

namespace coscope::od {
class ObjectDictionary;
}

namespace coscope::sim {

class VirtualDevice;

// The program download objects of a virtual device (CiA 302-3, program download), program
// number 1 only:
//   1F50h:01 program data, DOMAIN, wo: takes an image (ProgramImage.h) while the program is
//            stopped; refused with 08000022h (device state) while it runs.
//   1F51h:01 program control, UNSIGNED8, rw: write 0 stop, 1 start, 2 reset, 3 clear; reads
//            0 stopped, 1 running. Start checks the image: a bad one sets 1F57h and is refused
//            with 08000020h; a good one becomes the running program and the node resets
//            (boot-up) right after the SDO answer went out. Start without a download runs the
//            old program again unless it was cleared.
//   1F56h:01 program software identification, UNSIGNED32, ro: CRC-32 of the running program.
//   1F57h:01 flash status identification, UNSIGNED32, ro: bit 0 in progress (always 0 here:
//            the write is one step), bits 1-7 error: 0 none, 1 no valid program, 2 data format
//            unknown, 3 data format error (length or CRC).
//   100Ah    manufacturer software version (CiA 301 §7.5.2.7): the running program's version.
// The program survives resets and power cycles (it is flash). Added to every dictionary that
// lacks the objects, with the dictionary's 100Ah as the first version.
class ProgramFlash {
public:
    explicit ProgramFlash(VirtualDevice& device);

    // Adds the objects above where the dictionary has none; reads the first version.
    void addObjects(od::ObjectDictionary& dictionary);
    // Writes to 1F50h / 1F51h (after the device's access and length checks): 0 or an abort code.
    static bool handles(uint16_t index) { return index == 0x1F50 || index == 0x1F51; }
    uint32_t write(uint16_t index, uint8_t sub, const QByteArray& bytes);
    // Puts the flash's state into the device's values (after a write, and after any reset that
    // reloaded the defaults).
    void publish();
    // True once when a start or reset asked for a node reset (the device resets on its tick,
    // after the answer to the write went out).
    bool takeResetRequest();

    bool running() const { return running_; }
    QString version() const { return version_; }
    uint32_t softwareId() const { return softwareId_; }
    uint32_t flashStatus() const { return status_; }

private:
    VirtualDevice& dev_;
    bool running_ = true;
    bool cleared_ = false;   // 1F51h = 3 erased the program and no valid one came since
    QByteArray downloaded_;  // the image written to 1F50h:01, not started yet
    QString version_;
    uint32_t softwareId_ = 0;
    uint32_t status_ = 0;
    bool resetRequested_ = false;
};

}  // namespace coscope::sim
