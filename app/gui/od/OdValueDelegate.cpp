// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/od/OdValueDelegate.h"

#include "app/gui/od/IntegerSpinBox.h"
#include "app/gui/od/OdTreeModel.h"
#include "core/canopen/SdoClient.h"

#include <QCoreApplication>

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLineEdit>
#include <QRegularExpressionValidator>

#include <cmath>
#include <limits>

namespace coscope::gui {

namespace {

const od::SubObject* entryOf(const OdTreeModel* model, const QModelIndex& index) {
    const int sub = index.data(OdTreeModel::SubRole).toInt();
    if (sub < 0) return nullptr;
    return model->dictionary().entry(static_cast<uint16_t>(index.data(OdTreeModel::IndexRole).toInt()),
                                     static_cast<uint8_t>(sub));
}

}  // namespace

OdValueDelegate::OdValueDelegate(OdTreeModel* model, QObject* parent) : QStyledItemDelegate(parent), model_(model) {}

QWidget* OdValueDelegate::createEditor(QWidget* parent, const QStyleOptionViewItem& option,
                                       const QModelIndex& index) const {
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
        // Decimal, 0x1F or 1Fh, shown in the object's notation (README "Numbers").
        auto* spin = new IntegerSpinBox(parent);
        spin->setType(e->dataType, e->limits(), od::hexKindFor(e->index, e->sub));
        spin->setAccelerated(true);
        // Enter or leaving the field with text that does not read: the reason on the value's row.
        connect(spin, &IntegerSpinBox::refused, this, [this, index = e->index, sub = e->sub](const QString& why) {
            model_->setError(index, sub,
                             QCoreApplication::translate("OdTreeModel", "node %1 %2: %3")
                                 .arg(model_->node())
                                 .arg(canopen::objectRef(index, sub), why));
            emit refused(why);
        });
        editor = spin;
        break;
    }
    case od::TypeClass::Real: {
        auto* spin = new QDoubleSpinBox(parent);
        const double max = e->dataType == od::DataType::Real32 ? double(std::numeric_limits<float>::max())
                                                               : std::numeric_limits<double>::max();
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
    else if (auto* spin = qobject_cast<IntegerSpinBox*>(editor)) {
        const auto r = e ? od::Value::parse(e->dataType, text) : od::ValueResult{};
        spin->setValue(r.value);
        spin->selectAll();
    } else if (auto* dspin = qobject_cast<QDoubleSpinBox*>(editor)) dspin->setValue(text.toDouble());
    else if (auto* line = qobject_cast<QLineEdit*>(editor)) line->setText(text);
}

void OdValueDelegate::setModelData(QWidget* editor, QAbstractItemModel* model, const QModelIndex& index) const {
    const auto objIndex = static_cast<uint16_t>(index.data(OdTreeModel::IndexRole).toInt());
    const auto sub = static_cast<uint8_t>(index.data(OdTreeModel::SubRole).toInt());
    QString text;
    if (auto* box = qobject_cast<QComboBox*>(editor)) text = box->currentText();
    else if (auto* spin = qobject_cast<IntegerSpinBox*>(editor)) {
        // What does not read was refused when editing ended (refused()), not cut to what reads.
        const od::IntegerInput in = spin->typed();
        const od::SubObject* e = entryOf(model_, index);
        if (spin->wasRefused() || !in.ok() || !e) return;
        text = in.value.format(e->dataType);
    } else if (auto* dspin = qobject_cast<QDoubleSpinBox*>(editor)) text = QString::number(dspin->value(), 'g', 17);
    else if (auto* line = qobject_cast<QLineEdit*>(editor)) text = line->text();
    // Unchanged: no write.
    if (text == index.data(Qt::EditRole).toString() && model_->actualValue(objIndex, sub)) return;
    model->setData(index, text, Qt::EditRole);
}

}  // namespace coscope::gui
