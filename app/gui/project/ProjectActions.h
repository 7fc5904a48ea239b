// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "app/gui/project/CompareDialog.h"

#include <QObject>
#include <QPointer>

#include <functional>

class QMainWindow;
class QMenu;
class QMenuBar;

namespace coscope::gui {

class ProjectSession;
class Workspace;

// The project's place in the window: File ▸ New project / Open project… / Save project / Save
// project as… / Recent projects, the Project menu (compare with the machine, back up the machine,
// apply the project), the title bar ("name* — source — CoScope") and the question about unsaved
// project changes. The main window only calls addTo(), maybeSave() and updateTitle().
class ProjectActions : public QObject {
    Q_OBJECT
public:
    using Connector = std::function<bool(const QString& url)>;
    ProjectActions(Workspace* workspace, QMainWindow* window, Connector connector);

    void addTo(QMenu* file, QMenuBar* bar);
    // Before the project is replaced or the window closes: "save the project first?". True = go on.
    bool maybeSave();
    void updateTitle();

    ProjectSession* session() const { return session_; }
    CompareDialog* compareDialog() const { return compare_; }

    void newProject();
    bool openProject(const QString& path);
    bool saveProject();  // Save as… when it has no file yet
    bool saveProjectAs();
    void backUpMachine();
    CompareDialog* showCompare(bool run = true);

signals:
    void message(const QString& text);

private:
    void rebuildRecent();
    void addProgramToNodes();
    void showProblem(const QString& title, const QString& text);
    Workspace* workspace_;
    QMainWindow* window_;
    Connector connect_;
    ProjectSession* session_;
    QPointer<QMenu> recent_;
    QPointer<CompareDialog> compare_;
    bool backingUp_ = false;
    // The backup running (nullptr when none): ended, and said so, when its bus closes.
    QPointer<QObject> backup_;
};

}  // namespace coscope::gui
