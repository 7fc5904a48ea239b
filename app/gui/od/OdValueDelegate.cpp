// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/od/OdValueDelegate.h"

#include "app/gui/od/OdTreeModel.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLineEdit>
#include <QRegularExpressionValidator>
#include <QSpinBox>

#include <cmath>
#include <limits>

namespace coscope::gui {

namespace {

const od::SubObject* entryOf(const OdTreeModel* model, const QModelIndex& index) {
    const int sub = index.data(OdTreeModel::SubRole).toInt();
    if (sub < 0) return nullptr;
    return model->dictionary().entry(static_cast<uint16_t>(index.data(OdTreeModel::IndexRole).toInt()), static_cast<uint8_t>(sub));
}

// The type's range, narrowed by the entry's limits; nullopt when it does not fit an int.
std::optional<std::pair<qint64, qint64>> intRange(const od::SubObject& e) {
    const int bits = od::bitSize(e.dataType);
    qint64 lo = 0, hi = 0;
    if (od::isSigned(e.dataType)) {
        if (bits > 32) return std::nullopt;
        lo = -(qint64(1) << (bits - 1));
        hi = (qint64(1) << (bits - 1)) - 1;
    } else {
        if (bits >= 32) return std::nullopt;
        hi = (qint64(1) << bits) - 1;
    }
    const od::Limits l = e.limits();
    if (l.low && l.low->toInt64()) lo = std::max<qint64>(lo, *l.low->toInt64());
    if (l.high && l.high->toInt64()) hi = std::min<qint64>(hi, *l.high->toInt64());
    return std::make_pair(lo, hi);
}

}  // namespace

OdValueDelegate::OdValueDelegate(OdTreeModel* model, QObject* parent) : QStyledItemDelegate(parent), model_(model) {}

QWidget* OdValueDelegate::createEditor(QWidget* parent, const QStyleOptionViewItem& option, const QModelIndex& index) const {
    const od::SubObject* e = entryOf(model_, index);
    if (!e) return nullptr;
    QWidget* editor = nullptr;
    switch (od::typeClass(e->dataType)) {
    case od::TypeClass::Boolean: {
        auto* box = new QComboBox(parent);
        box->addItems({QStringLiteral("false"), QStringLiteral("true")});
        editor = box;
        break;
    }
    case od::TypeClass::Signed:
    case od::TypeClass::Unsigned: {
        if (const auto range = intRange(*e)) {
            auto* spin = new QSpinBox(parent);
            spin->setRange(static_cast<int>(range->first), static_cast<int>(range->second));
            spin->setAccelerated(true);
            editor = spin;
        } else {
            auto* line = new QLineEdit(parent);
            line->setPlaceholderText(od::isSigned(e->dataType) ? QStringLiteral("-5, 0x1F") : QStringLiteral("5, 0x1F"));
            line->setValidator(new QRegularExpressionValidator(QRegularExpression(QStringLiteral("-?(0[xX][0-9a-fA-F]*|[0-9]*)")), line));
            editor = line;
        }
        break;
    }
    case od::TypeClass::Real: {
        auto* spin = new QDoubleSpinBox(parent);
        const double max = e->dataType == od::DataType::Real32 ? double(std::numeric_limits<float>::max()) : std::numeric_limits<double>::max();
        double lo = -max, hi = max;
        const od::Limits l = e->limits();
        if (l.low) lo = l.low->toDouble().value_or(lo);
        if (l.high) hi = l.high->toDouble().value_or(hi);
        spin->setRange(lo, hi);
        spin->setDecimals(e->dataType == od::DataType::Real32 ? 6 : 10);
        editor = spin;
        break;
    }
    case od::TypeClass::OctetString:
    case od::TypeClass::Domain: {
        auto* line = new QLineEdit(parent);
        line->setPlaceholderText(QStringLiteral("01 02 FF"));
        line->setValidator(new QRegularExpressionValidator(QRegularExpression(QStringLiteral("[0-9a-fA-F ]*")), line));
        editor = line;
        break;
    }
    default: editor = new QLineEdit(parent); break;
    }
    editor->setObjectName(QStringLiteral("odValueEditor"));
    editor->setGeometry(option.rect);
    return editor;
}

void OdValueDelegate::setEditorData(QWidget* editor, const QModelIndex& index) const {
    const QString text = index.data(Qt::EditRole).toString();
    const od::SubObject* e = entryOf(model_, index);
    if (auto* box = qobject_cast<QComboBox*>(editor)) box->setCurrentIndex(text == u"true" ? 1 : 0);
    else if (auto* spin = qobject_cast<QSpinBox*>(editor)) {
        const auto r = e ? od::Value::parse(e->dataType, text) : od::ValueResult{};
        spin->setValue(static_cast<int>(r.value.toInt64().value_or(0)));
    } else if (auto* dspin = qobject_cast<QDoubleSpinBox*>(editor)) dspin->setValue(text.toDouble());
    else if (auto* line = qobject_cast<QLineEdit*>(editor)) line->setText(text);
}

void OdValueDelegate::setModelData(QWidget* editor, QAbstractItemModel* model, const QModelIndex& index) const {
    QString text;
    if (auto* box = qobject_cast<QComboBox*>(editor)) text = box->currentText();
    else if (auto* spin = qobject_cast<QSpinBox*>(editor)) text = QString::number(spin->value());
    else if (auto* dspin = qobject_cast<QDoubleSpinBox*>(editor)) text = QString::number(dspin->value(), 'g', 17);
    else if (auto* line = qobject_cast<QLineEdit*>(editor)) text = line->text();
    // Unchanged: no write.
    if (text == index.data(Qt::EditRole).toString() && model_->actualValue(static_cast<uint16_t>(index.data(OdTreeModel::IndexRole).toInt()),
                                                                           static_cast<uint8_t>(index.data(OdTreeModel::SubRole).toInt())))
        return;
    model->setData(index, text, Qt::EditRole);
}

}  // namespace coscope::gui
