// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/canopen/DeviceConfiguration.h"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <map>

namespace coscope::canopen {

struct DeviceConfiguration::Run {
    bool isRead = true;
    uint8_t node = 0;
    int timeoutMs = 0;
    size_t next = 0;
    // read
    std::vector<std::pair<uint16_t, uint8_t>> entries;
    ConfigReadResult readResult;
    ReadDone readDone;
    // apply
    std::vector<PlannedWrite> writes;
    std::vector<ConfigEntryResult> applied;
    ApplyDone applyDone;
    Progress progress;
    bool cancelled = false;

    int total() const { return static_cast<int>(isRead ? entries.size() : writes.size()); }
};

DeviceConfiguration::DeviceConfiguration(SdoClient& sdo, QObject* parent) : QObject(parent), sdo_(sdo) {}

bool DeviceConfiguration::isCommandObject(uint16_t index) {
    if (index == 0x1010 || index == 0x1011 || index == 0x1F51) return true;
    // CiA 402-1 §5: axis n uses the profile area + n x 800h (up to 8 axes).
    return index >= 0x6000 && index < 0xA000 && (index - 0x6000) % 0x800 == 0x40;
}

QString DeviceConfiguration::edsText(od::DataType type, const od::Value& value) {
    switch (od::typeClass(type)) {
    case od::TypeClass::Boolean: return value.toUInt64().value_or(0) ? QStringLiteral("1") : QStringLiteral("0");
    case od::TypeClass::Unsigned: {
        od::FormatOptions hex;
        hex.hex = true;
        return value.format(type, hex);
    }
    case od::TypeClass::Signed:
    case od::TypeClass::Real: return value.format(type);
    case od::TypeClass::VisibleString:
    case od::TypeClass::UnicodeString: return value.toText();
    case od::TypeClass::OctetString:
    case od::TypeClass::Domain: return QString::fromLatin1(value.toBytes().toHex().toUpper());
    case od::TypeClass::Time: return QString::number(value.toUInt64().value_or(0));
    }
    return value.format(type);
}

od::ValueResult DeviceConfiguration::decodeUpload(od::DataType type, const QByteArray& data, QByteArray* trimmed) {
    QByteArray bytes = data;
    const int size = od::byteSize(type);
    if (size > 0 && bytes.size() > size) bytes.truncate(size);
    if (trimmed) *trimmed = bytes;
    return od::Value::decode(type, bytes);
}

std::vector<std::pair<uint16_t, uint8_t>> DeviceConfiguration::readableEntries(const od::ObjectDictionary& dictionary,
                                                                               const ConfigReadOptions& options) {
    std::vector<std::pair<uint16_t, uint8_t>> out;
    for (const auto& [index, obj] : dictionary.objects()) {
        if (obj.objectType == od::ObjectType::DefType || obj.objectType == od::ObjectType::DefStruct ||
            obj.objectType == od::ObjectType::Null)
            continue;
        for (const od::SubObject& s : obj.subs) {
            if (!od::isReadable(s.access)) continue;
            if (!options.includeDomains && od::typeClass(s.dataType) == od::TypeClass::Domain) continue;
            out.emplace_back(index, s.sub);
        }
    }
    return out;
}

void DeviceConfiguration::read(uint8_t node, const od::ObjectDictionary& dictionary, Progress progress, ReadDone done,
                               ConfigReadOptions options) {
    read(node, dictionary, readableEntries(dictionary, options), std::move(progress), std::move(done), options);
}

void DeviceConfiguration::read(uint8_t node, const od::ObjectDictionary& dictionary,
                               std::vector<std::pair<uint16_t, uint8_t>> entries, Progress progress, ReadDone done,
                               ConfigReadOptions options) {
    auto run = std::make_shared<Run>();
    run->isRead = true;
    run->node = node;
    run->timeoutMs = options.timeoutMs;
    run->entries = std::move(entries);
    run->readResult.node = node;
    run->readResult.values = dictionary;
    run->readResult.values.setNodeId(node);
    run->progress = std::move(progress);
    run->readDone = std::move(done);
    running_ = true;
    cancelRequested_ = false;
    step(run);
}

ApplyPlan DeviceConfiguration::plan(uint8_t node, const od::ObjectDictionary& dcf, const od::ObjectDictionary* current,
                                    ApplyScope scope) {
    ApplyPlan p;
    p.node = node;
    for (const auto& entry : dcf.objects()) {
        // Not a structured binding: clang 14 cannot capture one in the lambda below.
        const uint16_t index = entry.first;
        const auto& obj = entry.second;
        for (const od::SubObject& s : obj.subs) {
            if (s.parameterValue.isEmpty()) continue;  // no value for this entry in the DCF
            const QString name = dcf.displayName(index, s.sub);
            auto skip = [&](const QString& why) { p.skipped.push_back({index, s.sub, name, why}); };
            if (!od::isWritable(s.access)) {
                skip(QStringLiteral("%1 (not writable)").arg(od::accessName(s.access)));
                continue;
            }
            if (isCommandObject(index)) {
                skip(QStringLiteral("command object, not configuration"));
                continue;
            }
            QString error;
            const auto value = s.interpret(s.parameterValue, node, &error);
            if (!value) {
                skip(QStringLiteral("ParameterValue '%1' unreadable: %2").arg(s.parameterValue, error));
                continue;
            }
            QString encError;
            const QByteArray data = value->encode(s.dataType, &encError);
            if (!encError.isEmpty()) {
                skip(QStringLiteral("cannot encode '%1': %2").arg(s.parameterValue, encError));
                continue;
            }
            PlannedWrite w;
            w.index = index;
            w.sub = s.sub;
            w.name = name;
            w.type = s.dataType;
            w.value = *value;
            w.data = data;
            w.valueText = od::typeClass(s.dataType) == od::TypeClass::Unsigned
                              ? edsText(s.dataType, *value)
                              : value->format(s.dataType, od::FormatOptions{false, {}, 1.0, true});
            if (current) {
                if (const od::SubObject* c = current->entry(index, s.sub); c && !c->parameterValue.isEmpty()) {
                    const auto now = c->interpret(c->parameterValue, node);
                    if (now) {
                        w.currentText = od::typeClass(s.dataType) == od::TypeClass::Unsigned
                                            ? edsText(s.dataType, *now)
                                            : now->format(s.dataType, od::FormatOptions{false, {}, 1.0, true});
                        if (scope == ApplyScope::OnlyDifferent && now->encode(s.dataType) == data) {
                            skip(QStringLiteral("unchanged (%1)").arg(w.currentText));
                            continue;
                        }
                    }
                }
            }
            p.writes.push_back(std::move(w));
        }
    }
    orderPdoWrites(p, dcf, current);
    return p;
}

// CiA 301 7.5.2.35-38: a PDO's COB-ID may change and its mapping may be written only while the
// PDO is invalid (COB-ID bit 31), a mapping with sub 0 = 0 first and the count last. The writes
// of each PDO that changes are put in that order, framed by "invalid" and the final COB-ID.
void DeviceConfiguration::orderPdoWrites(ApplyPlan& p, const od::ObjectDictionary& dcf,
                                         const od::ObjectDictionary* current) {
    auto isPdo = [](uint16_t i) { return (i >= 0x1400 && i <= 0x17FF) || (i >= 0x1800 && i <= 0x1BFF); };
    auto commOf = [](uint16_t i) {
        return static_cast<uint16_t>((i >= 0x1600 && i < 0x1800) || i >= 0x1A00 ? i - 0x200 : i);
    };
    std::vector<PlannedWrite> out;
    std::vector<PlannedWrite> rest;
    std::map<uint16_t, std::vector<PlannedWrite>> byPdo;
    for (PlannedWrite& w : p.writes) {
        if (isPdo(w.index)) byPdo[commOf(w.index)].push_back(std::move(w));
        else rest.push_back(std::move(w));
    }
    auto valueOf = [&](const od::ObjectDictionary* d, uint16_t index, uint8_t sub) -> std::optional<uint64_t> {
        if (!d) return std::nullopt;
        const od::SubObject* s = d->entry(index, sub);
        if (!s || s->parameterValue.isEmpty()) return std::nullopt;
        const auto v = s->interpret(s->parameterValue, p.node);
        return v ? v->toUInt64() : std::nullopt;
    };
    auto step = [&](uint16_t index, uint8_t sub, od::DataType type, uint64_t value, const QString& what) {
        PlannedWrite w;
        w.index = index;
        w.sub = sub;
        w.type = type;
        w.value = od::Value::unsignedInt(value);
        w.data = w.value.encode(type);
        w.name = dcf.displayName(index, sub) + QStringLiteral(" (%1)").arg(what);
        w.valueText = edsText(type, w.value);
        return w;
    };
    for (auto& [comm, writes] : byPdo) {
        const uint16_t map = static_cast<uint16_t>(comm + 0x200);
        const od::SubObject* cobEntry = dcf.entry(comm, 1);
        std::optional<uint64_t> finalCob = valueOf(&dcf, comm, 1);
        if (!finalCob) finalCob = valueOf(current, comm, 1);
        if (!cobEntry || !finalCob || !od::isWritable(cobEntry->access)) {  // cannot frame it: as planned
            for (auto& w : writes) out.push_back(std::move(w));
            continue;
        }
        const bool mapping =
            std::any_of(writes.begin(), writes.end(), [map](const PlannedWrite& w) { return w.index == map; });
        const od::SubObject* countEntry = dcf.entry(map, 0);
        out.push_back(
            step(comm, 1, cobEntry->dataType, *finalCob | 0x80000000u, QStringLiteral("invalid while configured")));
        for (auto& w : writes)
            if (w.index == comm && w.sub != 1) out.push_back(std::move(w));
        if (mapping && countEntry) {
            const std::optional<uint64_t> count = valueOf(&dcf, map, 0);
            out.push_back(step(map, 0, countEntry->dataType, 0, QStringLiteral("0 while mapping")));
            for (auto& w : writes)
                if (w.index == map && w.sub != 0) out.push_back(std::move(w));
            if (count) out.push_back(step(map, 0, countEntry->dataType, *count, QStringLiteral("count")));
        } else {
            for (auto& w : writes)
                if (w.index == map) out.push_back(std::move(w));
        }
        out.push_back(step(comm, 1, cobEntry->dataType, *finalCob, QStringLiteral("final")));
    }
    // PDO objects first (communication area order), then everything else in index order.
    std::vector<PlannedWrite> ordered;
    for (auto& w : rest)
        if (w.index < 0x1400) ordered.push_back(std::move(w));
    for (auto& w : out) ordered.push_back(std::move(w));
    for (auto& w : rest)
        if (w.index >= 0x1400) ordered.push_back(std::move(w));
    p.writes = std::move(ordered);
}

std::vector<std::pair<uint16_t, uint8_t>> DeviceConfiguration::planEntries(const ApplyPlan& plan) {
    std::vector<std::pair<uint16_t, uint8_t>> out;
    out.reserve(plan.writes.size());
    for (const PlannedWrite& w : plan.writes) out.emplace_back(w.index, w.sub);
    return out;
}

void DeviceConfiguration::apply(const ApplyPlan& plan, Progress progress, ApplyDone done, int timeoutMs) {
    auto run = std::make_shared<Run>();
    run->isRead = false;
    run->node = plan.node;
    run->timeoutMs = timeoutMs;
    run->writes = plan.writes;
    run->progress = std::move(progress);
    run->applyDone = std::move(done);
    running_ = true;
    cancelRequested_ = false;
    step(run);
}

void DeviceConfiguration::cancel() {
    if (running_) cancelRequested_ = true;
}

void DeviceConfiguration::step(std::shared_ptr<Run> run) {
    if (cancelRequested_) run->cancelled = true;
    if (run->cancelled || static_cast<int>(run->next) >= run->total()) {
        finish(run);
        return;
    }
    SdoOptions options;
    options.timeoutMs = run->timeoutMs;
    QPointer<DeviceConfiguration> self(this);
    const size_t i = run->next++;
    if (run->isRead) {
        // Plain names, not a structured binding: clang 14 cannot capture those in a lambda.
        const auto index = std::get<0>(run->entries[i]);
        const auto sub = std::get<1>(run->entries[i]);
        sdo_.upload(
            run->node, index, sub,
            [self, run, index, sub](const SdoResult& r) {
                if (!self) return;
                od::ObjectDictionary& dict = run->readResult.values;
                ConfigEntryResult e;
                e.index = index;
                e.sub = sub;
                e.name = dict.displayName(index, sub);
                const od::SubObject* s = dict.entry(index, sub);
                if (s) e.type = s->dataType;
                e.abortCode = r.ok ? 0 : r.abortCode;
                if (!r.ok) {
                    e.error = r.error;
                    dict.setParameterValue(index, sub, {});
                } else if (!s) {
                    e.error =
                        QStringLiteral("node %1 %2: not in the dictionary").arg(run->node).arg(objectRef(index, sub));
                } else {
                    const od::ValueResult v = decodeUpload(s->dataType, r.data, &e.data);
                    if (!v.ok()) {
                        e.error = QStringLiteral("node %1 %2: %3 (bytes %4)")
                                      .arg(run->node)
                                      .arg(objectRef(index, sub), v.error, QString::fromLatin1(r.data.toHex(' ')));
                    } else {
                        e.ok = true;
                        e.valueText = edsText(s->dataType, v.value);
                        dict.setParameterValue(index, sub, e.valueText);
                        // Pre-defined error field: only subs 1..n of 1003h:00 = n hold errors; the
                        // others answer "no data" (CiA 301 7.5.2.5) and are not asked.
                        if (index == 0x1003 && sub == 0) {
                            const uint64_t n = v.value.toUInt64().value_or(0);
                            auto& list = run->entries;
                            list.erase(std::remove_if(list.begin() + static_cast<std::ptrdiff_t>(run->next), list.end(),
                                                      [n](const auto& p) { return p.first == 0x1003 && p.second > n; }),
                                       list.end());
                        }
                    }
                }
                if (!e.ok) ++run->readResult.failed;
                run->readResult.entries.push_back(e);
                if (run->progress) run->progress(e, static_cast<int>(run->next), run->total());
                if (self) self->step(run);
            },
            options);
    } else {
        const PlannedWrite& w = run->writes[i];
        sdo_.download(
            run->node, w.index, w.sub, w.data,
            [self, run, i](const SdoResult& r) {
                if (!self) return;
                const PlannedWrite& w = run->writes[i];
                ConfigEntryResult e;
                e.index = w.index;
                e.sub = w.sub;
                e.name = w.name;
                e.type = w.type;
                e.data = w.data;
                e.valueText = w.valueText;
                e.ok = r.ok;
                e.abortCode = r.ok ? 0 : r.abortCode;
                e.error = r.error;
                run->applied.push_back(e);
                if (!r.ok && self->stopOnRefusal_) run->next = run->writes.size();
                if (run->progress) run->progress(e, static_cast<int>(run->next), run->total());
                if (self) self->step(run);
            },
            options);
    }
}

void DeviceConfiguration::finish(std::shared_ptr<Run> run) {
    running_ = false;
    cancelRequested_ = false;
    if (run->isRead) {
        run->readResult.cancelled = run->cancelled;
        if (run->readDone) run->readDone(run->readResult);
    } else {
        if (run->applyDone) run->applyDone(run->applied, run->cancelled);
    }
}

}  // namespace coscope::canopen
