// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/can/QtCanBus.h"

#include "core/can/SocketCanLinks.h"
#include "core/can/SocketCanPresence.h"

#include <QCanBus>
#include <QCanBusDevice>
#include <QThread>
#include <QTimer>
#include <QVariant>

#include <spdlog/spdlog.h>

namespace coscope {

QtCanBus::QtCanBus(const BusUrl& url, QObject* parent) : ThreadedCanBus(url, parent) {}

QtCanBus::~QtCanBus() { close(); }

QString QtCanBus::name() const { return url().scheme + QStringLiteral("://") + url().target; }

std::optional<CanFrame> QtCanBus::fromQt(const QCanBusFrame& q) {
    CanFrame f;
    const auto ts = q.timeStamp();
    f.timestampNs = ts.seconds() * 1'000'000'000 + ts.microSeconds() * 1000;
    const QByteArray payload = q.payload();
    switch (q.frameType()) {
    case QCanBusFrame::DataFrame: break;
    case QCanBusFrame::RemoteRequestFrame:
        // Qt carries the requested DLC of a remote frame as the payload size.
        f.flags |= CanFrame::Remote;
        f.len = static_cast<uint8_t>(std::min<qsizetype>(payload.size(), 8));
        f.id = q.frameId();
        if (q.hasExtendedFrameFormat()) f.flags |= CanFrame::Extended;
        return f;
    case QCanBusFrame::ErrorFrame:
        f.flags |= CanFrame::Error;
        f.id = static_cast<uint32_t>(q.error()) & 0x1FFFFFFFU;
        f.len = 8;
        std::copy_n(payload.constData(), std::min<qsizetype>(payload.size(), 8), f.data.begin());
        return f;
    default: return std::nullopt;  // invalid/unknown frames carry nothing usable
    }
    f.id = q.frameId();
    if (q.hasExtendedFrameFormat()) f.flags |= CanFrame::Extended;
    const int maxLen = q.hasFlexibleDataRateFormat() ? 64 : 8;
    if (q.hasFlexibleDataRateFormat()) {
        f.flags |= CanFrame::Fd;
        if (q.hasBitrateSwitch()) f.flags |= CanFrame::BitRateSwitch;
        if (q.hasErrorStateIndicator()) f.flags |= CanFrame::ErrorState;
    }
    f.len = static_cast<uint8_t>(std::min<qsizetype>(payload.size(), maxLen));
    std::copy_n(payload.constData(), f.len, f.data.begin());
    return f;
}

QCanBusFrame QtCanBus::toQt(const CanFrame& f) {
    QCanBusFrame q;
    q.setFrameId(f.id);
    q.setExtendedFrameFormat(f.isExtended());
    if (f.isRemote()) {
        q.setFrameType(QCanBusFrame::RemoteRequestFrame);
        q.setPayload(QByteArray(f.len, '\0'));
        return q;
    }
    q.setFrameType(QCanBusFrame::DataFrame);
    if (f.isFd()) {
        q.setFlexibleDataRateFormat(true);
        q.setBitrateSwitch(f.flags & CanFrame::BitRateSwitch);
        q.setErrorStateIndicator(f.flags & CanFrame::ErrorState);
    }
    q.setPayload(QByteArray(reinterpret_cast<const char*>(f.data.data()), f.len));
    return q;
}

QString QtCanBus::threadName() const { return QStringLiteral("can-") + url().scheme; }

void QtCanBus::startOnThread() {
    opened_ = false;
    stopping_ = false;
    QString error;
    device_ = QCanBus::instance()->createDevice(url().scheme, url().target, &error);
    if (!device_) {
        failedToOpen(QStringLiteral("cannot open %1: %2")
                         .arg(name(), explain(error.isEmpty() ? QStringLiteral("plugin refused the device") : error)));
        return;
    }
    device_->setParent(context_);
    if (url().bitrate() > 0) device_->setConfigurationParameter(QCanBusDevice::BitRateKey, url().bitrate());
    if (url().canFd() || url().dataBitrate() > 0) device_->setConfigurationParameter(QCanBusDevice::CanFdKey, true);
    if (url().dataBitrate() > 0) device_->setConfigurationParameter(QCanBusDevice::DataBitRateKey, url().dataBitrate());
    if (url().scheme == u"socketcan")
        device_->setConfigurationParameter(QCanBusDevice::ErrorFilterKey,
                                           QVariant::fromValue(QCanBusFrame::FrameErrors(QCanBusFrame::AnyError)));

    QObject::connect(device_, &QCanBusDevice::framesReceived, context_, [this] { onFramesReceived(); });
    QObject::connect(device_, &QCanBusDevice::errorOccurred, context_,
                     [this](QCanBusDevice::CanBusError e) { onDeviceError(e); });
    QObject::connect(device_, &QCanBusDevice::stateChanged, context_,
                     [this](QCanBusDevice::CanBusDeviceState s) { onDeviceState(s); });

    openTimer_ = new QTimer(context_);
    openTimer_->setSingleShot(true);
    QObject::connect(openTimer_, &QTimer::timeout, context_, [this] {
        if (!opened_)
            fail(QStringLiteral("cannot open %1: no connection within %2 s").arg(name()).arg(kOpenTimeoutMs / 1000));
    });
    openTimer_->start(kOpenTimeoutMs);
    if (url().scheme == u"socketcan") {
        linkTimer_ = new QTimer(context_);
        linkTimer_->setInterval(1000);
        QObject::connect(linkTimer_, &QTimer::timeout, context_, [this] { checkLink(); });
    }

    if (!device_->connectDevice()) {
        if (device_)
            fail(QStringLiteral("cannot open %1: %2")
                     .arg(name(), explain(device_->errorString())));  // else already reported
        return;
    }
    if (device_ && device_->state() == QCanBusDevice::ConnectedState) onDeviceState(QCanBusDevice::ConnectedState);
}

void QtCanBus::stopOnThread() {
    stopping_ = true;
    if (openTimer_) {
        delete openTimer_;
        openTimer_ = nullptr;
    }
    delete linkTimer_;
    linkTimer_ = nullptr;
    if (device_) {
        QObject::disconnect(device_, nullptr, context_, nullptr);
        if (device_->state() != QCanBusDevice::UnconnectedState) device_->disconnectDevice();
        delete device_;
        device_ = nullptr;
    }
    opened_ = false;
}

QString QtCanBus::explain(const QString& raw) const {
    return url().scheme == u"socketcan" ? explainSocketCanError(url().target, raw, url().bitrate()) : raw;
}

void QtCanBus::fail(const QString& message) {
    if (stopping_) return;
    if (openTimer_) openTimer_->stop();
    if (linkTimer_) linkTimer_->stop();
    if (device_) {
        QObject::disconnect(device_, nullptr, context_, nullptr);
        if (device_->state() != QCanBusDevice::UnconnectedState) device_->disconnectDevice();
        device_->deleteLater();
        device_ = nullptr;
    }
    const bool wasOpen = opened_;
    opened_ = false;
    // A device that was open and went away is a lost adapter: reopen with back-off.
    if (wasOpen) connectionLost(message);
    else failedToOpen(message);
}

void QtCanBus::onFramesReceived() {
    if (!device_) return;
    while (device_->framesAvailable() > 0) {
        const QList<QCanBusFrame> frames = device_->readAllFrames();
        for (const QCanBusFrame& q : frames) {
            if (q.hasLocalEcho()) continue;  // sendFrame() already delivered our own Tx copy
            auto f = fromQt(q);
            if (!f) continue;
            if (f->timestampNs == 0) f->timestampNs = nowNs();
            deliver(*f);
        }
    }
}

void QtCanBus::onDeviceError(int error) {
    if (!device_ || stopping_) return;
    const auto e = static_cast<QCanBusDevice::CanBusError>(error);
    if (e == QCanBusDevice::NoError) return;
    const QString text = device_->errorString();
    if (restarting_) {
        restartError_ = text.isEmpty() ? QStringLiteral("the plugin cannot restart the controller") : text;
        return;
    }
    if (e == QCanBusDevice::WriteError) {
        if (writing_) return;  // sendFrame() reports it to its caller
        countError();
        reportError(QStringLiteral("%1: write failed: %2").arg(name(), text));
        return;
    }
    if (!opened_) {
        fail(QStringLiteral("cannot open %1: %2").arg(name(), explain(text)));
        return;
    }
    if (e == QCanBusDevice::ReadError || e == QCanBusDevice::ConnectionError) {
        fail(QStringLiteral("%1 failed: %2").arg(name(), explain(text)));
        return;
    }
    reportError(QStringLiteral("%1: %2").arg(name(), text));
}

void QtCanBus::onDeviceState(int s) {
    if (stopping_) return;
    const auto st = static_cast<QCanBusDevice::CanBusDeviceState>(s);
    if (st == QCanBusDevice::ConnectedState && !opened_) {
        opened_ = true;
        if (openTimer_) openTimer_->stop();
        if (linkTimer_) linkTimer_->start();
        reachedOpen();
    } else if (st == QCanBusDevice::UnconnectedState && opened_) {
        fail(QStringLiteral("%1 disconnected (device gone or its server closed)").arg(name()));
    }
}

void QtCanBus::checkLink() {
    if (!opened_ || stopping_) return;
    switch (socketCanPresence(url().target)) {
    case LinkPresence::Up: return;
    case LinkPresence::Gone:
        fail(QStringLiteral("%1 failed: %2").arg(name(), explain(QStringLiteral("No such device"))));
        return;
    case LinkPresence::Down:
        fail(QStringLiteral("%1 failed: %2").arg(name(), explain(QStringLiteral("Network is down"))));
        return;
    }
}

bool QtCanBus::restartController(QString* error) {
    bool ok = false;
    QString why;
    runOnBusThread([&] {
        if (!device_) {
            why = QStringLiteral("%1 is not open").arg(name());
            return;
        }
        // Qt's socketcan plugin restarts through libsocketcan (can_do_restart); plugins without a
        // restart leave a ConfigurationError and its text.
        restartError_.clear();
        restarting_ = true;
        device_->resetController();  // errors arrive synchronously through onDeviceError
        restarting_ = false;
        ok = restartError_.isEmpty();
        if (!ok) why = QStringLiteral("%1: %2").arg(name(), explain(restartError_));
    });
    if (!ok && error) *error = why;
    return ok;
}

bool QtCanBus::sendFrame(const CanFrame& frame, QString* error) {
    if (frame.isError()) {
        if (error) *error = QStringLiteral("error frames cannot be sent");
        return false;
    }
    if (!thread_ || !context_) {
        if (error) *error = QStringLiteral("%1 is not open").arg(name());
        return false;
    }
    bool ok = false;
    QString why;
    auto doSend = [&] {
        if (!device_ || !opened_) {
            why = QStringLiteral("%1 is not open").arg(name());
            return;
        }
        writing_ = true;
        ok = device_->writeFrame(toQt(frame));
        writing_ = false;
        if (!ok) {
            why = QStringLiteral("%1: write failed: %2").arg(name(), device_->errorString());
            return;
        }
        deliverTxEcho(frame);
    };
    runOnBusThread(doSend);
    if (!ok && error) *error = why;
    return ok;
}

}  // namespace coscope
