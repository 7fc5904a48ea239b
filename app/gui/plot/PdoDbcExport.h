// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "app/gui/session/Job.h"
#include "core/trace/TraceStore.h"
#include "dissectors/NetworkContext.h"
#include "dissectors/RawSignal.h"

#include <QString>

#include <memory>
#include <vector>

class QWidget;

namespace coscope::gui {

class Workspace;

// File ▸ Export PDO layout as DBC: the PDO layout in force at the end of the workspace's trace
// (the nodes' dictionaries, then the SDO writes in the trace), with the user's raw signals,
// written by the same code as `coscope-cli pdo dbc` (dissectors/DbcExport.h). Every frame of
// the trace goes through the network context on a worker: frames paged out to the capture
// journal (issue 16) are read back there, never on the GUI thread.
class PdoDbcJob : public Job {
public:
    // Takes what it needs from the workspace now (on the GUI thread): the nodes' dictionaries,
    // the raw signals, the store and its size.
    PdoDbcJob(Workspace& workspace, QString path);
    ~PdoDbcJob() override;

    const QString& path() const { return path_; }
    // Once isDone() and not failed: "PDO layout exported to …"; failed: errorString().
    const QString& summary() const { return summary_; }

protected:
    void run() override;

private:
    QString path_;
    std::shared_ptr<const TraceStore> store_;
    size_t frames_ = 0;
    dissect::NetworkContext ctx_;
    std::vector<dissect::RawSignal> raw_;
    QString summary_;
};

// Asks for the DBC file name ("" when the user cancelled); adds ".dbc" when missing.
QString askPdoDbcPath(QWidget* parent);

}  // namespace coscope::gui
