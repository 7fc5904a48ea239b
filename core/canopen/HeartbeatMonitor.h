// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/canopen/MasterContext.h"
#include "core/canopen/NodeTable.h"

#include <QObject>

#include <map>

class QTimer;

namespace coscope::canopen {

// Heartbeat consumer and node-guarding master (CiA 301 §7.2.8.3.2) feeding the context's NodeTable.
// Receives 701h..77Fh (boot-up, heartbeat, guarding answers) and 81h..FFh (EMCY) through the
// dispatcher. Signals fire on changes only (a node appears, changes state, boots, is lost,
// sends an EMCY) - never per heartbeat frame.
class HeartbeatMonitor : public QObject {
    Q_OBJECT
public:
    explicit HeartbeatMonitor(MasterContext& context, QObject* parent = nullptr);
    ~HeartbeatMonitor() override;

    const NodeTable& table() const { return context_.nodes(); }
    NodeTable& table() { return context_.nodes(); }

    // Heartbeat consumer: the node is lost when no heartbeat came within `timeMs` (1016h). 0 = off.
    void setConsumerTime(uint8_t node, int timeMs);
    // Node guarding: RTR on 700h + node every guardTimeMs (100Ch); lost after lifeTimeFactor
    // (100Dh) periods without a correct answer. guardTimeMs 0 = off.
    void setGuarding(uint8_t node, int guardTimeMs, int lifeTimeFactor);

signals:
    void nodeChanged(int node);
    void nodeLost(int node);
    void bootUp(int node);
    void emergency(int node, quint16 code);

private:
    void onFrames(const std::vector<CanFrame>& frames);
    void onCheck();

    struct Guard {
        int guardTimeMs = 0;
        int lifeFactor = 0;
        int64_t nextRequestNs = 0;
        int64_t lastAnswerNs = 0;
        bool expectToggle = false;
        bool waiting = false;
        bool firstAnswer = true;
    };

    MasterContext& context_;
    int subscription_ = 0;
    QTimer* timer_;
    std::map<uint8_t, int> consumerMs_;
    std::map<uint8_t, int64_t> lastHeartbeatNs_;
    std::map<uint8_t, Guard> guards_;
};

}  // namespace coscope::canopen
