// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/canopen/DriveDisable.h"

#include "core/canopen/MasterContext.h"
#include "core/canopen/SdoDirect.h"

#include <QStringList>

#include <chrono>

#include <spdlog/spdlog.h>

namespace coscope::canopen {

namespace {
QByteArray controlwordBytes(uint16_t v) {
    QByteArray b(2, 0);
    b[0] = static_cast<char>(v & 0xFF);
    b[1] = static_cast<char>(v >> 8);
    return b;
}
}  // namespace

bool DriveDisableOutcome::allSeen() const {
    for (const Drive& d : drives)
        if (!d.seen) return false;
    return true;
}

QString DriveDisableOutcome::notSeen() const {
    QStringList out;
    for (const Drive& d : drives)
        if (!d.seen) out << QStringLiteral("%1 (%2)").arg(d.drive.name(), d.error);
    return out.join(QStringLiteral("; "));
}

QString DriveDisableOutcome::summary() const {
    QStringList out;
    for (const Drive& d : drives) {
        const QString what =
            d.quickStopSent ? QStringLiteral("Quick stop and Disable voltage") : QStringLiteral("Disable voltage");
        if (d.seen && d.answered)
            out << QStringLiteral("%1: %2 sent, seen on the bus and confirmed").arg(d.drive.name(), what);
        else if (d.seen)
            out << QStringLiteral("%1: %2 sent and seen on the bus; %3").arg(d.drive.name(), what, d.error);
        else out << QStringLiteral("%1: %2 NOT seen on the bus: %3").arg(d.drive.name(), what, d.error);
    }
    return out.join(u'\n');
}

DriveDisableOutcome disableEnabledDrives(MasterContext& context, int timeoutMs) {
    DriveDisableOutcome out;
    const std::vector<EnabledDrives::Drive> drives = context.enabledDrives().drives();
    if (drives.empty()) return out;
    for (const auto& d : drives) out.drives.push_back({d, false, false, false, {}});
    CanBus* bus = context.bus();
    if (!bus || bus->isListenOnly() || bus->state() != CanBus::State::Open) {
        const QString why = !bus                  ? QStringLiteral("no bus")
                            : bus->isListenOnly() ? QStringLiteral("the bus is listen-only")
                                                  : QStringLiteral("the bus is %1").arg(toString(bus->state()));
        for (auto& d : out.drives) d.error = why + QStringLiteral(": nothing could be sent");
        spdlog::warn("cannot disable {} before the bus closes: {}", context.enabledDrives().names().toStdString(),
                     why.toStdString());
        return out;
    }

    const auto deadline = std::chrono::steady_clock::now() + std::chrono::milliseconds(timeoutMs);
    // One round: the same controlword to `which` drives, straight on the bus, and a wait for
    // their copies and answers (SdoDirect.h).
    auto round = [&](uint16_t controlword, const std::vector<size_t>& which,
                     std::chrono::steady_clock::time_point until) {
        std::vector<DirectDownload> writes;
        for (size_t i : which) {
            const auto& d = out.drives[i].drive;
            writes.push_back(DirectDownload::of(d.node, static_cast<uint16_t>(0x6040 + d.axis * 0x800), 0,
                                                controlwordBytes(controlword)));
        }
        downloadDirect(context, writes, until, QStringLiteral("the drive"));
        for (size_t k = 0; k < which.size(); ++k) {
            auto& d = out.drives[which[k]];
            d.seen = writes[k].seen;
            d.answered = writes[k].answered;
            d.error = writes[k].error;
        }
    };

    const auto started = std::chrono::steady_clock::now();
    std::vector<size_t> moving, all;
    for (size_t i = 0; i < out.drives.size(); ++i) {
        all.push_back(i);
        if (out.drives[i].drive.mayMove()) moving.push_back(i), out.drives[i].quickStopSent = true;
    }
    // Quick stop first where the motor may turn (CiA 402-2 §6.2.1: it brakes on its ramp), then
    // Disable voltage to all (transitions 9/12 to Switch on disabled: no power to the motor).
    // The Quick stop round gets half the time at most, so Disable voltage always has its turn.
    if (!moving.empty()) round(0x0002, moving, started + std::chrono::milliseconds(timeoutMs / 2));
    round(0x0000, all, deadline);
    out.waitedMs = static_cast<int>(
        std::chrono::duration_cast<std::chrono::milliseconds>(std::chrono::steady_clock::now() - started).count());

    for (const auto& d : out.drives) {
        if (d.seen) context.enabledDrives().forget(d.drive.node, d.drive.axis);
        if (d.seen && d.answered)
            spdlog::info("{}: Disable voltage sent before the bus closed, seen on the bus and confirmed",
                         d.drive.name().toStdString());
        else if (d.seen)
            spdlog::warn("{}: Disable voltage seen on the bus; {}", d.drive.name().toStdString(),
                         d.error.toStdString());
        else
            spdlog::error("{}: Disable voltage NOT seen on the bus before it closed: {}", d.drive.name().toStdString(),
                          d.error.toStdString());
    }
    return out;
}

}  // namespace coscope::canopen
