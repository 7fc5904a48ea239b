// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/canopen/NodeTable.h"
#include "core/canopen/SdoClient.h"

#include <QObject>
#include <QPointer>

#include <functional>
#include <optional>
#include <vector>

class QTimer;

namespace coscope::canopen {

// One node found by a scan: 1000h, 1018h:01..04, 1008h/1009h/100Ah and the dictionary matched to them.
struct ScannedNode {
    uint8_t node = 0;
    uint32_t deviceType = 0;
    std::optional<uint32_t> vendorId, productCode, revision, serial;
    // Optional CiA 301 objects (§7.5.2.9-11), read quietly: nullopt = the node does not have it
    // (aborted or no answer), which is normal and not an error.
    std::optional<QString> deviceName, hardwareVersion, softwareVersion;  // 1008h, 1009h, 100Ah
    // Which of them the node refused (SDO abort): "not present", as opposed to not answered;
    // NodeInfo::kNoDeviceName, kNoHardwareVersion, kNoSoftwareVersion.
    uint8_t notPresent = 0;
    QString dictionary;  // empty when nothing matched
    QString error;       // 1018h could not be read (the node answered 1000h)
};

// Finds the nodes on a bus by reading 1000h (device type, mandatory, CiA 301 §7.5.2.1) of
// nodes first..last over SDO, then 1018h sub 1..4 of each that answered, then the optional
// 1008h, 1009h and 100Ah (a node without them is "not present" there, not in error). Rate-limited: at most
// `maxOutstanding` requests in flight and at least `intervalMs` between two new requests, so a
// scan never floods a production bus. No request is retried. The dictionary is matched by a
// function the caller gives (the eds layer's library; core cannot see it). Found nodes are
// written into the bus's node table (MasterContext::nodes()). The one scanner of CoScope: the
// CLI's `scan`, the project's backup and compare, the Nodes dock and the wizards (NodeScanner).
class NetworkScan : public QObject {
    Q_OBJECT
public:
    // Names the dictionary for what the node answered (empty: none), once all reads are in.
    using Matcher = std::function<QString(const ScannedNode& node)>;
    using Done = std::function<void(const std::vector<ScannedNode>&)>;

    explicit NetworkScan(SdoClient& sdo, QObject* parent = nullptr);

    void setRange(uint8_t first, uint8_t last) {
        first_ = first;
        last_ = last;
    }
    void setTimeout(int ms) { timeoutMs_ = ms; }  // per node; default 200 ms
    void setMaxOutstanding(int n) { maxOutstanding_ = std::max(1, n); }
    void setInterval(int ms) { intervalMs_ = std::max(0, ms); }
    void setMatcher(Matcher m) { matcher_ = std::move(m); }

    void start(Done done);
    bool isRunning() const { return running_; }
    int progress() const { return probed_; }  // nodes probed so far

private:
    void launchMore();
    void probe(uint8_t node);
    void readIdentity(std::shared_ptr<ScannedNode> found, uint8_t sub);
    void readStrings(std::shared_ptr<ScannedNode> found, int which);
    void finishNode(std::shared_ptr<ScannedNode> found);
    void nodeDone();

    // The bus's client; a scan whose bus closed (the client gone) stops quietly, as its pending
    // transfers do.
    QPointer<SdoClient> sdo_;
    QTimer* pacer_;
    uint8_t first_ = 1, last_ = 127;
    int timeoutMs_ = 200;
    int maxOutstanding_ = 8;
    int intervalMs_ = 2;
    Matcher matcher_;
    Done done_;
    bool running_ = false;
    int next_ = 0;
    int outstanding_ = 0;
    int probed_ = 0;
    std::vector<ScannedNode> found_;
};

}  // namespace coscope::canopen
