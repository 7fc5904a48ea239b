// SPDX-License-Identifier: GPL-3.0-or-later
// Folder app/gui/files/ owns what a user expects of files: dialogs that start where the last
// file of that kind was (LastFolders), and lists of recent files in menus (RecentFiles).
#pragma once

#include <QString>

class QWidget;

namespace coscope::gui::files {

// Kinds of file, each with its own last folder (QSettings "files/lastFolder/KIND"). Another part
// of the app may use a kind of its own ("projects"): any short key works.
inline constexpr char kLogs[] = "logs";                  // logs opened, replayed, saved
inline constexpr char kExports[] = "exports";            // filtered rows, plot CSV
inline constexpr char kDictionaries[] = "dictionaries";  // DCF/EDS exported or applied
inline constexpr char kPlotImages[] = "plot-images";     // plot PNG/PDF
inline constexpr char kScripts[] = "scripts";            // wizard command scripts
inline constexpr char kDbc[] = "dbc";                    // PDO layouts as DBC
inline constexpr char kPrograms[] = "programs";          // program (firmware) images
inline constexpr char kProjects[] = "projects";          // project files

// Where a dialog for `kind` starts: the folder of the last file of that kind, while it exists;
// else the user's Documents folder, else home (never the process's working folder).
QString startFolder(const QString& kind);
// Remembers the folder of `chosenPath` (a file) for `kind`.
void rememberFolder(const QString& kind, const QString& chosenPath);

// QFileDialog::getOpenFileName / getSaveFileName starting in startFolder(kind) (a save proposes
// `suggestedName` there); the chosen file's folder is remembered. Empty when cancelled.
QString askOpenFile(QWidget* parent, const QString& kind, const QString& caption, const QString& filter = {});
// `selectedFilter`, when given, receives the filter the user chose.
QString askSaveFile(QWidget* parent, const QString& kind, const QString& caption, const QString& suggestedName = {},
                    const QString& filter = {}, QString* selectedFilter = nullptr);

}  // namespace coscope::gui::files
