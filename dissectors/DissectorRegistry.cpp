// SPDX-License-Identifier: GPL-3.0-or-later
#include "dissectors/Services.h"

#include <array>

namespace coscope::dissect {

using canopen::Service;

Dissector dissectorFor(Service s) {
    static const auto table = [] {
        std::array<Dissector, 32> t{};
        t.fill(&dissectUnknown);
        auto set = [&t](Service sv, Dissector d) { t[static_cast<size_t>(sv)] = d; };
        set(Service::Nmt, &dissectNmt);
        set(Service::Sync, &dissectSync);
        set(Service::Time, &dissectTime);
        set(Service::Emcy, &dissectEmcy);
        for (Service p : {Service::Tpdo1, Service::Tpdo2, Service::Tpdo3, Service::Tpdo4, Service::Rpdo1,
                          Service::Rpdo2, Service::Rpdo3, Service::Rpdo4})
            set(p, &dissectPdo);
        set(Service::SdoRequest, &dissectSdo);
        set(Service::SdoResponse, &dissectSdo);
        set(Service::NmtErrorControl, &dissectErrorControl);
        set(Service::LssRequest, &dissectLss);
        set(Service::LssResponse, &dissectLss);
        return t;
    }();
    const auto i = static_cast<size_t>(s);
    return i < table.size() ? table[i] : &dissectUnknown;
}

void dissectUnknown(DissectCall& c) {
    if (c.frame.isError()) return dissectCanError(c);
    if (!c.out.wantText()) return;
    c.out.summary =
        c.frame.isExtended() ? QStringLiteral("not CANopen (29-bit identifier)") : QStringLiteral("unknown COB-ID");
    if (c.out.wantTree()) c.out.item(0, QStringLiteral("Data"), hexBytes(c.data, c.len, true), 0, c.len);
}

}  // namespace coscope::dissect
