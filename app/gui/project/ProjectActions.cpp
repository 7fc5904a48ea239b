// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/project/ProjectActions.h"

#include "app/gui/files/LastFolders.h"

#include "app/gui/nodes/NodesDock.h"
#include "app/gui/project/ApplyDialog.h"
#include "app/gui/project/CompareDialog.h"
#include "app/gui/project/ProjectProgram.h"
#include "app/gui/project/ProjectSession.h"
#include "app/gui/session/Workspace.h"
#include "core/project/ProjectBackup.h"
#include "eds/ProjectDictionaries.h"
#include "eds/ScanMatcher.h"

#include <QCoreApplication>
#include <QFileInfo>
#include <QMainWindow>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>
#include <QPointer>

namespace coscope::gui {

namespace {
QString projectFilter() { return ProjectActions::tr("CoScope projects (*.coscope *.coscope.json);;All files (*)"); }
}  // namespace

ProjectActions::ProjectActions(Workspace* workspace, QMainWindow* window, Connector connector)
    : QObject(window), workspace_(workspace), window_(window), connect_(std::move(connector)),
      session_(new ProjectSession(workspace, this)) {
    connect(session_, &ProjectSession::changed, this, &ProjectActions::updateTitle);
    // A backup whose bus closes half-way (Disconnect, another bus, a lost adapter) cannot finish:
    // its SDO client is gone. Say so, and keep the project as it was.
    if (workspace_)
        connect(workspace_, &Workspace::aboutToDisconnect, this, [this] {
            if (!backingUp_) return;
            backingUp_ = false;
            if (backup_) backup_->deleteLater();
            backup_ = nullptr;
            const QString text = tr("The bus closed before the backup was finished: the project is as it was.");
            emit message(text);
            QMetaObject::invokeMethod(
                this, [this, text] { QMessageBox::warning(window_, tr("Back up the machine"), text); },
                Qt::QueuedConnection);
        });
}

void ProjectActions::addTo(QMenu* file, QMenuBar* bar) {
    QAction* first = file->actions().value(0);
    auto add = [&](const QString& text, auto slot) {
        auto* a = new QAction(text, file);
        connect(a, &QAction::triggered, this, slot);
        file->insertAction(first, a);
        return a;
    };
    add(tr("&New project"), [this] { newProject(); });
    add(tr("Open &project…"), [this] {
        if (!maybeSave()) return;
        const QString path = files::askOpenFile(window_, files::kProjects, tr("Open project"), projectFilter());
        if (!path.isEmpty()) openProject(path);
    });
    add(tr("Save pro&ject"), [this] { saveProject(); });
    add(tr("Save project &as…"), [this] { saveProjectAs(); });
    recent_ = new QMenu(tr("Recent pro&jects"), file);
    file->insertMenu(first, recent_);
    file->insertSeparator(first);
    rebuildRecent();

    QMenu* menu = new QMenu(tr("&Project"), bar);
    // Before the View menu: File, Bus, Commission, Project, View.
    QAction* before = nullptr;
    for (QAction* a : bar->actions())
        if (a->menu() && a->menu()->title() == QCoreApplication::translate("coscope::gui::MainWindow", "&View"))
            before = a;
    bar->insertMenu(before, menu);
    menu->addAction(tr("&Compare with the machine…"), this, [this] { showCompare(); });
    menu->addAction(tr("&Back up the machine"), this, &ProjectActions::backUpMachine);
    menu->addAction(tr("&Apply the project…"), this, [this] { showCompare(false)->openApply({}); });
    addProgramToNodes();
    updateTitle();
}

// The Nodes dock's context menu ▸ "Download the project's program…": the program download dialog
// (CiA 302-3, its own confirmations) with the image and program number the project names for the
// selected node; enabled only for such a node.
void ProjectActions::addProgramToNodes() {
    auto* nodes = window_->findChild<NodesDock*>();
    if (!nodes) return;
    auto* action = new QAction(tr("Download the project's program…"), this);
    action->setObjectName(QStringLiteral("projectProgramAction"));
    action->setToolTip(
        tr("Load the program (firmware) the project names for the selected node: CiA 302-3 program download"));
    QPointer<NodesDock> dock(nodes);
    auto update = [this, action, dock] {
        action->setEnabled(dock && !ProjectProgram::imageFile(*session_, dock->selectedNode()).isEmpty() &&
                           workspace_ && workspace_->canTransmit());
    };
    connect(nodes, &NodesDock::nodeSelected, action, update);
    connect(session_, &ProjectSession::changed, action, update);
    update();
    connect(action, &QAction::triggered, this, [this, dock] {
        if (!dock || dock->selectedNode() < 1) return;
        const int node = dock->selectedNode();
        ProjectProgram::preset(dock->openProgramDownload(node), *session_, node, window_);
    });
    nodes->addNodeAction(action);
}

void ProjectActions::rebuildRecent() {
    if (!recent_) return;
    recent_->clear();
    const QStringList list = ProjectSession::recent();
    for (const QString& path : list)
        recent_
            ->addAction(QFileInfo(path).fileName(), this,
                        [this, path] {
                            if (maybeSave()) openProject(path);
                        })
            ->setToolTip(path);
    recent_->setEnabled(!list.isEmpty());
}

void ProjectActions::showProblem(const QString& title, const QString& text) {
    emit message(text);
    QMessageBox::warning(window_, title, text);
}

void ProjectActions::updateTitle() {
    const QString source = workspace_ ? workspace_->sourceName() : QString();
    QStringList parts;
    if (session_->isOpen()) parts << session_->displayName() + QStringLiteral("[*]");
    if (!source.isEmpty()) parts << source;
    parts << QStringLiteral("CoScope");
    window_->setWindowTitle(parts.join(QStringLiteral(" — ")));
    window_->setWindowModified(session_->isOpen() && session_->isModified());
}

bool ProjectActions::maybeSave() {
    if (!session_->isOpen() || !session_->isModified()) return true;
    QMessageBox box(
        QMessageBox::Question, tr("Unsaved project"),
        tr("The project \"%1\" has changes that are not saved. Save the project first?").arg(session_->displayName()),
        QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, window_);
    box.setDefaultButton(QMessageBox::Save);
    switch (box.exec()) {
    case QMessageBox::Save: return saveProject();
    case QMessageBox::Discard: return true;
    default: return false;
    }
}

void ProjectActions::newProject() {
    if (!maybeSave()) return;
    session_->newProject();
    emit message(tr("New project: Project ▸ Back up the machine reads the drives into it"));
}

bool ProjectActions::openProject(const QString& path) {
    QString error;
    if (!session_->open(path, &error)) {
        showProblem(tr("Open project"), error);
        return false;
    }
    rebuildRecent();
    emit message(tr("Project %1 opened").arg(path));
    const QString url = session_->project().busUrl;
    const bool connected = workspace_ && workspace_->bus() && workspace_->bus()->url().toString() == url;
    if (!url.isEmpty() && !connected && connect_) {
        QMessageBox box(QMessageBox::Question, tr("Open project"), tr("Connect to the project's bus %1?").arg(url),
                        QMessageBox::Yes | QMessageBox::No, window_);
        box.setDefaultButton(QMessageBox::Yes);
        if (box.exec() == QMessageBox::Yes) connect_(url);
    }
    return true;
}

bool ProjectActions::saveProject() {
    if (session_->path().isEmpty()) return saveProjectAs();
    QString error;
    if (!session_->save(session_->path(), &error)) {
        showProblem(tr("Save project"), error);
        return false;
    }
    emit message(tr("Project saved to %1").arg(session_->path()));
    return true;
}

bool ProjectActions::saveProjectAs() {
    const QString name =
        session_->path().isEmpty() ? QStringLiteral("machine.coscope") : QFileInfo(session_->path()).fileName();
    QString path = files::askSaveFile(window_, files::kProjects, tr("Save project"), name, projectFilter());
    if (path.isEmpty()) return false;
    if (!path.endsWith(QLatin1String(".coscope")) && !path.endsWith(QLatin1String(".coscope.json")))
        path += QStringLiteral(".coscope");
    QString error;
    if (!session_->save(path, &error)) {
        showProblem(tr("Save project"), error);
        return false;
    }
    rebuildRecent();
    emit message(tr("Project saved to %1").arg(path));
    return true;
}

void ProjectActions::backUpMachine() {
    if (backingUp_) return;
    if (!workspace_ || !workspace_->sdo() || !workspace_->canTransmit()) {
        showProblem(tr("Back up the machine"),
                    tr("Connect to the machine's bus first (not listen-only): the backup reads the drives."));
        return;
    }
    if (!session_->isOpen()) session_->newProject();
    backingUp_ = true;
    emit message(tr("Backing up the machine: reading every drive…"));
    auto* backup = new project::ProjectBackup(
        *workspace_->sdo(), eds::projectDictionaryResolver(QFileInfo(session_->path()).absolutePath()), this);
    backup->setMatcher(eds::scanMatcher());
    backup_ = backup;
    project::Project start = session_->project();
    if (start.busUrl.isEmpty()) start.busUrl = workspace_->bus()->url().toString();
    QPointer<ProjectActions> self(this);
    backup->start(
        start,
        [self](const QString& what, int, int) {
            if (self) emit self->message(tr("Backing up the machine: %1").arg(what));
        },
        [self, backup](const project::Project& result, const std::vector<project::BackupNodeResult>& nodes) {
            backup->deleteLater();
            if (!self) return;
            self->backingUp_ = false;
            self->backup_ = nullptr;
            self->session_->setProject(result);
            QStringList lines;
            for (const auto& n : nodes)
                lines << (n.ok ? tr("Node %1: %2") : tr("Node %1: NOT backed up: %2")).arg(n.node).arg(n.message);
            emit self->message(tr("Backup done: %n node(s)", nullptr, static_cast<int>(nodes.size())));
            // Shown once the SDO client's callback has returned (no nested loop inside it).
            const QString text = tr("The drives' configuration is in the project; save the project to keep it.") +
                                 QStringLiteral("\n\n") + lines.join(u'\n');
            QMetaObject::invokeMethod(
                self,
                [self, text] {
                    if (self) QMessageBox::information(self->window_, tr("Back up the machine"), text);
                },
                Qt::QueuedConnection);
        });
}

CompareDialog* ProjectActions::showCompare(bool run) {
    if (!compare_) {
        compare_ = new CompareDialog(*session_, workspace_, window_);
        compare_->setAttribute(Qt::WA_DeleteOnClose);
    }
    compare_->show();
    compare_->raise();
    if (run) compare_->compare();
    return compare_;
}

}  // namespace coscope::gui
