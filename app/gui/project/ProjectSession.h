// SPDX-License-Identifier: GPL-3.0-or-later
// Folder app/gui/project/ owns the project in the window (README "Projects"): the open project and
// its file (ProjectSession), the File and Project menu actions (ProjectActions), the comparison
// view (CompareDialog), applying the project (ApplyDialog) and replacing a drive.
#pragma once

#include "core/project/Project.h"

#include <QObject>
#include <QStringList>

#include <functional>

namespace coscope::gui {

class Workspace;

// The project open in the window: what it holds, its file and whether it changed since it was
// saved. The window's settings a project keeps (SYNC/heartbeat, transmit list, raw signals) live
// in QSettings while the app runs: they are copied into the project when it is saved and out of
// it when it is opened. No widgets.
class ProjectSession : public QObject {
    Q_OBJECT
public:
    explicit ProjectSession(Workspace* workspace, QObject* parent = nullptr);

    const project::Project& project() const { return project_; }
    QString path() const { return path_; }
    bool isOpen() const { return open_; }
    bool isModified() const { return modified_; }
    // The name shown in the title bar: the project's name, else the file's, else "Untitled project".
    QString displayName() const;

    void newProject();
    bool open(const QString& path, QString* error);
    bool save(const QString& path, QString* error);
    // A backup's result, or any change made to the project: marks it modified.
    void setProject(const project::Project& project);

    // A part of the window a project keeps that does not live in QSettings: read when the project
    // is saved, given back when it is opened (MainWindow binds the Plot and Trace docks).
    struct Part {
        std::function<QJsonObject()> capture;
        std::function<void(const QJsonObject&)> restore;
    };
    void bindPlots(Part part) { plots_ = std::move(part); }
    void bindTraceFilters(Part part) { traceFilters_ = std::move(part); }

    // Recent project files, newest first (RecentList "files/recent/projects").
    static QStringList recent();
    static void addRecent(const QString& path);

signals:
    void changed();  // opened, saved, modified
    // A project was opened: the transmit list and SYNC/heartbeat settings in QSettings are the
    // project's now (the Transmit dock reloads its rows).
    void settingsRestored();

private:
    void captureSettings();  // the window's settings into project_
    void restoreSettings();  // project_'s settings into the window's
    Workspace* workspace_;
    project::Project project_;
    QString path_;
    bool open_ = false;
    bool modified_ = false;
    Part plots_, traceFilters_;
};

}  // namespace coscope::gui
