// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/nodes/NodeScanner.h"

#include "core/canopen/NetworkScan.h"
#include "core/canopen/SdoClient.h"
#include "eds/ScanMatcher.h"

#include <spdlog/spdlog.h>

#include <algorithm>

namespace coscope::gui {

NodeScanner::NodeScanner(canopen::SdoClient* sdo, QObject* parent) : QObject(parent), sdo_(sdo) {}

void NodeScanner::scan(int firstNode, int lastNode, int timeoutMs) {
    if (!sdo_ || isRunning()) return;
    found_.clear();
    run(firstNode, lastNode, timeoutMs, true);
}

void NodeScanner::identify(int node) {
    if (sdo_ && node >= 1 && node <= 127) run(node, node, 300, false);
}

void NodeScanner::run(int first, int last, int timeoutMs, bool report) {
    auto* scan = new canopen::NetworkScan(*sdo_, this);
    scan->setRange(static_cast<uint8_t>(std::clamp(first, 1, 127)), static_cast<uint8_t>(std::clamp(last, 1, 127)));
    scan->setTimeout(timeoutMs);
    scan->setMaxOutstanding(kOutstanding);
    scan->setMatcher(eds::scanMatcher());
    ++running_;
    scan->start([this, scan, report](const std::vector<canopen::ScannedNode>& nodes) {
        scan->deleteLater();
        --running_;
        if (!report) return;
        for (const canopen::ScannedNode& n : nodes) found_.insert(n.node);
        spdlog::info("scan finished: {} nodes answered", found_.size());
        emit finished(static_cast<int>(found_.size()));
    });
}

}  // namespace coscope::gui
