// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/canopen/SyncProducer.h"

#include "core/canopen/SdoClient.h"

#include <QTimer>

#include <algorithm>

namespace coscope::canopen {

SyncProducer::SyncProducer(MasterContext& context, QObject* parent) : QObject(parent), context_(context), timer_(new QTimer(this)) {
    timer_->setTimerType(Qt::PreciseTimer);
    connect(timer_, &QTimer::timeout, this, [this] {
        QString error;
        if (!sendOne(&error)) {
            timer_->stop();
            emit stoppedOnError(error);
        }
    });
}

bool SyncProducer::setCounterOverflow(uint8_t overflow) {
    if (overflow == 1 || overflow > 240) return false;
    overflow_ = overflow;
    counter_ = 1;
    return true;
}

bool SyncProducer::start(QString* error) {
    if (periodUs_ == 0) {
        if (error) *error = QStringLiteral("SYNC period is 0");
        return false;
    }
    counter_ = 1;
    if (!sendOne(error)) return false;
    timer_->start(std::max<int>(1, static_cast<int>(periodUs_ / 1000)));
    return true;
}

void SyncProducer::stop() { timer_->stop(); }

bool SyncProducer::isRunning() const { return timer_->isActive(); }

bool SyncProducer::sendOne(QString* error) {
    CanFrame f;
    f.id = cobId_;
    if (overflow_) {
        // Counter 1..overflow, then back to 1 (CiA 301 §7.2.5.2.1).
        f.len = 1;
        f.data[0] = counter_;
        counter_ = counter_ >= overflow_ ? 1 : static_cast<uint8_t>(counter_ + 1);
    }
    if (!context_.send(f, error)) return false;
    ++sent_;
    return true;
}

void SyncProducer::writeCommunicationCyclePeriod(SdoClient& sdo, uint8_t node, std::function<void(const SdoResult&)> done) {
    QByteArray v(4, 0);
    for (int i = 0; i < 4; ++i) v[i] = static_cast<char>(periodUs_ >> (8 * i));
    sdo.download(node, 0x1006, 0, v, std::move(done));
}

}  // namespace coscope::canopen
