// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Clicks a user makes on items: a check box in a tree or table cell (where the style draws it),
// a dock's tab when docks are tabified, and the plot's signal tree item by node and name.

#include <QMainWindow>
#include <QStyle>
#include <QStyleOptionViewItem>
#include <QTabBar>
#include <QTableView>
#include <QTest>
#include <QTreeWidget>

namespace coscope::testing {

// Clicks the check box of `item` (column 0) where the tree's style draws it; false when it is
// not on screen or the click changed nothing.
inline bool clickCheckBox(QTreeWidget* tree, QTreeWidgetItem* item) {
    const QRect row = tree->visualItemRect(item);
    if (!row.isValid() || !tree->viewport()->rect().contains(row.topLeft())) return false;
    QStyleOptionViewItem option;
    option.initFrom(tree->viewport());
    option.rect =
        QRect(row.left(), row.top(), tree->columnWidth(0) - (row.left() + tree->header()->offset()), row.height());
    option.features = QStyleOptionViewItem::HasCheckIndicator | QStyleOptionViewItem::HasDisplay;
    option.text = item->text(0);
    option.checkState = item->checkState(0);
    const QRect box = tree->style()->subElementRect(QStyle::SE_ItemViewItemCheckIndicator, &option, tree);
    if (!box.isValid()) return false;
    const Qt::CheckState was = item->checkState(0);
    QTest::mouseClick(tree->viewport(), Qt::LeftButton, {}, box.center());
    return item->checkState(0) != was;
}

// Clicks the check box of a table cell where the style draws it.
inline void clickCheckBox(QTableView* view, const QModelIndex& index) {
    QStyleOptionViewItem option;
    option.initFrom(view->viewport());
    option.rect = view->visualRect(index);
    option.features = QStyleOptionViewItem::HasCheckIndicator;
    const QRect box = view->style()->subElementRect(QStyle::SE_ItemViewItemCheckIndicator, &option, view);
    QTest::mouseClick(view->viewport(), Qt::LeftButton, {}, box.center());
}

// Clicks the tab of the dock titled `title` (docks tabified together); false when there is none.
inline bool clickDockTab(QMainWindow& w, const QString& title) {
    for (QTabBar* bar : w.findChildren<QTabBar*>())
        for (int i = 0; i < bar->count(); ++i)
            if (bar->tabText(i) == title) {
                QTest::mouseClick(bar, Qt::LeftButton, {}, bar->tabRect(i).center());
                return true;
            }
    return false;
}

// The plot's signal tree item `name` of node `node` ("Node 2" or "Node 2 (…)" group), also a
// bit under its word; null when not offered.
inline QTreeWidgetItem* signalItem(QTreeWidget* tree, int node, const QString& name) {
    const QString group = QStringLiteral("Node %1").arg(node);
    for (int i = 0; i < tree->topLevelItemCount(); ++i) {
        QTreeWidgetItem* g = tree->topLevelItem(i);
        if (g->text(0) != group && !g->text(0).startsWith(group + QStringLiteral(" ("))) continue;
        for (int k = 0; k < g->childCount(); ++k) {
            QTreeWidgetItem* word = g->child(k);
            if (word->text(0) == name) return word;
            for (int b = 0; b < word->childCount(); ++b)
                if (word->child(b)->text(0) == name) return word->child(b);
        }
    }
    return nullptr;
}

}  // namespace coscope::testing
