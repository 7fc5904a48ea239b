// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QString>
#include <QStringList>

#include <span>

namespace coscope::dissect {

// The rules of the health report's findings (issue 37), one row per stable id: the default
// severity (HealthFinding::Severity) and three English sentences, what happened, why it matters
// and what to check, with %1.. for the values a finding carries (HealthFinding::args). The one
// place of these texts: the CLI writes them as they are, the GUI looks each up in context
// "HealthRules" (app/gui/health/HealthRuleText.cpp lists them for lupdate; a test keeps the two
// lists equal) and fills in the same values.
struct HealthRule {
    const char* id;
    int severity;
    const char* what;
    const char* why;
    const char* check;
};

std::span<const HealthRule> healthRules();
const HealthRule* healthRule(const QString& id);  // nullptr when unknown
// `text` with %1.. replaced by `args` in one pass (a value that contains "%2" stays as it is).
QString fillRule(const QString& text, const QStringList& args);

}  // namespace coscope::dissect
