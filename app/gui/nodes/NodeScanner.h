// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QObject>

#include <functional>
#include <set>

namespace coscope::canopen {
class MasterContext;
class SdoClient;
class NodeTable;
}  // namespace coscope::canopen

namespace coscope::gui {

// Network scan and identification through the SDO client (never blocks): reads 1000h (device
// type) from nodes 1..127 — a node that answers (even with an abort) exists — then its device
// type, name 1008h, versions 1009h/100Ah ("not present" when the node lacks one) and identity
// 1018h:01..04, and matches a dictionary (DictionaryLibrary::match).
class NodeScanner : public QObject {
    Q_OBJECT
public:
    NodeScanner(canopen::SdoClient* sdo, canopen::NodeTable* table, QObject* parent = nullptr);

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
    canopen::NodeTable* table_;
    int outstanding_ = 0;
    std::set<int> found_;
};

}  // namespace coscope::gui
