// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/canopen/DriveDisable.h"

#include "core/canopen/MasterContext.h"
#include "core/canopen/Sdo.h"

#include <QStringList>

#include <chrono>
#include <condition_variable>
#include <memory>
#include <mutex>

#include <spdlog/spdlog.h>

namespace coscope::canopen {

namespace {
// One expedited download of 6040h to one drive and what came back of it.
struct DisableRequest {
    CanFrame frame;
    uint32_t responseId = 0;
    uint16_t index = 0;
    bool seen = false;
    bool answered = false;
    uint32_t abortCode = 0;
};

struct DisableWaiter {
    std::mutex mutex;
    std::condition_variable changed;
    std::vector<DisableRequest> requests;

    // Ingest thread: a frame of a watched COB-ID.
    void offer(const CanFrame& f) {
        std::lock_guard lock(mutex);
        for (DisableRequest& r : requests) {
            if (f.isTx() && f.id == r.frame.id && f.len == r.frame.len && std::equal(f.data.begin(), f.data.begin() + f.len, r.frame.data.begin())) r.seen = true;
            // The server's answer names the object (CiA 301 §7.2.4.3.3): 60h confirms, 80h aborts.
            if (!f.isTx() && f.id == r.responseId && f.len >= 4 && f.data[1] == (r.index & 0xFF) && f.data[2] == (r.index >> 8) && f.data[3] == 0) {
                if (f.data[0] == 0x60) r.answered = true;
                else if (f.data[0] == 0x80 && f.len >= 8) r.answered = true, r.abortCode = le32At(f, 4);
            }
        }
        changed.notify_all();
    }
};

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
        const QString what = d.quickStopSent ? QStringLiteral("Quick stop and Disable voltage") : QStringLiteral("Disable voltage");
        if (d.seen && d.answered) out << QStringLiteral("%1: %2 sent, seen on the bus and confirmed").arg(d.drive.name(), what);
        else if (d.seen) out << QStringLiteral("%1: %2 sent and seen on the bus; %3").arg(d.drive.name(), what, d.error);
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
        const QString why = !bus ? QStringLiteral("no bus") : bus->isListenOnly() ? QStringLiteral("the bus is listen-only") : QStringLiteral("the bus is %1").arg(toString(bus->state()));
        for (auto& d : out.drives) d.error = why + QStringLiteral(": nothing could be sent");
        spdlog::warn("cannot disable {} before the bus closes: {}", context.enabledDrives().names().toStdString(), why.toStdString());
        return out;
    }

    auto waiter = std::make_shared<DisableWaiter>();
    std::vector<uint32_t> ids;
    for (const auto& d : drives) ids.push_back(0x600u + d.node), ids.push_back(0x580u + d.node);
    const int watch = context.dispatcher().addWatch(ids, [waiter](const CanFrame& f) { waiter->offer(f); });
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::milliseconds(timeoutMs);

    // One round: the same controlword to `which` drives, then wait for their copies and answers
    // (an SDO server takes one request at a time: the next round waits for this one).
    auto round = [&](uint16_t controlword, const std::vector<size_t>& which, std::chrono::steady_clock::time_point until) {
        {
            std::lock_guard lock(waiter->mutex);
            waiter->requests.clear();
            for (size_t i : which) {
                const auto& d = out.drives[i].drive;
                DisableRequest r;
                r.index = static_cast<uint16_t>(0x6040 + d.axis * 0x800);
                r.frame = sdo::initiateDownload(d.node, r.index, 0, controlwordBytes(controlword));
                r.responseId = 0x580u + d.node;
                waiter->requests.push_back(r);
            }
        }
        std::vector<QString> sendErrors(which.size());
        for (size_t k = 0; k < which.size(); ++k) {
            QString error;
            CanFrame f;
            {
                std::lock_guard lock(waiter->mutex);
                f = waiter->requests[k].frame;
            }
            if (!context.send(f, &error)) sendErrors[k] = error;
        }
        std::unique_lock lock(waiter->mutex);
        waiter->changed.wait_until(lock, until, [&] {
            for (size_t k = 0; k < which.size(); ++k)
                if (sendErrors[k].isEmpty() && !(waiter->requests[k].seen && waiter->requests[k].answered)) return false;
            return true;
        });
        std::vector<DisableRequest> done = waiter->requests;
        lock.unlock();
        for (size_t k = 0; k < which.size(); ++k) {
            auto& d = out.drives[which[k]];
            d.seen = done[k].seen;
            d.answered = done[k].answered && done[k].abortCode == 0;
            if (!sendErrors[k].isEmpty()) d.error = sendErrors[k];
            else if (!done[k].seen) d.error = QStringLiteral("its frame did not come back from the bus within %1 ms").arg(timeoutMs);
            else if (done[k].abortCode) d.error = QStringLiteral("the drive refused it: %1").arg(context.abortText(d.drive.node, done[k].abortCode));
            else if (!done[k].answered) d.error = QStringLiteral("the drive did not confirm it within %1 ms").arg(timeoutMs);
            else d.error.clear();
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
    context.dispatcher().removeWatch(watch);
    out.waitedMs = static_cast<int>(std::chrono::duration_cast<std::chrono::milliseconds>(std::chrono::steady_clock::now() - started).count());

    for (const auto& d : out.drives) {
        if (d.seen) context.enabledDrives().forget(d.drive.node, d.drive.axis);
        if (d.seen && d.answered) spdlog::info("{}: Disable voltage sent before the bus closed, seen on the bus and confirmed", d.drive.name().toStdString());
        else if (d.seen) spdlog::warn("{}: Disable voltage seen on the bus; {}", d.drive.name().toStdString(), d.error.toStdString());
        else spdlog::error("{}: Disable voltage NOT seen on the bus before it closed: {}", d.drive.name().toStdString(), d.error.toStdString());
    }
    return out;
}

}  // namespace coscope::canopen
