// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/help/ShortcutsDialog.h"

#include <QAction>
#include <QDialogButtonBox>
#include <QDockWidget>
#include <QHeaderView>
#include <QMenu>
#include <QRegularExpression>
#include <QSet>
#include <QTreeWidget>
#include <QVBoxLayout>

#include <algorithm>
#include <tuple>

namespace coscope::gui::help {

namespace {
// A menu text as read: without its accelerator ("&Quit", "結束(&Q)") and ellipsis.
QString shortcutText(QString text) {
    static const QRegularExpression accelerator(QStringLiteral("\\(&[^)]\\)"));
    return text.remove(accelerator).remove(u'&').remove(QStringLiteral("…")).trimmed();
}

// The menu or dock an action is shown in (or belongs to).
QString shortcutWhere(const QAction* a) {
    for (QObject* o : a->associatedObjects())
        if (auto* menu = qobject_cast<QMenu*>(o); menu && !menu->title().isEmpty()) return shortcutText(menu->title());
    for (const QObject* o = a->parent(); o; o = o->parent()) {
        if (auto* menu = qobject_cast<const QMenu*>(o); menu && !menu->title().isEmpty())
            return shortcutText(menu->title());
        if (auto* dock = qobject_cast<const QDockWidget*>(o)) return shortcutText(dock->windowTitle());
    }
    return {};
}
}  // namespace

QList<ShortcutsDialog::Entry> ShortcutsDialog::collect(const QWidget* window) {
    QList<Entry> out;
    QSet<const QAction*> seen;
    for (const QAction* a : window->findChildren<QAction*>()) {
        if (a->shortcuts().isEmpty() || a->isSeparator() || seen.contains(a)) continue;
        seen.insert(a);
        QStringList keys;
        for (const QKeySequence& k : a->shortcuts()) keys << k.toString(QKeySequence::NativeText);
        const QString text = shortcutText(a->text());
        out.push_back(
            {keys.join(QStringLiteral(", ")), text.isEmpty() ? shortcutText(a->toolTip()) : text, shortcutWhere(a)});
    }
    std::sort(out.begin(), out.end(),
              [](const Entry& x, const Entry& y) { return std::tie(x.where, x.action) < std::tie(y.where, y.action); });
    return out;
}

ShortcutsDialog::ShortcutsDialog(QWidget* window) : QDialog(window) {
    setObjectName(QStringLiteral("shortcutsDialog"));
    setWindowTitle(tr("Keyboard shortcuts"));
    resize(560, 480);
    auto* layout = new QVBoxLayout(this);
    list_ = new QTreeWidget(this);
    list_->setObjectName(QStringLiteral("shortcutsList"));
    list_->setRootIsDecorated(false);
    list_->setHeaderLabels({tr("Keys"), tr("Action"), tr("Where")});
    for (const Entry& e : collect(window))
        list_->addTopLevelItem(new QTreeWidgetItem(QStringList{e.keys, e.action, e.where}));
    list_->header()->setSectionResizeMode(QHeaderView::ResizeToContents);
    layout->addWidget(list_);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    layout->addWidget(buttons);
}

}  // namespace coscope::gui::help
