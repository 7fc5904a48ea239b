// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/plot/PdoDbcExport.h"

#include "app/gui/session/Workspace.h"
#include "dissectors/DbcExport.h"
#include "dissectors/NetworkContext.h"

#include <QCoreApplication>
#include <QFile>
#include <QFileDialog>

#include <spdlog/spdlog.h>

namespace coscope::gui {

namespace {
struct PdoDbcExport {
    Q_DECLARE_TR_FUNCTIONS(PdoDbcExport)
};
}  // namespace

bool writePdoLayoutDbc(Workspace& workspace, const QString& path, QString* summary) {
    dissect::NetworkContext ctx;
    for (const canopen::NodeInfo& n : workspace.nodes().snapshot()) {
        if (n.dictionary.isEmpty()) continue;
        QString error;
        if (!ctx.assignDictionary(n.node, n.dictionary, &error)) spdlog::warn("DBC export: node {}: {}", n.node, error.toStdString());
    }
    // The layout the trace leaves in force: every frame through the context, as the CLI does.
    const TraceStore& store = *workspace.store();
    dissect::Dissection d;
    const size_t total = store.size();
    for (size_t i = 0; i < total; ++i) ctx.dissect(store.frame(static_cast<FrameNo>(i)), d, dissect::Dissection::Level::Stats);
    int pdos = 0;
    const QByteArray dbc = dissect::pdoLayoutDbc(ctx, workspace.rawSignals(), 0, &pdos);
    QFile f(path);
    if (!f.open(QIODevice::WriteOnly | QIODevice::Truncate) || f.write(dbc) != dbc.size() || !f.flush()) {
        if (summary) *summary = PdoDbcExport::tr("%1: cannot write the DBC file (%2)").arg(path, f.errorString());
        return false;
    }
    if (summary)
        *summary = PdoDbcExport::tr("PDO layout exported to %1: %2 PDO messages, %3 raw signals").arg(path).arg(pdos).arg(workspace.rawSignals().size());
    return true;
}

void exportPdoLayoutDbc(Workspace& workspace, QWidget* parent, const std::function<void(const QString&)>& report) {
    QString path = QFileDialog::getSaveFileName(parent, PdoDbcExport::tr("Export PDO layout as DBC"), QStringLiteral("pdo-layout.dbc"), PdoDbcExport::tr("DBC file (*.dbc)"));
    if (path.isEmpty()) return;
    if (!path.endsWith(QStringLiteral(".dbc"), Qt::CaseInsensitive)) path += QStringLiteral(".dbc");
    QString summary;
    writePdoLayoutDbc(workspace, path, &summary);
    report(summary);
}

}  // namespace coscope::gui
