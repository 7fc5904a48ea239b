// SPDX-License-Identifier: GPL-3.0-or-later
// Placeholder: being implemented.
#include "app/gui/wizards/common/ScriptPreview.h"

namespace coscope::gui {

namespace {
canopen::CommandScript& placeholder() {
    static canopen::CommandScript s;
    return s;
}
}  // namespace

ScriptPreview::ScriptPreview(QWidget* parent) : QWidget(parent) {}
void ScriptPreview::setScript(const canopen::CommandScript& script) { placeholder() = script; }
const canopen::CommandScript& ScriptPreview::script() const { return placeholder(); }
void ScriptPreview::markStep(int, bool, const QString&) {}
bool ScriptPreview::saveTo(const QString&, QString*) const { return false; }
int ScriptPreview::rowCount() const { return 0; }

}  // namespace coscope::gui
