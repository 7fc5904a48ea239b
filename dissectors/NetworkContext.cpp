// SPDX-License-Identifier: GPL-3.0-or-later
#include "dissectors/NetworkContext.h"

#include "core/canopen/CobId.h"
#include "dissectors/Services.h"
#include "dissectors/VendorTable.h"

#include <array>

namespace coscope::dissect {

using canopen::Service;

PdoConfig& NodeState::pdo(bool tpdoDir, int number) {
    auto& v = tpdoDir ? tpdo : rpdo;
    if (static_cast<int>(v.size()) < number) v.resize(static_cast<size_t>(number));
    return v[static_cast<size_t>(number - 1)];
}

const PdoConfig* NodeState::findPdo(bool tpdoDir, int number) const {
    const auto& v = tpdoDir ? tpdo : rpdo;
    return number >= 1 && number <= static_cast<int>(v.size()) ? &v[static_cast<size_t>(number - 1)] : nullptr;
}

NetworkContext::NetworkContext() : template_(std::make_shared<const Bus>()), buses_(1) {}

const NodeState& NetworkContext::node(int bus, int id) const {
    const Bus& b = bus >= 0 && bus < static_cast<int>(buses_.size()) ? buses_[static_cast<size_t>(bus)] : *template_;
    return b.nodes[static_cast<size_t>(id & 0x7F)];
}

// A bus seen for the first time starts from the assigned dictionaries.
void NetworkContext::selectBus(int bus) {
    if (bus >= static_cast<int>(buses_.size())) buses_.resize(static_cast<size_t>(bus) + 1, *template_);
    current_ = static_cast<size_t>(bus);
}

bool NetworkContext::assignDictionary(int node, const QString& nameOrFile, QString* error) {
    if (node < 1 || node > 127) {
        if (error) *error = QStringLiteral("node-ID %1 is outside 1..127").arg(node);
        return false;
    }
    QString name;
    DictionaryPtr d = eds::DictionaryLibrary::shared().loadShared(nameOrFile, &name, error);
    if (!d) return false;
    assignDictionary(node, std::move(d), name, true);
    return true;
}

void NetworkContext::assignDictionary(int node, DictionaryPtr dictionary, const QString& name, bool byUser) {
    auto assign = [&](Bus& bus) {
        NodeState& n = bus.nodes[static_cast<size_t>(node & 0x7F)];
        n.dictionary = dictionary;
        n.dictionaryName = name;
        n.userAssigned = byUser;
        n.vendor = vendorTable(name);
        loadDefaults(bus, node & 0x7F);
    };
    if (byUser) {  // the user's choice holds for the node-ID on every bus, seen or not
        auto t = std::make_shared<Bus>(*template_);
        assign(*t);
        template_ = std::move(t);
        for (Bus& b : buses_) assign(b);
    } else {  // matched by the identity read on the current bus
        assign(buses_[current_]);
    }
}

// PDO parameters from the dictionary: DCF ParameterValue if present, else the default, with
// $NODEID resolved (CiA 306 §4.5.1).
void NetworkContext::loadDefaults(Bus& bus, int node) {
    NodeState& n = bus.nodes[static_cast<size_t>(node)];
    n.rpdo.clear();
    n.tpdo.clear();
    if (n.dictionary) {
        const od::ObjectDictionary& d = *n.dictionary;
        const auto nid = static_cast<uint8_t>(node);
        for (auto it = d.objects().lower_bound(0x1400); it != d.objects().end() && it->first <= 0x1BFF; ++it) {
            const PdoObject po = classifyPdoObject(it->first);
            if (!po.isPdo) continue;
            PdoConfig& cfg = n.pdo(po.tpdo, po.number);
            if (!po.mapping) {
                if (const od::SubObject* s = it->second.sub(1))
                    if (auto v = s->resolvedValue(nid); v && v->toUInt64()) {
                        cfg.cobId = static_cast<uint32_t>(*v->toUInt64());
                        cfg.cobIdKnown = true;
                    }
            } else {
                const od::SubObject* s0 = it->second.sub(0);
                auto cnt = s0 ? s0->resolvedValue(nid) : std::nullopt;
                if (!cnt || !cnt->toUInt64()) continue;
                cfg.count = static_cast<uint8_t>(std::min<uint64_t>(*cnt->toUInt64(), 64));
                cfg.entries.clear();
                for (int i = 1; i <= cfg.count; ++i) {
                    const od::SubObject* s = it->second.sub(static_cast<uint8_t>(i));
                    auto v = s ? s->resolvedValue(nid) : std::nullopt;
                    cfg.entries.push_back(
                        makeMapEntry(v && v->toUInt64() ? static_cast<uint32_t>(*v->toUInt64()) : 0, &d));
                }
                cfg.mappingKnown = true;
            }
        }
    }
    rebuildRoutes(bus);
}

void NetworkContext::rebuildRoutes(Bus& bus) {
    std::fill(bus.routes.begin(), bus.routes.end(), -1);
    for (int node = 1; node < 128; ++node) {
        const NodeState& n = bus.nodes[static_cast<size_t>(node)];
        for (int dir = 0; dir < 2; ++dir) {
            const auto& v = dir ? n.tpdo : n.rpdo;
            for (size_t i = 0; i < v.size(); ++i) {
                const PdoConfig& c = v[i];
                if (!c.valid() || (c.cobId & 0x20000000u)) continue;
                bus.routes[c.canId()] = (node << 12) | (dir << 11) | static_cast<int>(i);
            }
        }
    }
}

void NetworkContext::pdoCobIdChanged(int, bool, int) { rebuildRoutes(); }

const od::ObjectDictionary* NetworkContext::namesFor(int node) const {
    const auto& nodes = buses_[current_].nodes;
    if (node >= 1 && node < 128 && nodes[static_cast<size_t>(node)].dictionary)
        return nodes[static_cast<size_t>(node)].dictionary.get();
    if (!genericNames_) return nullptr;
    if (!generic_) const_cast<NetworkContext*>(this)->generic_ = genericDictionary();
    return generic_.get();
}

DictionaryPtr NetworkContext::genericDictionary() {
    return eds::DictionaryLibrary::shared().loadShared(QStringLiteral("generic-cia402"));
}

namespace {
uint32_t littleEndian(const QByteArray& b) {
    uint32_t v = 0;
    for (int i = 0; i < b.size() && i < 4; ++i) v |= uint32_t(uint8_t(b[i])) << (8 * i);
    return v;
}
}  // namespace

// What a confirmed SDO transfer teaches the context: PDO parameters (CiA 301 §7.5.2.35..38)
// and the identity (1018h, 1008h, 100Ah) used to pick the node's dictionary.
void NetworkContext::applySdoTransfer(int node, const SdoTransferRecord& t) {
    if (t.status != QLatin1String("ok") || node < 1 || node > 127) return;
    NodeState& n = buses_[current_].nodes[static_cast<size_t>(node)];
    const uint32_t v = littleEndian(t.data);
    const PdoObject po = classifyPdoObject(t.index);
    if (po.isPdo) {
        PdoConfig& cfg = n.pdo(po.tpdo, po.number);
        if (!po.mapping && t.sub == 1) {
            cfg.cobId = v;
            cfg.cobIdKnown = true;
            rebuildRoutes();
        } else if (po.mapping && t.sub == 0) {
            cfg.count = static_cast<uint8_t>(std::min<uint32_t>(v, 64));
            cfg.mappingKnown = true;
        } else if (po.mapping && t.sub <= 64) {
            if (static_cast<int>(cfg.entries.size()) < t.sub) cfg.entries.resize(t.sub);
            cfg.entries[t.sub - 1u] = makeMapEntry(v, namesFor(node));
            cfg.mappingKnown = true;
        }
        return;
    }
    if (!identityMatching_ || n.userAssigned) return;
    eds::DeviceIdentity& id = n.identity;
    // The text only for the two string objects: this runs for every confirmed transfer.
    auto text = [&] { return QString::fromLatin1(t.data).section(QChar(0), 0, 0); };
    if (t.index == 0x1000 && t.sub == 0) id.deviceType = v;
    else if (t.index == 0x1018 && t.sub >= 1 && t.sub <= 3)
        (t.sub == 1 ? id.vendorId : t.sub == 2 ? id.productCode : id.revision) = v;
    else if (t.index == 0x1008 && t.sub == 0) id.deviceName = text();
    else if (t.index == 0x100A && t.sub == 0) id.softwareVersion = text();
    else return;
    const auto* entry = eds::DictionaryLibrary::shared().match(id);
    const QString match = entry ? entry->name : QString();
    if (!match.isEmpty() && match != n.dictionaryName) {
        // Keep PDO parameters learned so far: they describe the device better than defaults.
        auto rp = n.rpdo, tp = n.tpdo;
        const bool learned = !rp.empty() || !tp.empty();
        if (DictionaryPtr d = eds::DictionaryLibrary::shared().loadShared(match))
            assignDictionary(node, d, match, false);
        if (learned) {
            n.rpdo = std::move(rp);
            n.tpdo = std::move(tp);
            rebuildRoutes();
        }
    }
}

void NetworkContext::dissect(const CanFrame& frame, Dissection& out, Dissection::Level level) {
    ++frames_;
    if (frame.bus != current_) selectBus(frame.bus);
    out.reset(level);
    Bus& bus = buses_[current_];
    int node = -1;
    Service service = Service::Unknown;
    if (!frame.isError()) {
        const int32_t r = frame.isExtended() ? -1 : bus.routes[frame.id & 0x7FF];
        if (r >= 0) {
            node = r >> 12;
            const bool tp = (r >> 11) & 1;
            out.pdoNumber = (r & 0x7FF) + 1;
            static const Service tps[] = {Service::Tpdo1, Service::Tpdo2, Service::Tpdo3, Service::Tpdo4};
            static const Service rps[] = {Service::Rpdo1, Service::Rpdo2, Service::Rpdo3, Service::Rpdo4};
            service = out.pdoNumber <= 4 ? (tp ? tps : rps)[out.pdoNumber - 1] : Service::Unknown;
            if (service == Service::Unknown) {
                // PDO 5..512: no service name in the contract; decode it as a PDO all the same.
                out.node = node;
                bus.nodes[static_cast<size_t>(node)].seen = true;
                DissectCall c{frame, *this, out, node, frame.data.data(), frame.payloadSize()};
                out.service = tp ? Service::Tpdo4 : Service::Rpdo4;  // for the dissector's direction
                dissectPdo(c);
                out.service = Service::Unknown;
                return;
            }
        } else {
            const canopen::CobIdInfo info = canopen::classifyCobId(frame.id, frame.isExtended());
            service = info.service;
            node = info.node;
            if (const int p = canopen::pdoNumber(service); p >= 0) out.pdoNumber = p + 1;
        }
    }
    out.service = service;
    out.node = node;
    if (node >= 1 && node < 128) bus.nodes[static_cast<size_t>(node)].seen = true;
    DissectCall c{frame, *this, out, node, frame.data.data(), frame.payloadSize()};
    dissectorFor(service)(c);
}

}  // namespace coscope::dissect
