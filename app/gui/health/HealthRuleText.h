// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "dissectors/HealthReport.h"

#include <QString>

#include <span>

namespace coscope::gui {

enum class RulePart { What, Why, Check };

// A finding's sentence in the UI language: its rule's text (dissectors/HealthRules.h) looked up
// in context "HealthRules", filled with the finding's values (each through coreText()).
QString healthRuleText(const dissect::HealthFinding& f, RulePart part);

// Every sentence listed for lupdate, for the test that keeps them equal to the rule table.
std::span<const char* const> healthRuleTexts();

}  // namespace coscope::gui
