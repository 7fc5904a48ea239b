// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/project/ProjectSession.h"

#include "app/gui/files/RecentFiles.h"

#include "app/gui/session/Workspace.h"
#include "core/project/ProjectFile.h"

#include <QFileInfo>
#include <QJsonDocument>
#include <QSettings>

namespace coscope::gui {

namespace {
const QString kTransmitKey = QStringLiteral("transmit/rows");  // TransmitModel
}  // namespace

ProjectSession::ProjectSession(Workspace* workspace, QObject* parent) : QObject(parent), workspace_(workspace) {}

QString ProjectSession::displayName() const {
    if (!project_.name.isEmpty()) return project_.name;
    if (!path_.isEmpty()) return QFileInfo(path_).completeBaseName().remove(QStringLiteral(".coscope"));
    return tr("Untitled project");
}

void ProjectSession::newProject() {
    project_ = {};
    if (workspace_ && workspace_->bus()) project_.busUrl = workspace_->bus()->url().toString();
    path_.clear();
    open_ = true;
    modified_ = false;
    emit changed();
}

bool ProjectSession::open(const QString& path, QString* error) {
    const project::ProjectReadResult r = project::ProjectFile::read(path);
    if (!r.project) {
        if (error) *error = r.error;
        return false;
    }
    project_ = *r.project;
    path_ = QFileInfo(path).absoluteFilePath();
    open_ = true;
    modified_ = false;
    restoreSettings();
    addRecent(path_);
    emit changed();
    return true;
}

bool ProjectSession::save(const QString& path, QString* error) {
    captureSettings();
    if (project_.busUrl.isEmpty() && workspace_ && workspace_->bus())
        project_.busUrl = workspace_->bus()->url().toString();
    if (!project::ProjectFile::write(project_, path, error)) return false;
    path_ = QFileInfo(path).absoluteFilePath();
    open_ = true;
    modified_ = false;
    addRecent(path_);
    emit changed();
    return true;
}

void ProjectSession::setProject(const project::Project& project) {
    project_ = project;
    open_ = true;
    modified_ = true;
    emit changed();
}

void ProjectSession::captureSettings() {
    QSettings s;
    QJsonObject master;
    s.beginGroup(QStringLiteral("master"));
    for (const QString& key : s.childKeys()) master.insert(key, QJsonValue::fromVariant(s.value(key)));
    s.endGroup();
    project_.master = master;
    project_.transmit = QJsonDocument::fromJson(s.value(kTransmitKey).toByteArray()).array();
    QJsonArray raw;
    if (workspace_)
        for (const auto& signal : workspace_->rawSignals()) raw.append(signal.spec());
    project_.rawSignals = raw;
    if (plots_.capture) project_.plots = plots_.capture();
    if (traceFilters_.capture) project_.traceFilters = traceFilters_.capture();
}

// SYNC/heartbeat settings are read from QSettings each time they are used, the transmit list when
// settingsRestored() reloads it; raw signals are added to the workspace, plot layouts and trace
// filters given to their docks at once.
void ProjectSession::restoreSettings() {
    QSettings s;
    for (auto it = project_.master.begin(); it != project_.master.end(); ++it)
        s.setValue(QStringLiteral("master/") + it.key(), it.value().toVariant());
    s.setValue(kTransmitKey,
               QJsonDocument(project_.transmit).toJson(QJsonDocument::Compact));  // a project without rows has none
    emit settingsRestored();
    if (plots_.restore) plots_.restore(project_.plots);
    if (traceFilters_.restore) traceFilters_.restore(project_.traceFilters);
    if (!workspace_) return;
    for (const QJsonValue v : project_.rawSignals) {
        const auto signal = dissect::RawSignal::parse(v.toString());
        if (!signal) continue;
        const auto& have = workspace_->rawSignals();
        if (std::none_of(have.begin(), have.end(),
                         [&](const dissect::RawSignal& h) { return h.spec() == signal->spec(); }))
            workspace_->addRawSignal(*signal);
    }
}

// The app's one model of recent lists (RecentFiles.h).
QStringList ProjectSession::recent() { return RecentList(QString::fromLatin1(RecentFilesMenu::kProjects)).list(); }

void ProjectSession::addRecent(const QString& path) {
    RecentList(QString::fromLatin1(RecentFilesMenu::kProjects)).add(path);
}

}  // namespace coscope::gui
