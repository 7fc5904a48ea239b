// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/sim/ProgramFlash.h"

#include "core/canopen/SdoAbort.h"
#include "core/od/ObjectDictionary.h"
#include "core/sim/ProgramImage.h"
#include "core/sim/VirtualDevice.h"

namespace coscope::sim {

namespace abortcode = canopen::sdoabort;

namespace {
// 1F51h program control values (CiA 302-3 §4).
enum Control : uint8_t { Stop = 0, Start = 1, Reset = 2, Clear = 3 };
// 1F57h flash status identification error codes, bits 1-7 (CiA 302-3 §4).
constexpr uint32_t kNoValidProgram = 1u << 1;

void addArray(od::ObjectDictionary& dict, uint16_t index, const QString& name, od::DataType type, od::Access access) {
    if (dict.object(index)) return;
    od::Object o;
    o.index = index;
    o.name = name;
    o.objectType = od::ObjectType::Array;
    o.dataType = type;
    od::SubObject count;
    count.index = index;
    count.sub = 0;
    count.name = QStringLiteral("Highest sub-index supported");
    count.dataType = od::DataType::Unsigned8;
    count.access = od::Access::Const;
    count.defaultValue = QStringLiteral("1");
    od::SubObject program = count;
    program.sub = 1;
    program.name = QStringLiteral("Program number 1");
    program.dataType = type;
    program.access = access;
    program.defaultValue = QString();
    o.subs = {count, program};
    dict.insert(std::move(o));
}
}  // namespace

ProgramFlash::ProgramFlash(VirtualDevice& device) : dev_(device) {}

void ProgramFlash::addObjects(od::ObjectDictionary& dict) {
    addArray(dict, 0x1F50, QStringLiteral("Program data"), od::DataType::Domain, od::Access::WriteOnly);
    addArray(dict, 0x1F51, QStringLiteral("Program control"), od::DataType::Unsigned8, od::Access::ReadWrite);
    addArray(dict, 0x1F56, QStringLiteral("Program software identification"), od::DataType::Unsigned32,
             od::Access::ReadOnly);
    addArray(dict, 0x1F57, QStringLiteral("Flash status identification"), od::DataType::Unsigned32,
             od::Access::ReadOnly);
    if (const od::SubObject* v = dict.entry(0x100A, 0)) {
        version_ = v->defaultValue.trimmed();
    } else {
        od::Object o;
        o.index = 0x100A;
        o.name = QStringLiteral("Manufacturer software version");
        o.objectType = od::ObjectType::Var;
        o.dataType = od::DataType::VisibleString;
        od::SubObject s;
        s.index = 0x100A;
        s.name = o.name;
        s.dataType = od::DataType::VisibleString;
        s.access = od::Access::ReadOnly;
        o.subs.push_back(s);
        dict.insert(std::move(o));
    }
    if (version_.isEmpty()) version_ = QStringLiteral("1.0");
    softwareId_ = crc32(version_.toLatin1());
}

void ProgramFlash::publish() {
    if (auto* v = dev_.valueSlot(0x100A, 0)) *v = od::Value::text(version_);
    if (auto* v = dev_.valueSlot(0x1F51, 1)) *v = od::Value::unsignedInt(running_ ? 1 : 0);
    if (auto* v = dev_.valueSlot(0x1F56, 1)) *v = od::Value::unsignedInt(softwareId_);
    if (auto* v = dev_.valueSlot(0x1F57, 1)) *v = od::Value::unsignedInt(status_);
}

bool ProgramFlash::takeResetRequest() {
    const bool r = resetRequested_;
    resetRequested_ = false;
    return r;
}

uint32_t ProgramFlash::write(uint16_t index, uint8_t sub, const QByteArray& bytes) {
    if (sub != 1) return abortcode::NoSubIndex;
    if (index == 0x1F50) {
        // Program data goes in while the program is stopped (CiA 302-3).
        if (running_) return abortcode::DeviceState;
        downloaded_ = bytes;
        status_ = 0;
        publish();
        return 0;
    }
    const uint8_t control = bytes.isEmpty() ? 0xFF : static_cast<uint8_t>(bytes[0]);
    switch (control) {
    case Stop: running_ = false; break;
    case Clear:
        if (running_) return abortcode::DeviceState;
        downloaded_.clear();
        cleared_ = true;
        status_ = kNoValidProgram;
        break;
    case Start:
    case Reset: {
        if (running_ && control == Start) break;  // already running: nothing to do
        if (!downloaded_.isEmpty()) {
            ProgramImageHeader header;
            if (const int error = checkProgramImage(downloaded_, &header)) {
                status_ = uint32_t(error) << 1;
                publish();
                return abortcode::CannotStore;
            }
            if (!header.version.isEmpty()) version_ = header.version;
            softwareId_ = header.crc;
            downloaded_.clear();
            cleared_ = false;
        } else if (cleared_) {
            status_ = kNoValidProgram;
            publish();
            return abortcode::DeviceState;
        }
        status_ = 0;
        running_ = true;
        resetRequested_ = true;
        break;
    }
    default: return abortcode::InvalidValue;
    }
    publish();
    return 0;
}

}  // namespace coscope::sim
