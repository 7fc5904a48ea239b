// SPDX-License-Identifier: GPL-3.0-or-later
#include "eds/StandardDictionary.h"

#include "eds/BundledDictionaries.h"
#include "eds/DictionaryLibrary.h"

#include <spdlog/spdlog.h>

namespace coscope::eds {

namespace {

using od::Access;
using od::DataType;
using od::ObjectType;

od::SubObject var(std::uint8_t sub, const QString& name, DataType type, Access access) {
    od::SubObject s;
    s.sub = sub;
    s.name = name;
    s.dataType = type;
    s.access = access;
    return s;
}

od::Object simple(std::uint16_t index, const QString& name, DataType type, Access access) {
    od::Object o;
    o.index = index;
    o.name = name;
    o.objectType = type == DataType::Domain ? ObjectType::Domain : ObjectType::Var;
    o.dataType = type;
    o.subs.push_back(var(0, name, type, access));
    return o;
}

// ARRAY of `count` entries named "<entry> n" after sub 0 "Highest sub-index supported".
od::Object array(std::uint16_t index, const QString& name, const QString& entry, DataType type, Access access,
                 int count) {
    od::Object o;
    o.index = index;
    o.name = name;
    o.objectType = ObjectType::Array;
    o.dataType = type;
    o.subs.push_back(var(0, QStringLiteral("Highest sub-index supported"), DataType::Unsigned8, Access::ReadOnly));
    for (int i = 1; i <= count; ++i)
        o.subs.push_back(var(static_cast<std::uint8_t>(i), QStringLiteral("%1 %2").arg(entry).arg(i), type, access));
    return o;
}

od::Object record(std::uint16_t index, const QString& name, std::vector<od::SubObject> subs) {
    od::Object o;
    o.index = index;
    o.name = name;
    o.objectType = ObjectType::Record;
    o.subs.push_back(var(0, QStringLiteral("Highest sub-index supported"), DataType::Unsigned8, Access::ReadOnly));
    for (auto& s : subs) o.subs.push_back(std::move(s));
    return o;
}

void addIfMissing(od::ObjectDictionary& d, od::Object o) {
    if (!d.object(o.index)) d.insert(std::move(o));
}

// CiA 301 v4.2 7.5.2: the communication objects 1000h-1029h the generic drive leaves out.
void addCommunicationObjects(od::ObjectDictionary& d) {
    addIfMissing(
        d, simple(0x1002, QStringLiteral("Manufacturer status register"), DataType::Unsigned32, Access::ReadOnly));
    addIfMissing(d,
                 simple(0x1012, QStringLiteral("COB-ID time stamp object"), DataType::Unsigned32, Access::ReadWrite));
    addIfMissing(d,
                 simple(0x1013, QStringLiteral("High resolution time stamp"), DataType::Unsigned32, Access::ReadWrite));
    addIfMissing(d, record(0x1020, QStringLiteral("Verify configuration"),
                           {var(1, QStringLiteral("Configuration date"), DataType::Unsigned32, Access::ReadWrite),
                            var(2, QStringLiteral("Configuration time"), DataType::Unsigned32, Access::ReadWrite)}));
    addIfMissing(d, simple(0x1021, QStringLiteral("Store EDS"), DataType::Domain, Access::ReadOnly));
    addIfMissing(d, simple(0x1022, QStringLiteral("Store format"), DataType::Unsigned8, Access::ReadOnly));
    const auto osRecord = [](std::uint16_t index, const QString& name) {
        return record(index, name,
                      {var(1, QStringLiteral("Command"), DataType::OctetString, Access::ReadWrite),
                       var(2, QStringLiteral("Status"), DataType::Unsigned8, Access::ReadOnly),
                       var(3, QStringLiteral("Reply"), DataType::OctetString, Access::ReadOnly)});
    };
    addIfMissing(d, osRecord(0x1023, QStringLiteral("OS command")));
    addIfMissing(d, simple(0x1024, QStringLiteral("OS command mode"), DataType::Unsigned8, Access::WriteOnly));
    addIfMissing(d, osRecord(0x1025, QStringLiteral("OS debugger interface")));
    addIfMissing(d, record(0x1026, QStringLiteral("OS prompt"),
                           {var(1, QStringLiteral("StdIn"), DataType::Unsigned8, Access::WriteOnly),
                            var(2, QStringLiteral("StdOut"), DataType::Unsigned8, Access::ReadOnly),
                            var(3, QStringLiteral("StdErr"), DataType::Unsigned8, Access::ReadOnly)}));
    addIfMissing(d, array(0x1027, QStringLiteral("Module list"), QStringLiteral("Module"), DataType::Unsigned16,
                          Access::ReadOnly, 0xFE));
    addIfMissing(d, array(0x1028, QStringLiteral("Emergency consumer object"), QStringLiteral("Emergency consumer"),
                          DataType::Unsigned32, Access::ReadWrite, 0x7F));
}

// CiA 301 v4.2 7.5.2.33/34: SDO server parameter 1200h-127Fh, SDO client parameter 1280h-12FFh.
void addSdoParameters(od::ObjectDictionary& d) {
    for (int n = 0; n < 128; ++n) {
        addIfMissing(
            d, record(static_cast<std::uint16_t>(0x1200 + n), QStringLiteral("SDO server parameter %1").arg(n + 1),
                      {var(1, QStringLiteral("COB-ID client to server (rx)"), DataType::Unsigned32, Access::ReadWrite),
                       var(2, QStringLiteral("COB-ID server to client (tx)"), DataType::Unsigned32, Access::ReadWrite),
                       var(3, QStringLiteral("Node-ID of the SDO client"), DataType::Unsigned8, Access::ReadWrite)}));
        addIfMissing(
            d, record(static_cast<std::uint16_t>(0x1280 + n), QStringLiteral("SDO client parameter %1").arg(n + 1),
                      {var(1, QStringLiteral("COB-ID client to server (tx)"), DataType::Unsigned32, Access::ReadWrite),
                       var(2, QStringLiteral("COB-ID server to client (rx)"), DataType::Unsigned32, Access::ReadWrite),
                       var(3, QStringLiteral("Node-ID of the SDO server"), DataType::Unsigned8, Access::ReadWrite)}));
    }
}

// CiA 301 v4.2 7.5.2.35-38: RPDO/TPDO communication (sub 1-5, TPDO also 6) and mapping
// parameters (sub 0 = number of mapped objects, 1-40h = mapped objects) for PDOs 1-512.
void addPdoParameters(od::ObjectDictionary& d) {
    for (int dir = 0; dir < 2; ++dir) {
        const bool tpdo = dir == 1;
        const QString kind = tpdo ? QStringLiteral("TPDO") : QStringLiteral("RPDO");
        const std::uint16_t commBase = tpdo ? 0x1800 : 0x1400;
        for (int n = 0; n < 512; ++n) {
            std::vector<od::SubObject> comm = {
                var(1, QStringLiteral("COB-ID used by %1").arg(kind), DataType::Unsigned32, Access::ReadWrite),
                var(2, QStringLiteral("Transmission type"), DataType::Unsigned8, Access::ReadWrite),
                var(3, QStringLiteral("Inhibit time"), DataType::Unsigned16, Access::ReadWrite),
                var(4, QStringLiteral("Compatibility entry"), DataType::Unsigned8, Access::ReadWrite),
                var(5, QStringLiteral("Event timer"), DataType::Unsigned16, Access::ReadWrite)};
            if (tpdo)
                comm.push_back(var(6, QStringLiteral("SYNC start value"), DataType::Unsigned8, Access::ReadWrite));
            const auto commIndex = static_cast<std::uint16_t>(commBase + n);
            const auto mapIndex = static_cast<std::uint16_t>(commBase + 0x200 + n);
            addIfMissing(d, record(commIndex, QStringLiteral("%1%2 communication parameter").arg(kind).arg(n + 1),
                                   std::move(comm)));
            od::Object map;
            if (const od::Object* have = d.object(mapIndex)) map = *have;
            else {
                map.index = mapIndex;
                map.name = QStringLiteral("%1%2 mapping parameter").arg(kind).arg(n + 1);
                map.objectType = ObjectType::Record;
                map.subs.push_back(
                    var(0, QStringLiteral("Number of mapped objects"), DataType::Unsigned8, Access::ReadWrite));
            }
            // Mapping entries up to 40h (64 one-bit objects fill a classic CAN PDO).
            for (int i = 1; i <= 0x40; ++i)
                if (!map.sub(static_cast<std::uint8_t>(i)))
                    map.subs.push_back(var(static_cast<std::uint8_t>(i), QStringLiteral("Mapped object %1").arg(i),
                                           DataType::Unsigned32, Access::ReadWrite));
            d.insert(std::move(map));
        }
    }
}

od::ObjectDictionary build() {
    ReadResult r = DictionaryLibrary::loadFile(bundledDictionaryPath(QStringLiteral("generic-cia402")));
    if (!r.usable) spdlog::error("standard dictionary: the bundled generic-cia402 dictionary is not readable");
    od::ObjectDictionary d = std::move(r.dictionary);
    d.fileInfo.description = QStringLiteral("CiA 301 / CiA 402 standard objects");
    addCommunicationObjects(d);
    addSdoParameters(d);
    addPdoParameters(d);
    // The generic drive's limits are its own, not the standard's.
    for (const auto& [index, object] : d.objects())
        for (const od::SubObject& s : object.subs)
            if (od::SubObject* e = d.entryForEdit(index, s.sub)) e->lowLimit.clear(), e->highLimit.clear();
    return d;
}

}  // namespace

const od::ObjectDictionary& standardDictionary() {
    static const od::ObjectDictionary dictionary = build();
    return dictionary;
}

const od::SubObject* entryWithStandard(const od::ObjectDictionary* device, std::uint16_t index, std::uint8_t sub,
                                       const od::ObjectDictionary** names) {
    if (device)
        if (const od::SubObject* e = device->entry(index, sub)) {
            if (names) *names = device;
            return e;
        }
    const od::ObjectDictionary& standard = standardDictionary();
    const od::SubObject* e = standard.entry(index, sub);
    if (names) *names = e ? &standard : nullptr;
    return e;
}

}  // namespace coscope::eds
