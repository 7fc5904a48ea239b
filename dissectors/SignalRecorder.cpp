// SPDX-License-Identifier: GPL-3.0-or-later
#include "dissectors/SignalRecorder.h"

#include "core/canopen/CobId.h"

#include <QFileInfo>

#include <algorithm>
#include <tuple>

#include <spdlog/spdlog.h>

namespace coscope::dissect {

namespace {
QString objectText(uint16_t index, uint8_t sub) {
    return QStringLiteral("%1:%2").arg(index, 4, 16, QLatin1Char('0')).arg(sub, 2, 16, QLatin1Char('0')).toUpper();
}
QString pdoText(bool tpdo, int number) {
    return (tpdo ? QStringLiteral("TPDO") : QStringLiteral("RPDO")) + QString::number(number);
}
// The entry's unit, else the bundled sidecar's (dictionaries loaded without it).
std::pair<QString, double> unitOf(const PdoMapEntry& e, const QString& dictionary) {
    if (!e.unit.isEmpty()) return {e.unit, e.factor};
    if (const auto u = sidecarUnit(dictionary, e.index, e.sub)) return {u->unit, u->factor};
    return {QString(), e.factor};
}
uint64_t parameterKey(int bus, int node, uint16_t index, uint8_t sub) {
    return uint64_t(uint8_t(bus)) << 32 | uint64_t(uint8_t(node)) << 24 | uint64_t(index) << 8 | sub;
}
}  // namespace

SignalRecorder::SignalRecorder(size_t capacityPerSignal) : capacity_(capacityPerSignal) {}
SignalRecorder::~SignalRecorder() = default;

void SignalRecorder::setDictionaries(const std::map<int, QString>& names) {
    std::lock_guard lock(mutex_);
    if (names == pendingNames_) return;
    pendingNames_ = names;
    namesChanged_ = true;
}

void SignalRecorder::setRawSignals(const std::vector<RawSignal>& raw) {
    std::lock_guard lock(mutex_);
    pendingRaw_ = raw;
    rawChanged_ = true;
}

SignalRecorder::Slot& SignalRecorder::rawSlot(int bus, size_t number) {
    const RawSignal& r = raw_[number];
    SignalKey key;
    key.bus = static_cast<uint8_t>(bus);
    key.raw = static_cast<uint16_t>(number + 1);
    const auto it = slots_.find(key.packed());
    if (it != slots_.end()) return *it->second;
    auto slot = std::make_unique<Slot>();
    SignalInfo& i = slot->info;
    i.key = key;
    i.name = r.name;
    i.object = QStringLiteral("%1|%2@%3%4")
                   .arg(r.startBit)
                   .arg(r.length)
                   .arg(r.order == RawSignal::Order::Intel ? 1 : 0)
                   .arg(r.type == RawSignal::Type::Unsigned ? QStringLiteral("u")
                        : r.type == RawSignal::Type::Signed ? QStringLiteral("s")
                                                            : QStringLiteral("f"));
    i.pdo = QStringLiteral("COB-ID %1h").arg(QString::number(r.cobId, 16).toUpper());
    i.rawUnit = r.unit;
    i.rawFactor = r.factor;
    i.scale = r.scale();
    i.cobId = r.cobId;
    slot->buffer = std::make_shared<SignalBuffer>(capacity_);
    Slot& ref = *slot;
    {
        std::lock_guard lock(mutex_);
        slots_.emplace(key.packed(), std::move(slot));
    }
    revision_.fetch_add(1, std::memory_order_acq_rel);
    return ref;
}

void SignalRecorder::recordRaw(const CanFrame& f, FrameNo n) {
    for (size_t k = 0; k < raw_.size(); ++k) {
        if (!raw_[k].matches(f)) continue;
        const std::optional<double> v = raw_[k].rawValue(f.data.data(), f.payloadSize());
        if (!v) continue;
        Slot& s = rawSlot(f.bus, k);
        if (s.pending.empty()) dirty_.push_back(&s);
        s.pending.push_back({f.timestampNs, *v, n});
    }
}

void SignalRecorder::applyDictionaries() {
    std::map<int, QString> names;
    {
        std::lock_guard lock(mutex_);
        if (rawChanged_) {
            rawChanged_ = false;
            raw_ = pendingRaw_;
        }
        if (!namesChanged_) return;
        namesChanged_ = false;
        names = pendingNames_;
    }
    for (const auto& [node, name] : names) {
        if (node < 1 || node > 127 || name.isEmpty() || appliedNames_[node] == name) continue;
        appliedNames_[node] = name;
        // Already decoding with it (matched by identity): keep the mappings learned so far.
        if (context_.node(node).dictionaryName == QFileInfo(name).completeBaseName() ||
            context_.node(node).dictionaryName == name)
            continue;
        QString error;
        if (!context_.assignDictionary(node, name, &error))
            spdlog::warn("plot: node {}: {}", node, error.toStdString());
    }
}

SignalScale SignalRecorder::scaleFor(int bus, int node, const QString& dictionary, const QString& unit,
                                     double factor) const {
    return engineeringScale(dictionary, unit, factor, [&](uint16_t index, uint8_t sub) -> std::optional<double> {
        const auto it = parameters_.find(parameterKey(bus, node, index, sub));
        if (it == parameters_.end()) return std::nullopt;
        return it->second;
    });
}

SignalRecorder::Slot& SignalRecorder::slotFor(int bus, int node, const PdoMapEntry& e, bool tpdo, int pdoNumber) {
    const SignalKey key{static_cast<uint8_t>(bus), static_cast<uint8_t>(node), e.index, e.sub, -1};
    const auto it = slots_.find(key.packed());
    if (it != slots_.end()) return *it->second;
    auto slot = std::make_unique<Slot>();
    SignalInfo& i = slot->info;
    i.key = key;
    i.name = e.name;
    i.object = objectText(e.index, e.sub);
    i.pdo = pdoText(tpdo, pdoNumber);  // only for a new slot: no string per frame
    i.dictionary = context_.node(bus, node).dictionaryName;
    std::tie(i.rawUnit, i.rawFactor) = unitOf(e, i.dictionary);
    i.scale = scaleFor(bus, node, i.dictionary, i.rawUnit, i.rawFactor);
    slot->buffer = std::make_shared<SignalBuffer>(capacity_);
    Slot& ref = *slot;
    {
        std::lock_guard lock(mutex_);
        slots_.emplace(key.packed(), std::move(slot));
    }
    revision_.fetch_add(1, std::memory_order_acq_rel);
    return ref;
}

// The catalogue lists what the nodes' PDO mappings carry, before their first frame too, and
// follows a node's dictionary (names, units) when it becomes known.
void SignalRecorder::ensureCatalogue() {
    for (int bus = 0; bus < context_.busCount(); ++bus) {
        for (int node = 1; node < 128; ++node) {
            const NodeState& ns = context_.node(bus, node);
            if (!ns.seen) continue;
            for (int dir = 0; dir < 2; ++dir) {
                const auto& pdos = dir ? ns.tpdo : ns.rpdo;
                for (size_t p = 0; p < pdos.size(); ++p) {
                    const PdoConfig& cfg = pdos[p];
                    if (!cfg.valid() || !cfg.mappingKnown) continue;
                    for (int k = 0; k < cfg.count && k < static_cast<int>(cfg.entries.size()); ++k) {
                        const PdoMapEntry& e = cfg.entries[static_cast<size_t>(k)];
                        if (e.dummy || e.bits == 0) continue;
                        Slot& s = slotFor(bus, node, e, dir == 1, static_cast<int>(p) + 1);
                        const auto [unit, factor] = unitOf(e, ns.dictionaryName);
                        if (s.info.dictionary == ns.dictionaryName && s.info.name == e.name && s.info.rawUnit == unit &&
                            s.info.rawFactor == factor)
                            continue;
                        std::lock_guard lock(mutex_);
                        s.info.dictionary = ns.dictionaryName;
                        s.info.name = e.name;
                        s.info.rawUnit = unit;
                        s.info.rawFactor = factor;
                        s.info.scale = scaleFor(bus, node, ns.dictionaryName, unit, factor);
                        revision_.fetch_add(1, std::memory_order_acq_rel);
                    }
                }
            }
        }
    }
}

// Vendor scaling parameters written or read by SDO in the trace (Delta 6093h:01/02).
void SignalRecorder::learnParameter(int bus, int node, const SdoTransferRecord& t) {
    if (t.status != QLatin1String("ok") || node < 1 || node > 127 || t.data.isEmpty() || t.data.size() > 4) return;
    const std::optional<RevolutionRule> rule = revolutionRule(context_.node(bus, node).dictionaryName);
    if (!rule || !rule->dependsOn(t.index, t.sub)) return;
    uint32_t v = 0;
    for (int i = 0; i < t.data.size(); ++i) v |= uint32_t(uint8_t(t.data[i])) << (8 * i);
    parameters_[parameterKey(bus, node, t.index, t.sub)] = double(v);
    std::lock_guard lock(mutex_);
    for (auto& [packed, slot] : slots_) {
        if (slot->info.key.bus != bus || slot->info.key.node != node) continue;
        slot->info.scale = scaleFor(bus, node, slot->info.dictionary, slot->info.rawUnit, slot->info.rawFactor);
    }
    revision_.fetch_add(1, std::memory_order_acq_rel);
}

namespace {
uint64_t modeKey(int bus, int node, uint16_t index) {
    return uint64_t(bus) << 32 | uint64_t(node) << 8 | uint64_t((index - 0x6000) / 0x800);
}
}  // namespace

void SignalRecorder::learnMode(int bus, int node, uint16_t index, uint8_t sub, uint64_t raw) {
    // 6060h/6061h sub 0 of an axis (CiA 402-1 §5: + n x 800h).
    if (sub != 0 || index < 0x6000 || index > 0x67FF || (index & 0x7FE) != 0x060) return;
    const uint64_t key = modeKey(bus, node, index);
    const auto mode = static_cast<int8_t>(raw);
    std::lock_guard lock(mutex_);
    const auto it = modes_.find(key);
    if (it != modes_.end() && it->second == mode) return;
    modes_[key] = mode;
    revision_.fetch_add(1, std::memory_order_acq_rel);  // the bit names follow
}

std::optional<int8_t> SignalRecorder::modeOf(const SignalKey& word) const {
    if (word.index < 0x6000 || word.index > 0x67FF) return std::nullopt;
    const auto it = modes_.find(modeKey(word.bus, word.node, word.index));
    return it == modes_.end() ? std::nullopt : std::optional<int8_t>(it->second);
}

// A PDO's first frame: true once per bus and COB-ID (a flat table for 11-bit identifiers, no
// tree lookup per PDO frame).
bool SignalRecorder::notePdoSeen(int bus, uint32_t id, bool extended) {
    if (extended) return pdoKeysExtended_.insert(uint64_t(bus) << 32 | id).second;
    if (static_cast<size_t>(bus) >= pdoSeenStd_.size()) pdoSeenStd_.resize(static_cast<size_t>(bus) + 1);
    auto& seen = pdoSeenStd_[static_cast<size_t>(bus)];
    if (seen.test(id & 0x7FF)) return false;
    seen.set(id & 0x7FF);
    return true;
}

void SignalRecorder::consume(const TraceStore& store, FrameNo first, size_t count) {
    applyDictionaries();
    if (!count) return;
    if (!haveOrigin_.load(std::memory_order_acquire)) {
        originNs_.store(store.record(first).timestampNs, std::memory_order_release);
        haveOrigin_.store(true, std::memory_order_release);
    }
    for (size_t i = 0; i < count; ++i) {
        const auto n = static_cast<FrameNo>(first + i);
        const CanFrame f = store.frame(n);
        context_.dissect(f, scratch_, Dissection::Level::Stats);
        if (scratch_.hasTransfer) {
            const SdoTransferRecord& t = scratch_.transfer;
            const int node = t.node >= 0 ? t.node : scratch_.node;
            learnParameter(f.bus, node, t);
            if (t.status == QLatin1String("ok") && t.data.size() == 1)
                learnMode(f.bus, node, t.index, t.sub, uint8_t(t.data[0]));
        }
        if (!raw_.empty()) recordRaw(f, n);
        const int pdoIndex = canopen::pdoNumber(scratch_.service);
        if (pdoIndex < 0 || f.isRemote() || scratch_.node < 1 || scratch_.node > 127) continue;
        const bool tpdo = canopen::isTpdo(scratch_.service);
        if (notePdoSeen(f.bus, f.id, f.isExtended())) {
            std::lock_guard lock(mutex_);
            pdos_.push_back({f.bus, f.id, scratch_.node, pdoText(tpdo, scratch_.pdoNumber)});
        }
        const PdoConfig* cfg = context_.node(scratch_.node).findPdo(tpdo, scratch_.pdoNumber);
        if (!cfg || !cfg->mappingKnown) continue;
        int bit = 0;
        for (int k = 0; k < cfg->count && k < static_cast<int>(cfg->entries.size()); ++k) {
            const PdoMapEntry& e = cfg->entries[static_cast<size_t>(k)];
            const int at = bit;
            bit += e.bits;
            if (e.dummy) continue;
            const std::optional<double> v = pdoValue(e, f.data.data(), f.payloadSize(), at);
            if (!v) continue;
            if ((e.index & 0x7FE) == 0x060)
                learnMode(f.bus, scratch_.node, e.index, e.sub, static_cast<uint64_t>(static_cast<int64_t>(*v)));
            Slot& s = slotFor(f.bus, scratch_.node, e, tpdo, scratch_.pdoNumber);
            if (s.pending.empty()) dirty_.push_back(&s);
            s.pending.push_back({f.timestampNs, *v, n});
        }
    }
    for (Slot* s : dirty_) {
        s->buffer->append(s->pending);
        s->pending.clear();
    }
    dirty_.clear();
    ensureCatalogue();
    latestNs_.store(store.record(static_cast<FrameNo>(first + count - 1)).timestampNs, std::memory_order_release);
    frames_.fetch_add(count, std::memory_order_acq_rel);
}

std::vector<SignalRecorder::PdoSeen> SignalRecorder::pdosSeen() const {
    std::vector<PdoSeen> out;
    {
        std::lock_guard lock(mutex_);
        out = pdos_;
    }
    std::sort(out.begin(), out.end());
    return out;
}

std::vector<SignalInfo> SignalRecorder::catalog() const {
    std::vector<SignalInfo> out;
    std::lock_guard lock(mutex_);
    out.reserve(slots_.size());
    for (const auto& [packed, slot] : slots_) {
        const SignalInfo& w = slot->info;
        out.push_back(w);
        if (!hasDigitalBits(w.key.index, w.key.sub)) continue;
        for (int b = 0; b < 16; ++b) {
            SignalInfo bi = w;
            bi.key.bit = static_cast<int8_t>(b);
            bi.name = QStringLiteral("%1: %2").arg(w.name, digitalBitName(w.key.index, b, modeOf(w.key)));
            bi.object = QStringLiteral("%1 bit %2").arg(w.object).arg(b);
            bi.rawUnit.clear();
            bi.rawFactor = 1.0;
            bi.scale = SignalScale{};
            bi.digital = true;
            out.push_back(std::move(bi));
        }
    }
    std::sort(out.begin(), out.end(), [](const SignalInfo& a, const SignalInfo& b) { return a.key < b.key; });
    return out;
}

std::optional<SignalInfo> SignalRecorder::info(const SignalKey& key) const {
    for (SignalInfo& i : catalog())
        if (i.key == key) return std::move(i);
    return std::nullopt;
}

std::shared_ptr<const SignalBuffer> SignalRecorder::buffer(const SignalKey& key) const {
    std::lock_guard lock(mutex_);
    const auto it = slots_.find(key.word().packed());
    return it == slots_.end() ? nullptr : it->second->buffer;
}

std::optional<int64_t> SignalRecorder::originNs() const {
    if (!haveOrigin_.load(std::memory_order_acquire)) return std::nullopt;
    return originNs_.load(std::memory_order_acquire);
}

}  // namespace coscope::dissect
