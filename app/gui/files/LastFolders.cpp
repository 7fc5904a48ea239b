// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/files/LastFolders.h"

#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QSettings>
#include <QStandardPaths>

namespace coscope::gui::files {

namespace {
QString lastFolderKey(const QString& kind) { return QStringLiteral("files/lastFolder/") + kind; }
}  // namespace

QString startFolder(const QString& kind) {
    QString last = QSettings().value(lastFolderKey(kind)).toString();
    if (!last.isEmpty() && QFileInfo(last).isDir()) return last;
    QString documents = QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation);
    if (!documents.isEmpty() && QFileInfo(documents).isDir()) return documents;
    return QDir::homePath();
}

void rememberFolder(const QString& kind, const QString& chosenPath) {
    if (chosenPath.isEmpty()) return;
    QSettings().setValue(lastFolderKey(kind), QFileInfo(chosenPath).absolutePath());
}

QString askOpenFile(QWidget* parent, const QString& kind, const QString& caption, const QString& filter) {
    QString path = QFileDialog::getOpenFileName(parent, caption, startFolder(kind), filter);
    rememberFolder(kind, path);
    return path;
}

QString askSaveFile(QWidget* parent, const QString& kind, const QString& caption, const QString& suggestedName,
                    const QString& filter, QString* selectedFilter) {
    const QDir folder(startFolder(kind));
    QString path = QFileDialog::getSaveFileName(
        parent, caption, suggestedName.isEmpty() ? folder.path() : folder.filePath(suggestedName), filter,
        selectedFilter);
    rememberFolder(kind, path);
    return path;
}

}  // namespace coscope::gui::files
