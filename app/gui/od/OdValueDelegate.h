// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QStyledItemDelegate>

namespace coscope::gui {

class OdTreeModel;

// The editor of the Value column, fitting the entry's type and its LowLimit/HighLimit:
// a spin box for integers that fit an int (limits as its range), a double spin box for REAL32/64,
// a true/false box for BOOLEAN, a line edit for strings, one that accepts only hex bytes for
// OCTET_STRING/DOMAIN, and one checked with od::Value::parse for wider integers. The text goes
// to the model, which asks for the write (OdTreeModel::writeRequested).
class OdValueDelegate : public QStyledItemDelegate {
    Q_OBJECT
public:
    explicit OdValueDelegate(OdTreeModel* model, QObject* parent = nullptr);

    QWidget* createEditor(QWidget* parent, const QStyleOptionViewItem& option, const QModelIndex& index) const override;
    void setEditorData(QWidget* editor, const QModelIndex& index) const override;
    void setModelData(QWidget* editor, QAbstractItemModel* model, const QModelIndex& index) const override;

private:
    OdTreeModel* model_;
};

}  // namespace coscope::gui
