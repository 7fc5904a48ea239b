// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/can/ThreadedCanBus.h"

#include <QCanBusFrame>

#include <optional>

class QCanBusDevice;
class QThread;
class QTimer;

namespace coscope {

// Every Qt CAN bus plugin (socketcan, virtualcan, peakcan, ...) through QCanBusDevice:
// scheme = plugin name, target = interface ("socketcan://can0", "virtualcan://can0").
// The device is created, read and written on its own thread; received frames go straight into
// the ring, nothing per frame crosses a signal.
//
// URL options mapped to QCanBusDevice configuration keys (where the plugin supports them):
//   bitrate=N       BitRateKey (socketcan needs libsocketcan and the right to change the link)
//   fd=1            CanFdKey (required by Qt to send or receive CAN FD frames)
//   data-bitrate=N  DataBitRateKey, implies fd=1
//   listen-only=1   Qt 6.4 has no listen-only configuration key for any plugin, so the adapter is
//                   not switched to listen-only mode; CanBus::send() refuses every frame instead
//                   (the one place that enforces it), so nothing is ever written to the device.
// socketcan also gets ErrorFilterKey = all error classes, so bus errors show as error frames.
class QtCanBus : public ThreadedCanBus {
    Q_OBJECT
public:
    static constexpr int kOpenTimeoutMs = 5000;

    explicit QtCanBus(const BusUrl& url, QObject* parent = nullptr);
    ~QtCanBus() override;

    // Conversions (pure, public for tests). An error frame's `id` holds the SocketCAN error
    // class bits, which QCanBusFrame::FrameError mirrors bit for bit (linux/can/error.h).
    static std::optional<CanFrame> fromQt(const QCanBusFrame& q);
    static QCanBusFrame toQt(const CanFrame& frame);

    bool restartController(QString* error) override;  // QCanBusDevice::resetController()

protected:
    bool sendFrame(const CanFrame& frame, QString* error) override;

private:
    // These run on the device thread.
    QString threadName() const override;
    void startOnThread() override;
    void stopOnThread() override;
    void onFramesReceived();
    void onDeviceError(int error);
    void onDeviceState(int state);
    void checkLink();
    void fail(const QString& message);
    QString explain(const QString& raw) const;  // socketcan: what the system error means (SocketCanLinks.h)
    QString name() const;

    QCanBusDevice* device_ = nullptr;
    QTimer* openTimer_ = nullptr;
    QTimer* linkTimer_ = nullptr;  // socketcan: is the interface still there and up (SocketCanPresence.h)
    bool restarting_ = false;      // bus thread: resetController() running, its error goes to restartError_
    QString restartError_;
    bool opened_ = false;
    bool stopping_ = false;
    bool writing_ = false;
};

}  // namespace coscope
