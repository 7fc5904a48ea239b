// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "dissectors/Dissection.h"
#include "dissectors/SignalCatalog.h"

#include <QString>

namespace coscope::gui {

// The dissectors write the object names of the dictionaries as the EDS has them ("6041:00
// Statusword = …"), for the CLI. When those names come from a bundled dictionary
// (Dissection::namesFrom), the GUI shows the standard objects in its language
// (dissectors/ObjectNames.h): `english` (a summary, a field name or value of this frame) with the
// name of each object the frame refers to (its SDO object, its transfer's, its PDO signals')
// replaced. Applied before coreText()/coreLines(). In English, and for a user's dictionary, the
// text is returned as it is.
QString localObjectNames(const dissect::Dissection& d, const QString& english);

// The name of a transfer's object (SdoTransferRecord::name) in the UI language, for the trace's
// SDO transfer rows and the details pane.
QString localObjectName(const dissect::SdoTransferRecord& t);

// A plot signal's name (SignalInfo::name: the object's, "Statusword: fault" for a bit) in the UI
// language, when its node's dictionary is a bundled one; a bit's name through coreText().
QString localSignalName(const dissect::SignalInfo& s);

}  // namespace coscope::gui
