// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/canopen/MasterContext.h"

#include <QElapsedTimer>
#include <QObject>

#include <deque>
#include <functional>
#include <memory>
#include <optional>

class QTimer;

namespace coscope::canopen {

struct LssIdentity {
    uint32_t vendorId = 0, productCode = 0, revision = 0, serial = 0;  // 1018h:01..04
};

struct LssResult {
    bool ok = false;
    uint8_t errorCode = 0;  // configure/store: the slave's error code (CiA 305 §6.4)
    uint32_t value = 0;     // inquire: the value; inquire node-ID: the node-ID
    LssIdentity identity;   // inquireIdentity / fastscan
    bool noSlave = false;   // fastscan: no unconfigured slave answered
    QString error;
};
using LssCallback = std::function<void(const LssResult&)>;

// LSS master (CiA 305): requests on 7E5h, answers on 7E4h through the dispatcher. One
// confirmed service at a time (LSS has no addressing in its answers); the others queue.
// Unconfirmed services (switch state global, activate bit timing) go out at once.
class LssMaster : public QObject {
    Q_OBJECT
public:
    explicit LssMaster(MasterContext& context, QObject* parent = nullptr);
    ~LssMaster() override;

    void setTimeout(int ms) { timeoutMs_ = ms > 0 ? ms : 1000; }
    // Fastscan waits at least this long for "any slave matches" at each bit (CiA 305 §6.7.4
    // leaves it to the master); the window widens to twice the slaves' measured answer time,
    // and a scan whose result does not confirm is repeated with a wider window.
    void setFastscanTimeout(int ms) { fastscanMs_ = ms > 0 ? ms : 25; }

    // CiA 305 §6.3.2: 0 = waiting, 1 = configuration.
    bool switchStateGlobal(bool configuration, QString* error = nullptr);
    // §6.3.3: the one slave with this identity enters configuration state.
    void switchStateSelective(const LssIdentity& id, LssCallback done);
    void configureNodeId(uint8_t nodeId, LssCallback done);                    // §6.4.2 (FFh = unconfigured)
    void configureBitRate(int bitRate, LssCallback done);                      // §6.4.3, standard table (selector 0)
    bool activateBitTiming(uint16_t switchDelayMs, QString* error = nullptr);  // §6.4.4
    void storeConfiguration(LssCallback done);                                 // §6.4.5
    void inquire(uint8_t cs, LssCallback done);                                // 5Ah..5Eh (§6.6)
    void inquireIdentity(LssCallback done);                                    // vendor, product, revision, serial
    void inquireNodeId(LssCallback done);
    // §6.7.4 Fastscan: finds one unconfigured slave's identity bit by bit and leaves it in
    // configuration state.
    void fastscan(LssCallback done);

private:
    struct Request {
        CanFrame frame;
        uint8_t expectCs = 0;  // 0 = no answer expected
        int timeoutMs = 0;
        int graceMs = -1;  // >= 0: collect answers; after the first, wait this long, then complete
        bool seen = false;
        QElapsedTimer sentAt;
        std::function<void(bool answered, const CanFrame& answer)> then;
    };
    void enqueue(Request r);
    void pump();
    void onFrames(const std::vector<CanFrame>& frames);
    void onTimeout();
    void complete(bool answered, const CanFrame& answer);
    static CanFrame request(uint8_t cs, std::initializer_list<uint8_t> rest = {});
    void fastscanReset(std::shared_ptr<struct FastscanState> st, LssCallback done);
    void fastscanStep(std::shared_ptr<struct FastscanState> st, LssCallback done);
    void fastscanRetry(std::shared_ptr<struct FastscanState> st, LssCallback done, const QString& why);

    QString noAnswer(const QString& what) const { return sendError_.isEmpty() ? what : sendError_; }

    MasterContext& context_;
    QString sendError_;  // set while a request that could not be sent is completed
    int subscription_ = 0;
    QTimer* timer_;
    int timeoutMs_ = 1000;
    int fastscanMs_ = 25;
    int lastRttMs_ = 0;  // time to the first answer of the last collecting request
    std::deque<Request> queue_;
    std::optional<Request> active_;
};

}  // namespace coscope::canopen
