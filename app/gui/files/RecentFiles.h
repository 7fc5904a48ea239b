// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QObject>
#include <QStringList>

#include <functional>

class QMenu;

namespace coscope::gui {

// A list of the most recent entries of one kind (newest first, no duplicates, at most `max`),
// kept in QSettings under `settingsKey`. One model for every recent list of the app: recent
// logs ("files/recent/logs"), recent connections (RecentConnections), recent projects.
class RecentList {
public:
    explicit RecentList(QString settingsKey, int max = 8);
    QStringList list() const;
    void add(const QString& entry);
    void remove(const QString& entry);
    void clear();

private:
    QString key_;
    int max_;
};

// A "Recent …" submenu of files: the newest first, numbered, the full path in the tooltip;
// a file that no longer exists is shown disabled and says so; "Clear recent" at the end.
// Built again each time `parent` opens, so it always shows what the list holds now (the
// submenu is disabled while the list is empty). Choosing a file calls `open(path)`.
class RecentFilesMenu : public QObject {
    Q_OBJECT
public:
    // QSettings keys of the app's recent file lists.
    static constexpr const char* kLogs = "files/recent/logs";
    static constexpr const char* kProjects = "files/recent/projects";

    RecentFilesMenu(QMenu* parent, const QString& title, const QString& settingsKey,
                    std::function<void(const QString&)> open);
    QMenu* menu() const { return menu_; }
    RecentList& list() { return list_; }

private:
    void rebuild();
    QMenu* menu_;
    RecentList list_;
    std::function<void(const QString&)> open_;
};

}  // namespace coscope::gui
