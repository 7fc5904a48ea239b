// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/canopen/MasterContext.h"

#include <QByteArray>
#include <QObject>
#include <QString>

#include <cstdint>
#include <deque>
#include <functional>
#include <map>
#include <memory>

class QTimer;

namespace coscope::canopen {

// How one SDO transfer goes on the bus.
struct SdoOptions {
    enum class Protocol : uint8_t {
        Auto,   // expedited when the data fits 4 bytes, otherwise segmented
        Block,  // block transfer (CiA 301 §7.2.4.3.9); segmented when the server declines it
    };
    Protocol protocol = Protocol::Auto;
    int timeoutMs = 0;        // per response; 0 = the client's default (1 s)
    uint8_t blockSize = 127;  // segments per sub-block the client accepts (block upload)
    // Download: called with the bytes the server confirmed so far and the total, after each
    // confirmed segment or sub-block (on the client's thread; throttle in the caller).
    std::function<void(qint64 done, qint64 total)> progress;
};

// The outcome of one transfer. `error` is one line naming the node and object, e.g.
// "node 5 aborted 2000:01: Object does not exist in the object dictionary (0x06020000)".
struct SdoResult {
    quint64 id = 0;
    bool upload = true;
    uint8_t node = 0;
    uint16_t index = 0;
    uint8_t sub = 0;
    bool ok = false;
    QByteArray data;             // upload: the bytes read
    uint32_t abortCode = 0;      // the code the server sent, or the one we sent it
    bool serverAborted = false;  // the server aborted the transfer
    bool timedOut = false;
    bool fellBackToSegmented = false;  // block transfer was declined; segmented was used
    int framesSent = 0;
    int framesReceived = 0;
    QString error;
};

using SdoCallback = std::function<void(const SdoResult&)>;

// "2000:01"
QString objectRef(uint16_t index, uint8_t sub);

// SDO client (CiA 301 §7.2.4): expedited, segmented and block upload/download to any node,
// one transfer at a time per node (the others wait in that node's queue, in order). Lives on
// the thread that created it and never blocks it: upload()/download() return at once and the
// callback runs later on this thread. Frames arrive through the context's dispatcher, filtered
// to 580h + the nodes with a transfer in progress.
//
// Nothing is retried: a failed or timed-out write is reported, never repeated; a failed read is
// reported too (the caller may ask again). The one fallback is protocol-level: when a server
// declines block transfer at the initiate step (nothing was transferred yet), the transfer
// continues as segmented and the result says so.
class SdoClient : public QObject {
    Q_OBJECT
public:
    explicit SdoClient(MasterContext& context, QObject* parent = nullptr);
    ~SdoClient() override;

    void setDefaultTimeout(int ms) { defaultTimeoutMs_ = ms > 0 ? ms : 1000; }
    int defaultTimeout() const { return defaultTimeoutMs_; }

    quint64 upload(uint8_t node, uint16_t index, uint8_t sub, SdoCallback done, SdoOptions options = {});
    quint64 download(uint8_t node, uint16_t index, uint8_t sub, QByteArray data, SdoCallback done,
                     SdoOptions options = {});

    // Aborts every active and queued transfer (active ones with abort code 08000000h to the
    // server); each callback reports "cancelled".
    void cancelAll();
    // Cancels one transfer: an active one is aborted with 08000000h (general error: CiA 301
    // §7.2.4.3.17 has no code of its own for a client that gives up), a queued one is dropped;
    // its callback reports "cancelled". False when the id is not pending.
    bool cancel(quint64 id);
    int pendingCount() const;

    MasterContext& context() const { return context_; }

signals:
    // A download the server confirmed, whoever asked for it (a wizard, a dock, a script): views
    // holding values read before show the new one (issue 35: 6040h after the wizard's Disable).
    void written(quint8 node, quint16 index, quint8 sub, const QByteArray& data);

private:
    struct Transfer;
    struct NodeQueue;

    quint64 enqueue(std::unique_ptr<Transfer> t);
    void pump(uint8_t node);
    void start(NodeQueue& q);
    void onFrames(const std::vector<CanFrame>& frames);
    void onFrame(NodeQueue& q, const CanFrame& frame);
    void onTimeout(uint8_t node);
    bool sendStep(NodeQueue& q, const CanFrame& frame);
    void armTimer(NodeQueue& q);
    void finish(NodeQueue& q, bool ok, const QString& error = {});
    void abortTransfer(NodeQueue& q, uint32_t code, const QString& why);
    void serverAbort(NodeQueue& q, uint32_t code);
    void updateSubscription();

    // protocol steps
    void startUploadSegmented(NodeQueue& q);
    void startDownloadSegmented(NodeQueue& q);
    void sendNextDownloadSegment(NodeQueue& q);
    void sendDownloadSubBlock(NodeQueue& q);
    void handleSegmented(NodeQueue& q, const CanFrame& frame);
    void handleBlockUpload(NodeQueue& q, const CanFrame& frame);
    void handleBlockDownload(NodeQueue& q, const CanFrame& frame);

    MasterContext& context_;
    int subscription_ = 0;
    int defaultTimeoutMs_ = 1000;
    quint64 nextId_ = 1;
    std::map<uint8_t, std::unique_ptr<NodeQueue>> queues_;
    std::vector<uint32_t> subscribedIds_;
};

}  // namespace coscope::canopen
