// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/canopen/MasterContext.h"

#include <QObject>

#include <functional>

class QTimer;

namespace coscope::canopen {

class SdoClient;
struct SdoResult;

// SYNC producer (CiA 301 §7.2.5): SYNC on COB-ID 80h (1005h) every period, with an optional
// counter 1..overflow (1019h synchronous counter overflow value, 2..240; 0 = no counter, DLC 0).
// Lives on its thread's event loop; the period has the event loop's millisecond resolution.
class SyncProducer : public QObject {
    Q_OBJECT
public:
    explicit SyncProducer(MasterContext& context, QObject* parent = nullptr);

    void setCobId(uint32_t id) { cobId_ = id; }
    void setPeriodUs(uint32_t us) { periodUs_ = us; }
    uint32_t periodUs() const { return periodUs_; }
    // 0 = no counter; 2..240 otherwise (CiA 301 §7.5.2.22). False for other values.
    bool setCounterOverflow(uint8_t overflow);

    // Starts sending; false with *error when the period is 0 or the bus refuses (listen-only).
    bool start(QString* error = nullptr);
    void stop();
    bool isRunning() const;
    uint64_t sent() const { return sent_; }

    // Writes the period to a node's 1006h (communication cycle period, µs) when asked.
    void writeCommunicationCyclePeriod(SdoClient& sdo, uint8_t node, std::function<void(const SdoResult&)> done);

signals:
    void stoppedOnError(const QString& message);

private:
    bool sendOne(QString* error);

    MasterContext& context_;
    QTimer* timer_;
    uint32_t cobId_ = 0x80;
    uint32_t periodUs_ = 0;
    uint8_t overflow_ = 0;
    uint8_t counter_ = 1;
    uint64_t sent_ = 0;
};

}  // namespace coscope::canopen
