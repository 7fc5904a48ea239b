// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QObject>
#include <QPointer>

#include <set>

namespace coscope::canopen {
class SdoClient;
}  // namespace coscope::canopen

namespace coscope::gui {

// The window's side of the network scan: core's NetworkScan (the one scanner, also the CLI's
// `scan` and the project's), with the bundled dictionaries as its matcher, run by the Nodes dock
// and the wizards. The results go into the bus's node table (the NodeTable of the SDO client's
// MasterContext). Never blocks.
class NodeScanner : public QObject {
    Q_OBJECT
public:
    explicit NodeScanner(canopen::SdoClient* sdo, QObject* parent = nullptr);

    // Nodes first..last; a technician waits for this one, so it asks more node-IDs at a time
    // (kOutstanding) than NetworkScan's default.
    void scan(int firstNode = 1, int lastNode = 127, int timeoutMs = 300);
    // One node again (its identity and strings), e.g. when it is selected.
    void identify(int node);
    bool isRunning() const { return running_ > 0; }
    int found() const { return static_cast<int>(found_.size()); }

    static constexpr int kOutstanding = 32;

signals:
    void finished(int nodesFound);

private:
    void run(int first, int last, int timeoutMs, bool report);
    QPointer<canopen::SdoClient> sdo_;  // null once its bus closed
    int running_ = 0;
    std::set<int> found_;
};

}  // namespace coscope::gui
