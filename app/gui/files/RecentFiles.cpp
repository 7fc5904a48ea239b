// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/files/RecentFiles.h"

#include <QDir>
#include <QFileInfo>
#include <QMenu>
#include <QSettings>

#include <utility>

namespace coscope::gui {

RecentList::RecentList(QString settingsKey, int max) : key_(std::move(settingsKey)), max_(max) {}

QStringList RecentList::list() const { return QSettings().value(key_).toStringList(); }

void RecentList::add(const QString& entry) {
    QStringList l = list();
    l.removeAll(entry);
    l.prepend(entry);
    while (l.size() > max_) l.removeLast();
    QSettings().setValue(key_, l);
}

void RecentList::remove(const QString& entry) {
    QStringList l = list();
    if (l.removeAll(entry) > 0) QSettings().setValue(key_, l);
}

void RecentList::clear() { QSettings().remove(key_); }

RecentFilesMenu::RecentFilesMenu(QMenu* parent, const QString& title, const QString& settingsKey,
                                 std::function<void(const QString&)> open)
    : QObject(parent), menu_(parent->addMenu(title)), list_(settingsKey), open_(std::move(open)) {
    menu_->setToolTipsVisible(true);
    connect(parent, &QMenu::aboutToShow, this, &RecentFilesMenu::rebuild);
    rebuild();
}

void RecentFilesMenu::rebuild() {
    menu_->clear();
    const QStringList paths = list_.list();
    int n = 0;
    for (const QString& path : paths) {
        const QFileInfo info(path);
        // 1..9 as the accelerator, as desktop programs number their recent files.
        const QString number = ++n < 10 ? QStringLiteral("&%1 ").arg(n) : QString();
        QAction* a = menu_->addAction(number + info.fileName());
        if (info.exists()) {
            a->setToolTip(QDir::toNativeSeparators(path));
            connect(a, &QAction::triggered, this, [this, path] { open_(path); });
        } else {
            a->setText(tr("%1 (not found)").arg(a->text()));
            a->setToolTip(tr("%1 no longer exists").arg(QDir::toNativeSeparators(path)));
            a->setEnabled(false);
        }
    }
    if (!paths.isEmpty()) {
        menu_->addSeparator();
        menu_->addAction(tr("Clear recent"), this, [this] { list_.clear(); });
    }
    menu_->setEnabled(!paths.isEmpty());
}

}  // namespace coscope::gui
