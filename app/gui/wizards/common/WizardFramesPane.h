// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QWidget>

#include <cstdint>
#include <memory>

namespace coscope::gui {

class Workspace;

// The frames pane every wizard shows: each request and response on the bus since markStart(),
// for the wizard's node: SDO, boot-up/heartbeat, EMCY (plus NMT and LSS; no SYNC or PDOs,
// whose cyclic traffic would bury the answers), decoded by the workspace's decoder (time,
// direction, COB-ID, data, summary). Pulls from the trace store on its own ≤ 30 Hz timer.
class WizardFramesPane : public QWidget {
    Q_OBJECT
public:
    explicit WizardFramesPane(Workspace* workspace, QWidget* parent = nullptr);
    ~WizardFramesPane() override;

    void setNode(int node);  // -1 = every node
    void markStart();        // show only frames from now on
    int rowCount() const;
    QString rowText(int row) const;  // "Tx 605 2B 40 60 00 06 00 00 00  SDO write 6040h:00 …"

    // Pulls the frames that arrived since the last pull (the pane's timer calls this at 25 Hz;
    // tests may call it directly). Rows are appended, never reset, and the view follows the end.
    void poll();

private:
    struct Private;
    std::unique_ptr<Private> d_;
};

}  // namespace coscope::gui
