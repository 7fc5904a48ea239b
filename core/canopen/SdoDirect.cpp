// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/canopen/SdoDirect.h"

#include "core/canopen/MasterContext.h"
#include "core/canopen/Sdo.h"

#include <condition_variable>
#include <map>
#include <memory>
#include <mutex>

namespace coscope::canopen {

namespace {
// The request in flight to each node and what came back of it (ingest thread and caller).
struct DirectWaiter {
    struct Pending {
        CanFrame frame;
        bool seen = false;
        bool answered = false;
        uint32_t abortCode = 0;
    };
    std::mutex mutex;
    std::condition_variable changed;
    std::map<uint8_t, Pending> pending;  // by node

    void offer(const CanFrame& f) {
        std::lock_guard lock(mutex);
        for (auto& [node, p] : pending) {
            if (f.isTx() && f.id == p.frame.id && f.len == p.frame.len &&
                std::equal(f.data.begin(), f.data.begin() + f.len, p.frame.data.begin()))
                p.seen = true;
            // The server's answer names the object (CiA 301 §7.2.4.3.3): 60h confirms, 80h aborts.
            if (!f.isTx() && f.id == 0x580u + node && f.len >= 4 && f.data[1] == p.frame.data[1] &&
                f.data[2] == p.frame.data[2] && f.data[3] == p.frame.data[3]) {
                if (f.data[0] == 0x60) p.answered = true;
                else if (f.data[0] == 0x80 && f.len >= 8) p.answered = true, p.abortCode = le32At(f, 4);
            }
        }
        changed.notify_all();
    }
};
}  // namespace

void downloadDirect(MasterContext& context, std::vector<DirectDownload>& downloads,
                    std::chrono::steady_clock::time_point deadline, const QString& what) {
    if (downloads.empty()) return;
    const auto started = std::chrono::steady_clock::now();
    auto waiter = std::make_shared<DirectWaiter>();
    std::vector<uint32_t> ids;
    for (const DirectDownload& d : downloads) ids.push_back(0x600u + d.node), ids.push_back(0x580u + d.node);
    const int watch = context.dispatcher().addWatch(ids, [waiter](const CanFrame& f) { waiter->offer(f); });
    const auto waitedMs = [&] {
        return std::chrono::duration_cast<std::chrono::milliseconds>(std::chrono::steady_clock::now() - started)
            .count();
    };

    // Rounds: the k-th download of every node, side by side.
    std::vector<bool> done(downloads.size(), false);
    std::map<uint8_t, bool> failed;  // nodes whose last download was not confirmed
    for (;;) {
        std::map<uint8_t, size_t> round;  // node -> its next download
        for (size_t i = 0; i < downloads.size(); ++i) {
            if (done[i] || round.count(downloads[i].node)) continue;
            if (failed.count(downloads[i].node)) {  // in order: nothing after a write that was not confirmed
                done[i] = true;
                downloads[i].error = QStringLiteral("not sent: the write before it was not confirmed");
                continue;
            }
            round[downloads[i].node] = i;
        }
        if (round.empty()) break;
        std::map<uint8_t, QString> sendErrors;
        {
            std::lock_guard lock(waiter->mutex);
            waiter->pending.clear();
            for (const auto& [node, i] : round)
                waiter->pending[node].frame =
                    sdo::initiateDownload(node, downloads[i].index, downloads[i].sub, downloads[i].data);
        }
        for (const auto& [node, i] : round) {
            QString error;
            CanFrame f;
            {
                std::lock_guard lock(waiter->mutex);
                f = waiter->pending[node].frame;
            }
            if (!context.send(f, &error)) sendErrors[node] = error;
        }
        std::unique_lock lock(waiter->mutex);
        waiter->changed.wait_until(lock, deadline, [&] {
            for (const auto& [node, p] : waiter->pending)
                if (!sendErrors.count(node) && !(p.seen && p.answered)) return false;
            return true;
        });
        const auto results = waiter->pending;
        lock.unlock();
        for (const auto& [node, i] : round) {
            DirectDownload& d = downloads[i];
            const auto& p = results.at(node);
            done[i] = true;
            d.seen = p.seen;
            d.answered = p.answered && p.abortCode == 0;
            d.abortCode = p.abortCode;
            if (sendErrors.count(node)) d.error = sendErrors[node];
            else if (!p.seen)
                d.error = QStringLiteral("its frame did not come back from the bus within %1 ms").arg(waitedMs());
            else if (p.abortCode)
                d.error = QStringLiteral("%1 refused it: %2").arg(what, context.abortText(node, p.abortCode));
            else if (!p.answered)
                d.error = QStringLiteral("%1 did not confirm it within %2 ms").arg(what).arg(waitedMs());
            else d.error.clear();
            if (!d.error.isEmpty()) failed[node] = true;
        }
    }
    context.dispatcher().removeWatch(watch);
}

}  // namespace coscope::canopen
