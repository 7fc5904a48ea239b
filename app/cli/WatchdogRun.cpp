// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/cli/WatchdogRun.h"

#include "core/canopen/ServiceWait.h"

#include <cstdio>

namespace coscope::cli {

void WatchdogOptions::addTo(QCommandLineParser& parser) const { parser.addOptions({watchdog, node, period, reaction}); }

bool WatchdogOptions::read(const QCommandLineParser& parser, uint8_t driveNode, QString* error) {
    enabled = parser.isSet(watchdog);
    const auto n = parseNodeId(parser.value(node));
    if (!n) {
        *error = QStringLiteral("--heartbeat-node must be 1-127");
        return false;
    }
    if (*n == driveNode) {
        *error = QStringLiteral(
                     "--heartbeat-node %1 is the drive's own node-ID; CoScope's heartbeat needs a node-ID of its own")
                     .arg(*n);
        return false;
    }
    heartbeatNode = *n;
    bool ok = false;
    const uint ms = parser.value(period).toUInt(&ok);
    if (!ok || ms == 0 || ms > 21845) {
        *error = QStringLiteral("--heartbeat-ms must be 1-21845 (the drive waits 3 x, at most 65535 ms)");
        return false;
    }
    periodMs = static_cast<uint16_t>(ms);
    // 6007h abort connection option code (CiA 402-2).
    const QString r = parser.value(reaction).toLower();
    if (r == u"quick-stop") abortOption = 3;
    else if (r == u"disable-voltage") abortOption = 2;
    else if (r == u"fault") abortOption = 1;
    else if (r == u"none") abortOption = 0;
    else {
        *error = QStringLiteral("--watchdog-reaction must be quick-stop, disable-voltage, fault or none");
        return false;
    }
    return true;
}

WatchdogRun::WatchdogRun(BusSession& session, uint8_t node, int axis, QTextStream& out)
    : session_(session), out_(out), guard_(std::make_unique<canopen::HeartbeatGuard>(session.sdo(), node, axis)) {
    guard_->setSendObserver([this](const QString& line) {
        out_ << "send " << line << "\n";
        out_.flush();
    });
}

WatchdogRun::~WatchdogRun() {
    const QString e = finish();
    if (!e.isEmpty()) std::fprintf(stderr, "watchdog: %s\n", qPrintable(e));
}

bool WatchdogRun::start(const WatchdogOptions& options, QString* error) {
    canopen::HeartbeatProducer& hb = session_.master().heartbeat();
    hb.setNodeId(options.heartbeatNode);
    hb.setPeriodMs(options.periodMs);
    if (!hb.start(error)) return false;
    running_ = true;
    canopen::waitUntil([&hb] { return hb.sent() > 0; }, 1000);
    out_ << "heartbeat: node " << options.heartbeatNode << " every " << options.periodMs << " ms (COB-ID 0x"
         << QString::number(0x700 + options.heartbeatNode, 16).toUpper() << ")\n";
    guard_->setAbortOption(options.abortOption);
    auto r =
        canopen::waitForResult<canopen::HeartbeatGuardResult>([this, &hb](auto cb) { guard_->arm(hb, cb); }, 30000);
    if (!r || !r->ok) {
        *error = r ? r->error : QStringLiteral("arming the heartbeat guard gave no answer");
        finish();
        return false;
    }
    out_ << "watchdog: " << r->summary << "\n";
    out_.flush();
    return true;
}

QString WatchdogRun::finish() {
    QString error;
    if (guard_->armed()) {
        auto r = canopen::waitForResult<canopen::HeartbeatGuardResult>([this](auto cb) { guard_->release(cb); }, 30000);
        if (r && r->ok) out_ << "watchdog: " << r->summary << "\n";
        else error = r ? r->error : QStringLiteral("putting back 1016h/6007h gave no answer");
        out_.flush();
    }
    // After putting back: the drive no longer watches, so stopping the heartbeat is harmless.
    if (running_) session_.master().heartbeat().stop();
    running_ = false;
    return error;
}

}  // namespace coscope::cli
