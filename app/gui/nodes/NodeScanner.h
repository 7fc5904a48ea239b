// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QObject>

#include <functional>
#include <set>

namespace coscope::canopen {
class MasterContext;
class SdoClient;
}  // namespace coscope::canopen

namespace coscope::gui {

class NodeTable;

// Network scan and identification through the SDO client (never blocks): reads 1000h (device
// type) from nodes 1..127 — a node that answers (even with an abort) exists — then its device
// name 1008h, hardware and software versions 1009h/100Ah and identity 1018h:01..04, and matches
// a dictionary from the library by identity. The optional ones a node lacks are "not present".
class NodeScanner : public QObject {
    Q_OBJECT
public:
    NodeScanner(canopen::SdoClient* sdo, NodeTable* table, QObject* parent = nullptr);

    void scan(int firstNode = 1, int lastNode = 127, int timeoutMs = 300);
    void identify(int node);
    bool isRunning() const { return outstanding_ > 0; }
    int found() const { return static_cast<int>(found_.size()); }

signals:
    void finished(int nodesFound);

private:
    void identifyThen(int node, std::function<void()> then);
    void done();
    canopen::SdoClient* sdo_;
    NodeTable* table_;
    int outstanding_ = 0;
    std::set<int> found_;
};

}  // namespace coscope::gui
