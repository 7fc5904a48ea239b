// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/od/ObjectDictionary.h"

#include "core/od/NumberText.h"

#include <algorithm>

namespace coscope::od {

QString objectTypeName(ObjectType t) {
    switch (t) {
    case ObjectType::Null: return QStringLiteral("NULL");
    case ObjectType::Domain: return QStringLiteral("DOMAIN");
    case ObjectType::DefType: return QStringLiteral("DEFTYPE");
    case ObjectType::DefStruct: return QStringLiteral("DEFSTRUCT");
    case ObjectType::Var: return QStringLiteral("VAR");
    case ObjectType::Array: return QStringLiteral("ARRAY");
    case ObjectType::Record: return QStringLiteral("RECORD");
    }
    return QStringLiteral("0x%1").arg(static_cast<int>(t), 0, 16);
}

QString accessName(Access a) {
    switch (a) {
    case Access::ReadOnly: return QStringLiteral("ro");
    case Access::WriteOnly: return QStringLiteral("wo");
    case Access::ReadWrite: return QStringLiteral("rw");
    case Access::ReadWriteRead: return QStringLiteral("rwr");
    case Access::ReadWriteWrite: return QStringLiteral("rww");
    case Access::Const: return QStringLiteral("const");
    }
    return QStringLiteral("ro");
}

std::optional<Access> accessFromString(const QString& text) {
    const QString t = text.trimmed().toLower();
    if (t == u"ro") return Access::ReadOnly;
    if (t == u"wo") return Access::WriteOnly;
    if (t == u"rw") return Access::ReadWrite;
    if (t == u"rwr") return Access::ReadWriteRead;
    if (t == u"rww") return Access::ReadWriteWrite;
    if (t == u"const") return Access::Const;
    return std::nullopt;
}

// ---- SubObject ----

bool SubObject::defaultUsesNodeId() const { return containsNodeId(defaultValue); }

std::optional<Value> SubObject::interpret(const QString& text, std::uint8_t nodeId, QString* error) const {
    if (error) error->clear();
    if (text.trimmed().isEmpty() && !isString(dataType)) return std::nullopt;
    if (containsNodeId(text)) {
        const auto v = evaluateNodeIdFormula(text, nodeId);
        if (!v) {
            if (error) *error = QStringLiteral("'%1' is not a $NODEID formula").arg(text);
            return std::nullopt;
        }
        if (isSigned(dataType)) return Value::signedInt(static_cast<std::int64_t>(*v));
        if (typeClass(dataType) == TypeClass::Real) return Value::real(static_cast<double>(*v));
        return Value::unsignedInt(*v);
    }
    const auto r = Value::parse(dataType, text, Limits{}, TextStyle::Eds);
    if (!r.ok()) {
        if (error) *error = r.error;
        return std::nullopt;
    }
    return r.value;
}

std::optional<Value> SubObject::resolvedDefault(std::uint8_t nodeId, QString* error) const {
    return interpret(defaultValue, nodeId, error);
}

std::optional<Value> SubObject::resolvedValue(std::uint8_t nodeId, QString* error) const {
    if (!parameterValue.isEmpty()) return interpret(parameterValue, nodeId, error);
    return resolvedDefault(nodeId, error);
}

Limits SubObject::limits() const {
    Limits l;
    if (!lowLimit.trimmed().isEmpty()) l.low = interpret(lowLimit, 0);
    if (!highLimit.trimmed().isEmpty()) l.high = interpret(highLimit, 0);
    return l;
}

// ---- Object ----

const SubObject* Object::sub(std::uint8_t s) const {
    auto it =
        std::lower_bound(subs.begin(), subs.end(), s, [](const SubObject& a, std::uint8_t b) { return a.sub < b; });
    return it != subs.end() && it->sub == s ? &*it : nullptr;
}

// ---- ObjectDictionary ----

ObjectDictionary::ObjectDictionary(const ObjectDictionary& o)
    : fileInfo(o.fileInfo), device(o.device), commissioning(o.commissioning), dummyUsage(o.dummyUsage),
      dynamicChannels(o.dynamicChannels), extraSections(o.extraSections), comments(o.comments),
      bundledName(o.bundledName), objects_(o.objects_) {
    rebuildIndex();
}

ObjectDictionary& ObjectDictionary::operator=(const ObjectDictionary& o) {
    if (this == &o) return *this;
    fileInfo = o.fileInfo;
    device = o.device;
    commissioning = o.commissioning;
    dummyUsage = o.dummyUsage;
    dynamicChannels = o.dynamicChannels;
    extraSections = o.extraSections;
    comments = o.comments;
    bundledName = o.bundledName;
    objects_ = o.objects_;
    rebuildIndex();
    return *this;
}

void ObjectDictionary::indexObject(const Object& o) {
    for (const SubObject& s : o.subs) index_[key(o.index, s.sub)] = const_cast<SubObject*>(&s);
}

void ObjectDictionary::unindexObject(const Object& o) {
    for (const SubObject& s : o.subs) index_.erase(key(o.index, s.sub));
}

void ObjectDictionary::rebuildIndex() {
    index_.clear();
    index_.reserve(objects_.size() * 3);
    for (const auto& [i, o] : objects_) indexObject(o);
}

void ObjectDictionary::insert(Object obj) {
    std::stable_sort(obj.subs.begin(), obj.subs.end(),
                     [](const SubObject& a, const SubObject& b) { return a.sub < b.sub; });
    // Duplicated sub-indices: keep the first.
    obj.subs.erase(std::unique(obj.subs.begin(), obj.subs.end(),
                               [](const SubObject& a, const SubObject& b) { return a.sub == b.sub; }),
                   obj.subs.end());
    for (SubObject& s : obj.subs) s.index = obj.index;
    auto it = objects_.find(obj.index);
    if (it != objects_.end()) {
        unindexObject(it->second);
        it->second = std::move(obj);
    } else {
        it = objects_.emplace(obj.index, std::move(obj)).first;
    }
    indexObject(it->second);
}

bool ObjectDictionary::remove(std::uint16_t index) {
    auto it = objects_.find(index);
    if (it == objects_.end()) return false;
    unindexObject(it->second);
    objects_.erase(it);
    return true;
}

void ObjectDictionary::clear() { *this = ObjectDictionary(); }

const Object* ObjectDictionary::object(std::uint16_t index) const {
    auto it = objects_.find(index);
    return it == objects_.end() ? nullptr : &it->second;
}

const SubObject* ObjectDictionary::entry(std::uint16_t index, std::uint8_t sub) const {
    auto it = index_.find(key(index, sub));
    return it == index_.end() ? nullptr : it->second;
}

SubObject* ObjectDictionary::entryForEdit(std::uint16_t index, std::uint8_t sub) {
    auto it = index_.find(key(index, sub));
    return it == index_.end() ? nullptr : it->second;
}

bool ObjectDictionary::setParameterValue(std::uint16_t index, std::uint8_t sub, const QString& text) {
    SubObject* s = entryForEdit(index, sub);
    if (!s) return false;
    s->parameterValue = text;
    return true;
}

QString ObjectDictionary::displayName(std::uint16_t index, std::uint8_t sub) const {
    const Object* o = object(index);
    if (!o) return {};
    if (!o->isComposite()) return o->name;
    const SubObject* s = o->sub(sub);
    return s ? o->name + QStringLiteral(": ") + s->name : o->name;
}

namespace {
std::optional<std::uint32_t> identityField(const ObjectDictionary& od, std::uint8_t sub) {
    const SubObject* s = od.entry(0x1018, sub);
    if (!s) return std::nullopt;
    const auto v = s->resolvedValue(od.nodeId());
    if (!v) return std::nullopt;
    const auto u = v->toUInt64();
    if (!u || *u > 0xFFFFFFFFu) return std::nullopt;
    return static_cast<std::uint32_t>(*u);
}
}  // namespace

std::optional<std::uint32_t> ObjectDictionary::vendorId() const {
    return device.vendorNumber ? device.vendorNumber : identityField(*this, 1);
}
std::optional<std::uint32_t> ObjectDictionary::productCode() const {
    return device.productNumber ? device.productNumber : identityField(*this, 2);
}
std::optional<std::uint32_t> ObjectDictionary::revisionNumber() const {
    return device.revisionNumber ? device.revisionNumber : identityField(*this, 3);
}

std::optional<Unit> ObjectDictionary::unit(std::uint16_t index, std::uint8_t sub) const {
    const SubObject* s = entry(index, sub);
    return s ? s->unit : std::nullopt;
}

}  // namespace coscope::od
