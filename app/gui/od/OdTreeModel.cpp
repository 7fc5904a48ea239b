// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/od/OdTreeModel.h"

#include "app/gui/language/CoreText.h"

#include "core/canopen/DeviceConfiguration.h"
#include "core/canopen/Ds402.h"
#include "core/od/NumberNotation.h"
#include "dissectors/ObjectNames.h"
#include "dissectors/ParameterNames.h"
#include "dissectors/VendorTable.h"

#include <QBrush>
#include <QColor>
#include <QFont>

#include <QCoreApplication>

namespace coscope::gui {

namespace {
QString hexIndex(uint16_t index) { return QStringLiteral("%1").arg(index, 4, 16, QLatin1Char('0')).toUpper() + u'h'; }
QString hexSub(uint8_t sub) { return QStringLiteral("%1").arg(sub, 2, 16, QLatin1Char('0')).toUpper(); }
const QColor kErrorColor(0xB0, 0x00, 0x20);
const QColor kChangedColor(0x00, 0x4E, 0xA8);
}  // namespace

QString OdTreeModel::localName(uint16_t index, int sub, const QString& edsName) const {
    // A standard object of a bundled dictionary as the manuals name it, a vendor parameter with
    // its Chinese name; a user's EDS as written (dissectors/ObjectNames.h).
    const QString lang = dissect::vendorTextLanguage();
    return dissect::localParameterName(dissect::localObjectName(dictionary_.bundledName, index, sub, edsName, lang),
                                       lang);
}

OdTreeModel::OdTreeModel(QObject* parent) : QAbstractItemModel(parent) {}

void OdTreeModel::setDictionary(const od::ObjectDictionary& dictionary, uint8_t node) {
    beginResetModel();
    dictionary_ = dictionary;
    node_ = node;
    rows_.clear();
    states_.clear();
    valuesRead_ = 0;
    for (const auto& [index, obj] : dictionary_.objects()) {
        if (obj.objectType == od::ObjectType::DefType || obj.objectType == od::ObjectType::DefStruct ||
            obj.subs.empty())
            continue;
        rows_.push_back({index, obj.isComposite() || obj.subs.size() > 1 || obj.subs.front().sub != 0});
    }
    endResetModel();
}

void OdTreeModel::clear() {
    beginResetModel();
    dictionary_ = {};
    node_ = 0;
    rows_.clear();
    states_.clear();
    valuesRead_ = 0;
    endResetModel();
}

OdTreeModel::NodeValues OdTreeModel::values() const {
    NodeValues out{states_, valuesRead_};
    for (auto& [k, s] : out.states)
        if (s.state == State::Reading || s.state == State::Writing) s.state = s.value ? State::Read : State::Unknown;
    return out;
}

void OdTreeModel::setValues(const NodeValues& values) {
    beginResetModel();  // right after setDictionary: nothing expanded to keep
    states_ = values.states;
    valuesRead_ = values.valuesRead;
    endResetModel();
}

const od::Object* OdTreeModel::objectAt(const QModelIndex& index) const {
    if (!index.isValid()) return nullptr;
    const size_t row =
        index.internalId() == 0 ? static_cast<size_t>(index.row()) : static_cast<size_t>(index.internalId() - 1);
    return row < rows_.size() ? dictionary_.object(rows_[row].index) : nullptr;
}

const od::SubObject* OdTreeModel::entryAt(const QModelIndex& index) const {
    const od::Object* obj = objectAt(index);
    if (!obj) return nullptr;
    if (index.internalId() == 0) {
        const bool composite = rows_[static_cast<size_t>(index.row())].composite;
        return composite ? nullptr : &obj->subs.front();
    }
    return index.row() < static_cast<int>(obj->subs.size()) ? &obj->subs[static_cast<size_t>(index.row())] : nullptr;
}

QModelIndex OdTreeModel::indexOf(uint16_t index, uint8_t sub, int column) const {
    auto it =
        std::lower_bound(rows_.begin(), rows_.end(), index, [](const ObjectRow& r, uint16_t i) { return r.index < i; });
    if (it == rows_.end() || it->index != index) return {};
    const int objRow = static_cast<int>(it - rows_.begin());
    if (!it->composite) return sub == 0 ? createIndex(objRow, column, quintptr(0)) : QModelIndex();
    const od::Object* obj = dictionary_.object(index);
    for (size_t i = 0; i < obj->subs.size(); ++i)
        if (obj->subs[i].sub == sub) return createIndex(static_cast<int>(i), column, quintptr(objRow) + 1);
    return {};
}

QModelIndex OdTreeModel::index(int row, int column, const QModelIndex& parent) const {
    if (row < 0 || column < 0 || column >= ColumnCount) return {};
    if (!parent.isValid())
        return row < static_cast<int>(rows_.size()) ? createIndex(row, column, quintptr(0)) : QModelIndex();
    if (parent.internalId() != 0 || !rows_[static_cast<size_t>(parent.row())].composite) return {};
    const od::Object* obj = dictionary_.object(rows_[static_cast<size_t>(parent.row())].index);
    if (!obj || row >= static_cast<int>(obj->subs.size())) return {};
    return createIndex(row, column, quintptr(parent.row()) + 1);
}

QModelIndex OdTreeModel::parent(const QModelIndex& child) const {
    if (!child.isValid() || child.internalId() == 0) return {};
    return createIndex(static_cast<int>(child.internalId() - 1), 0, quintptr(0));
}

int OdTreeModel::rowCount(const QModelIndex& parent) const {
    if (!parent.isValid()) return static_cast<int>(rows_.size());
    if (parent.column() != 0 || parent.internalId() != 0) return 0;
    const ObjectRow& r = rows_[static_cast<size_t>(parent.row())];
    if (!r.composite) return 0;
    const od::Object* obj = dictionary_.object(r.index);
    return obj ? static_cast<int>(obj->subs.size()) : 0;
}

int OdTreeModel::columnCount(const QModelIndex&) const { return ColumnCount; }

QString OdTreeModel::valueText(const od::SubObject& e, const od::Value& v, bool withUnit) const {
    od::FormatOptions o;
    if (auto u = dictionary_.unit(e.index, e.sub)) {
        if (withUnit) o.unit = u->text;
        o.factor = u->factor;
    }
    const uint16_t base =
        e.index >= 0x6000 && e.index < 0xA000 ? static_cast<uint16_t>(0x6000 + (e.index - 0x6000) % 0x800) : e.index;
    if ((base == 0x6060 || base == 0x6061) && e.sub == 0 && od::isInteger(e.dataType)) {
        const QString mode = coreText(canopen::ds402::modeName(static_cast<int8_t>(v.toInt64().value_or(0))));
        return mode.isEmpty() ? v.format(e.dataType, o) : QStringLiteral("%1 (%2)").arg(v.format(e.dataType, o), mode);
    }
    // COB-IDs, mapping entries, identity, control/statuswords…: hex by the app's one rule
    // (od/NumberNotation.h); quantities decimal with their unit.
    if (od::isInteger(e.dataType) && od::bitSize(e.dataType) <= 64) {
        const auto raw = v.toInt64();
        const uint64_t bits = raw ? static_cast<uint64_t>(*raw) : v.toUInt64().value_or(0);
        if (QString hex = od::hexValueText(e.index, e.sub, bits, od::bitSize(e.dataType)); !hex.isEmpty()) return hex;
        if (QString named = od::namedValueText(e.index, e.sub, bits); !named.isEmpty()) return coreText(named);
    }
    return v.format(e.dataType, o);
}

QString OdTreeModel::statuswordBitsText(const od::SubObject& e, const od::Value& v) const {
    // 6041h of an axis (CiA 402-1 §5: + n x 800h): the bits that are on, 12/13 named by the
    // axis' mode of operation 6061h as read here (CiA 402-2 §6.3.2; the trace's names, one source).
    if (e.sub != 0 || e.index < 0x6000 || e.index > 0x67FF || (e.index - 0x6000) % 0x800 != 0x41) return {};
    const auto sw = v.toUInt64();
    if (!sw) return {};
    std::optional<int8_t> mode;
    if (const auto m = actualValue(static_cast<uint16_t>(e.index + 0x20), 0))
        mode = static_cast<int8_t>(m->toInt64().value_or(0));
    QStringList bits;
    for (const QString& b : canopen::ds402::statuswordBits(static_cast<uint16_t>(*sw), mode)) bits << coreText(b);
    return QCoreApplication::translate("OdTreeModel", "\nBits on: %1")
        .arg(bits.isEmpty() ? QStringLiteral("—") : bits.join(QStringLiteral(", ")));
}

QVariant OdTreeModel::data(const QModelIndex& index, int role) const {
    const od::Object* obj = objectAt(index);
    if (!obj) return {};
    const od::SubObject* e = entryAt(index);
    const bool objectRow = index.internalId() == 0;
    if (role == IndexRole) return obj->index;
    if (role == SubRole) return e ? e->sub : -1;
    const EntryState* st = nullptr;
    if (e) {
        auto it = states_.find(key(e->index, e->sub));
        if (it != states_.end()) st = &it->second;
    }
    if (role == ChangedRole) {
        if (st) return st->changed;
        if (!e) {  // a composite object is changed when one of its subs is
            for (const auto& s : obj->subs)
                if (isChanged(obj->index, s.sub)) return true;
        }
        return false;
    }
    if (role == ErrorRole) return st ? st->error : QString();
    if (role == SearchRole) {
        QString t = hexIndex(obj->index) + u' ' + QStringLiteral("%1").arg(obj->index, 4, 16, QLatin1Char('0')) + u' ' +
                    obj->name;
        if (e && !objectRow)
            t += u' ' +
                 QStringLiteral("%1:%2").arg(obj->index, 4, 16, QLatin1Char('0')).arg(e->sub, 2, 16, QLatin1Char('0')) +
                 u' ' + e->name;
        if (objectRow)
            for (const auto& s : obj->subs) t += u' ' + s.name;
        // The names shown (Chinese) are found too.
        t += u' ' + localName(obj->index, -1, obj->name);
        if (e && !objectRow) t += u' ' + localName(obj->index, e->sub, e->name);
        return t;
    }
    const int col = index.column();
    if (role == Qt::DisplayRole || role == Qt::EditRole) {
        if (!e) {  // composite object row
            switch (col) {
            case Object: return hexIndex(obj->index);
            case Name: return localName(obj->index, -1, obj->name);
            case Type: return od::objectTypeName(obj->objectType);
            default: return {};
            }
        }
        switch (col) {
        case Object:
            return objectRow ? hexIndex(obj->index)
                             : QCoreApplication::translate("OdTreeModel", "sub %1").arg(hexSub(e->sub));
        case Name: return objectRow ? localName(obj->index, -1, obj->name) : localName(obj->index, e->sub, e->name);
        case Type: return od::dataTypeName(e->dataType);
        case Access: return od::accessName(e->access);
        case Pdo: return e->pdoMappable ? QStringLiteral("✓") : QString();
        case Default: {
            const auto d = e->resolvedDefault(node_);
            if (!d) return e->defaultValue;
            return valueText(*e, *d, false);
        }
        case Value:
            if (role == Qt::EditRole) {
                if (st && st->value) return st->value->format(e->dataType);
                const auto d = e->resolvedDefault(node_);
                return d ? d->format(e->dataType) : QString();
            }
            if (!st) return {};
            if (st->state == State::Reading)
                return st->value ? valueText(*e, *st->value, false) + QStringLiteral("  …")
                                 : QCoreApplication::translate("OdTreeModel", "reading…");
            if (st->state == State::Writing) return QCoreApplication::translate("OdTreeModel", "writing…");
            if (st->state == State::Error) {
                const QString prefix =
                    st->value ? valueText(*e, *st->value, false) + QStringLiteral("  ⚠ ") : QStringLiteral("⚠ ");
                return prefix + st->error.section(QStringLiteral(": "), 1);
            }
            return st->value ? valueText(*e, *st->value, false) : QString();
        case Unit: {
            const auto u = dictionary_.unit(e->index, e->sub);
            return u ? u->text : QString();
        }
        default: return {};
        }
    }
    if (!e) {
        if (role == Qt::FontRole && col == Object) {
            QFont f;
            f.setBold(data(index, ChangedRole).toBool());
            return f;
        }
        return {};
    }
    if (role == Qt::ToolTipRole) {
        if (st && !st->error.isEmpty()) return st->error;
        // The name shown, and the EDS's own when the view shows a translated one.
        const QString eds = dictionary_.displayName(e->index, e->sub);
        const QString shown = dissect::localDisplayName(dictionary_, e->index, e->sub, dissect::vendorTextLanguage());
        QString tip =
            QStringLiteral("%1:%2 %3\n%4, %5%6")
                .arg(obj->index, 4, 16, QLatin1Char('0'))
                .arg(e->sub, 2, 16, QLatin1Char('0'))
                .arg(shown == eds ? eds : QStringLiteral("%1 (%2)").arg(shown, eds), od::dataTypeName(e->dataType),
                     od::accessName(e->access),
                     e->pdoMappable ? QCoreApplication::translate("OdTreeModel", ", PDO-mappable") : QString());
        if (!e->lowLimit.isEmpty() || !e->highLimit.isEmpty())
            tip += QCoreApplication::translate("OdTreeModel", "\nLimits: %1 … %2").arg(e->lowLimit, e->highLimit);
        if (st && st->changed) tip += QCoreApplication::translate("OdTreeModel", "\nDiffers from the default");
        if (st && st->value) tip += statuswordBitsText(*e, *st->value);
        return tip;
    }
    if (role == Qt::ForegroundRole) {
        if (col == Value && st && st->state == State::Error) return QBrush(kErrorColor);
        if (col == Value && st && st->changed) return QBrush(kChangedColor);
        if (col == Value && st && (st->state == State::Reading || st->state == State::Writing)) return QBrush(Qt::gray);
        return {};
    }
    if (role == Qt::FontRole && st && st->changed && (col == Value || col == Object || col == Name)) {
        QFont f;
        f.setBold(true);
        return f;
    }
    if (role == Qt::TextAlignmentRole && col == Pdo) return Qt::AlignCenter;
    return {};
}

bool OdTreeModel::setData(const QModelIndex& index, const QVariant& value, int role) {
    if (role != Qt::EditRole || index.column() != Value) return false;
    const od::SubObject* e = entryAt(index);
    if (!e) return false;
    // The editors hand over text, parsed here as the entry's type within its limits.
    const od::ValueResult r = od::Value::parse(e->dataType, value.toString(), e->limits());
    if (!r.ok()) {
        setError(e->index, e->sub,
                 QCoreApplication::translate("OdTreeModel", "node %1 %2: %3")
                     .arg(node_)
                     .arg(canopen::objectRef(e->index, e->sub), r.error));
        return false;
    }
    emit writeRequested(e->index, e->sub, r.value);
    return false;  // the model shows the value once it is read back
}

Qt::ItemFlags OdTreeModel::flags(const QModelIndex& index) const {
    if (!index.isValid()) return {};
    Qt::ItemFlags f = Qt::ItemIsEnabled | Qt::ItemIsSelectable;
    const od::SubObject* e = entryAt(index);
    if (e && index.column() == Value && writable_ && od::isWritable(e->access)) f |= Qt::ItemIsEditable;
    if (e && !od::isReadable(e->access) && index.column() == Value) f &= ~Qt::ItemIsEnabled;
    return f;
}

QVariant OdTreeModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole) return {};
    switch (section) {
    case Object: return tr("Index");
    case Name: return tr("Name");
    case Type: return tr("Type");
    case Access: return tr("Access");
    case Pdo: return tr("PDO");
    case Default: return tr("Default");
    case Value: return tr("Value");
    case Unit: return tr("Unit");
    default: return {};
    }
}

void OdTreeModel::entryChanged(uint16_t index, uint8_t sub) {
    const QModelIndex first = indexOf(index, sub, 0);
    if (!first.isValid()) return;
    emit dataChanged(first, first.siblingAtColumn(ColumnCount - 1));
    if (first.parent().isValid()) emit dataChanged(first.parent(), first.parent());
}

void OdTreeModel::setState(uint16_t index, uint8_t sub, State state) {
    EntryState& s = states_[key(index, sub)];
    s.state = state;
    if (state == State::Reading || state == State::Writing) s.error.clear();
    entryChanged(index, sub);
}

void OdTreeModel::setUploaded(uint16_t index, uint8_t sub, const QByteArray& data) {
    const od::SubObject* e = dictionary_.entry(index, sub);
    if (!e) return;
    EntryState& s = states_[key(index, sub)];
    const od::ValueResult v = canopen::DeviceConfiguration::decodeUpload(e->dataType, data);
    if (!v.ok()) {
        s.state = State::Error;
        s.error = QCoreApplication::translate("OdTreeModel", "node %1 %2: %3 (bytes %4)")
                      .arg(node_)
                      .arg(canopen::objectRef(index, sub), v.error, QString::fromLatin1(data.toHex(' ')));
    } else {
        if (!s.value) ++valuesRead_;
        s.state = State::Read;
        s.error.clear();
        s.value = v.value;
        const auto def = e->resolvedDefault(node_);
        s.changed = def && def->encode(e->dataType) != v.value.encode(e->dataType);
    }
    entryChanged(index, sub);
}

void OdTreeModel::setError(uint16_t index, uint8_t sub, const QString& error) {
    EntryState& s = states_[key(index, sub)];
    s.state = State::Error;
    s.error = error;
    entryChanged(index, sub);
}

OdTreeModel::State OdTreeModel::state(uint16_t index, uint8_t sub) const {
    auto it = states_.find(key(index, sub));
    return it == states_.end() ? State::Unknown : it->second.state;
}

std::optional<od::Value> OdTreeModel::actualValue(uint16_t index, uint8_t sub) const {
    auto it = states_.find(key(index, sub));
    return it == states_.end() ? std::nullopt : it->second.value;
}

QString OdTreeModel::actualText(uint16_t index, uint8_t sub) const {
    const od::SubObject* e = dictionary_.entry(index, sub);
    const auto v = actualValue(index, sub);
    return e && v ? valueText(*e, *v) : QString();
}

QString OdTreeModel::errorText(uint16_t index, uint8_t sub) const {
    auto it = states_.find(key(index, sub));
    return it == states_.end() ? QString() : it->second.error;
}

bool OdTreeModel::isChanged(uint16_t index, uint8_t sub) const {
    auto it = states_.find(key(index, sub));
    return it != states_.end() && it->second.changed;
}

od::ObjectDictionary OdTreeModel::actualValues() const {
    od::ObjectDictionary out = dictionary_;
    out.setNodeId(node_);
    for (const auto& [index, obj] : dictionary_.objects())
        for (const auto& s : obj.subs) {
            const auto v = actualValue(index, s.sub);
            out.setParameterValue(index, s.sub, v ? canopen::DeviceConfiguration::edsText(s.dataType, *v) : QString());
        }
    return out;
}

}  // namespace coscope::gui
