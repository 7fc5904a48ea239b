// SPDX-License-Identifier: GPL-3.0-or-later
#include "dissectors/Dissection.h"

#include <cstring>

namespace coscope::dissect {

namespace {
// `to = from`, skipping the reference counting (two atomic operations) when `to` already holds
// the same text: names and units repeat frame after frame.
void assignShared(QString& to, const QString& from) {
    // The same buffer (shared, or the same static literal), or both empty: nothing to do.
    if (to.size() == from.size() && (to.constData() == from.constData() || to.isEmpty())) return;
    to = from;
}
}  // namespace

void Dissection::reset(Level level) {
    level_ = level;
    service = canopen::Service::Unknown;
    node = -1;
    pdoNumber = 0;
    if (!summary.isEmpty()) summary.resize(0);  // keeps the capacity; skips the call when already empty
    if (!warnings.isEmpty()) warnings.clear();
    signalCount = 0;
    hasTransfer = false;
    // Assigned from a dictionary's bundledName (shared data): release it rather than resize it,
    // which would detach, i.e. allocate a copy for every PDO/SDO frame.
    if (!namesFrom.isNull()) namesFrom = QString();
    fieldCount_ = 0;
    if (!tree.empty()) tree.clear();
}

const FlatField* Dissection::find(const char* key) const {
    for (int i = 0; i < fieldCount_; ++i)
        if (std::strcmp(fields_[static_cast<size_t>(i)].key, key) == 0) return &fields_[static_cast<size_t>(i)];
    return nullptr;
}

FlatField& Dissection::next(const char* key, FlatField::Kind kind) {
    if (static_cast<size_t>(fieldCount_) == fields_.size()) fields_.emplace_back();
    FlatField& f = fields_[static_cast<size_t>(fieldCount_++)];
    f.key = key;
    f.kind = kind;
    return f;
}

void Dissection::addInt(const char* key, int64_t v) {
    if (wantFields) next(key, FlatField::Kind::Int).i = v;
}
void Dissection::addUInt(const char* key, uint64_t v) {
    if (wantFields) next(key, FlatField::Kind::UInt).u = v;
}
void Dissection::addReal(const char* key, double v) {
    if (wantFields) next(key, FlatField::Kind::Real).d = v;
}
void Dissection::addBool(const char* key, bool v) {
    if (wantFields) next(key, FlatField::Kind::Bool).i = v ? 1 : 0;
}
void Dissection::addText(const char* key, const QString& v) {
    if (wantFields) assignShared(next(key, FlatField::Kind::Text).text, v);
}

PdoSignal& Dissection::addSignal(const QString& name, const QString& unit) {
    if (!wantFields) return scratchSignal_;  // the dissector still fills in the value it decodes
    if (static_cast<size_t>(signalCount) == pdoSignals.size()) pdoSignals.emplace_back();
    PdoSignal& s = pdoSignals[static_cast<size_t>(signalCount++)];
    assignShared(s.name, name);
    assignShared(s.unit, unit);
    s.raw = false;
    return s;
}

void Dissection::item(int depth, const QString& label, const QString& value, int byteOffset, int byteLength,
                      int bitOffset, int bitLength) {
    tree.push_back({depth, label, value, byteOffset, byteLength, bitOffset, bitLength});
}

QString hex(uint32_t v, int width) {
    return QStringLiteral("0x") + QString::number(v, 16).toUpper().rightJustified(width, u'0');
}

QString hexBytes(const uint8_t* data, int len, bool spaced) {
    static const char digits[] = "0123456789ABCDEF";
    QString s;
    s.reserve(len * 3);
    for (int i = 0; i < len; ++i) {
        if (spaced && i) s += u' ';
        s += QLatin1Char(digits[data[i] >> 4]);
        s += QLatin1Char(digits[data[i] & 15]);
    }
    return s;
}

}  // namespace coscope::dissect
