// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QStyledItemDelegate>

namespace coscope::gui {

class OdTreeModel;

// The editor of the Value column, fitting the entry's type and its LowLimit/HighLimit:
// the app's integer field for INTEGERn/UNSIGNEDn (decimal, 0x1F or 1Fh, shown in the object's
// notation; IntegerSpinBox), a double spin box for REAL32/64, a true/false box for BOOLEAN, a
// line edit for strings, one that accepts only hex bytes for OCTET_STRING/DOMAIN. The text goes
// to the model, which asks for the write (OdTreeModel::writeRequested); an integer that does not
// read is refused with the reason (the value's cell and refused()).
class OdValueDelegate : public QStyledItemDelegate {
    Q_OBJECT
public:
    explicit OdValueDelegate(OdTreeModel* model, QObject* parent = nullptr);

    QWidget* createEditor(QWidget* parent, const QStyleOptionViewItem& option, const QModelIndex& index) const override;
    void setEditorData(QWidget* editor, const QModelIndex& index) const override;
    void setModelData(QWidget* editor, QAbstractItemModel* model, const QModelIndex& index) const override;

signals:
    void refused(const QString& why) const;

private:
    OdTreeModel* model_;
};

}  // namespace coscope::gui
