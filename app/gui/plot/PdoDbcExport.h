// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QString>

#include <functional>

class QWidget;

namespace coscope::gui {

class Workspace;

// File ▸ Export PDO layout as DBC: the PDO layout in force at the end of the workspace's trace
// (the nodes' dictionaries, then the SDO writes in the trace), with the user's raw signals,
// written by the same code as `coscope-cli pdo dbc` (dissectors/DbcExport.h).
bool writePdoLayoutDbc(Workspace& workspace, const QString& path, QString* summary);
// Asks for the file name, writes it; the result (or what went wrong) goes to `report`.
void exportPdoLayoutDbc(Workspace& workspace, QWidget* parent, const std::function<void(const QString&)>& report);

}  // namespace coscope::gui
