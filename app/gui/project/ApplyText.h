// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/project/ProjectApply.h"

#include <QCoreApplication>

namespace coscope::gui {

// The Apply dialog's dry run and report in the UI language, built from ProjectApply's plans and
// results (the CLI keeps core's English: project::applyPlanText, applyReportText).
class ApplyText {
    Q_DECLARE_TR_FUNCTIONS(ApplyText)
public:
    static QString plan(const std::vector<project::NodeApplyPlan>& plans);
    // `plans`: the dry run the report belongs to (why a node was skipped).
    static QString report(const project::ApplyReport& report, const std::vector<project::NodeApplyPlan>& plans);
    static QString stateText(project::NodeApplyState state);

private:
    static QString nodeText(uint8_t node, const QString& name);
    static QString notWrittenReason(const project::NodeApplyPlan& plan);
};

}  // namespace coscope::gui
