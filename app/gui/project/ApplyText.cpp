// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/project/ApplyText.h"

#include <QTextStream>

namespace coscope::gui {

using project::NodeApplyState;
using project::objectKey;

QString ApplyText::nodeText(uint8_t node, const QString& name) {
    return name.isEmpty() ? tr("Node %1").arg(node) : tr("Node %1 (%2)").arg(node).arg(name);
}

QString ApplyText::notWrittenReason(const project::NodeApplyPlan& p) {
    switch (p.match) {
    case project::NodeMatch::Missing: return tr("the node does not answer");
    case project::NodeMatch::DifferentDevice: return tr("another device answers at this node-ID");
    case project::NodeMatch::NotInProject: return tr("not in the project");
    default: return tr("no dictionary for the node (%1)").arg(p.error);  // core's words: the file's problem
    }
}

QString ApplyText::stateText(NodeApplyState s) {
    switch (s) {
    case NodeApplyState::Written: return tr("written");
    case NodeApplyState::NothingToWrite: return tr("nothing to write, already as in the project");
    case NodeApplyState::RefusedRolledBack: return tr("refused, old values put back");
    case NodeApplyState::RefusedRollbackFailed: return tr("refused, old values NOT all put back");
    case NodeApplyState::NotReached: return tr("not written: a node before refused");
    case NodeApplyState::Skipped: return tr("skipped");
    }
    return {};
}

QString ApplyText::plan(const std::vector<project::NodeApplyPlan>& plans) {
    QString text;
    QTextStream out(&text);
    for (const project::NodeApplyPlan& p : plans) {
        if (!p.writable()) {
            out << tr("%1: not written: %2").arg(nodeText(p.node, p.name), notWrittenReason(p)) << "\n";
            continue;
        }
        out << tr("%1: %n SDO write(s)", nullptr, static_cast<int>(p.plan.writes.size())).arg(nodeText(p.node, p.name))
            << "\n";
        for (const canopen::PlannedWrite& w : p.plan.writes) {
            const QString line = tr("write %1 %2 = %3").arg(objectKey(w.index, w.sub), w.name, w.valueText);
            out << "  " << (w.currentText.isEmpty() ? line : tr("%1  (now %2)").arg(line, w.currentText)) << "\n";
        }
    }
    return text;
}

QString ApplyText::report(const project::ApplyReport& report, const std::vector<project::NodeApplyPlan>& plans) {
    QString text;
    QTextStream out(&text);
    for (const project::NodeApplyResult& n : report.nodes) {
        QString line = tr("%1: %2").arg(nodeText(n.node, n.name), stateText(n.state));
        if (n.state == NodeApplyState::Written) {
            line += tr(" - %n object(s) written", nullptr, static_cast<int>(n.writes.size()));
        } else if (n.state == NodeApplyState::Skipped) {
            for (const project::NodeApplyPlan& p : plans)
                if (p.node == n.node) line += QStringLiteral(" - ") + notWrittenReason(p);
        }
        out << line << "\n";
        for (const canopen::ConfigEntryResult& e : n.writes) {
            const QString what = QStringLiteral("%1 %2 = %3").arg(objectKey(e.index, e.sub), e.name, e.valueText);
            out << "  " << (e.ok ? tr("written: %1").arg(what) : tr("REFUSED: %1: %2").arg(what, e.error)) << "\n";
        }
        for (const canopen::ConfigEntryResult& e : n.rollback) {
            const QString what = QStringLiteral("%1 %2 = %3").arg(objectKey(e.index, e.sub), e.name, e.valueText);
            out << "  " << (e.ok ? tr("put back: %1").arg(what) : tr("NOT put back: %1: %2").arg(what, e.error))
                << "\n";
        }
    }
    return text;
}

}  // namespace coscope::gui
