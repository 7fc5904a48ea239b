// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/canopen/NetworkScan.h"

#include <QPointer>
#include <QTimer>

#include <algorithm>

namespace coscope::canopen {

namespace {
uint32_t u32(const QByteArray& b) {
    uint32_t v = 0;
    for (int i = 0; i < std::min<int>(4, static_cast<int>(b.size())); ++i) v |= uint32_t(uint8_t(b[i])) << (8 * i);
    return v;
}
}  // namespace

NetworkScan::NetworkScan(SdoClient& sdo, QObject* parent) : QObject(parent), sdo_(&sdo), pacer_(new QTimer(this)) {
    pacer_->setSingleShot(true);
    connect(pacer_, &QTimer::timeout, this, &NetworkScan::launchMore);
}

void NetworkScan::start(Done done) {
    done_ = std::move(done);
    found_.clear();
    running_ = true;
    next_ = std::max<int>(1, first_);
    outstanding_ = 0;
    probed_ = 0;
    QMetaObject::invokeMethod(this, &NetworkScan::launchMore, Qt::QueuedConnection);
}

void NetworkScan::launchMore() {
    if (!running_) return;
    if (!sdo_) {
        running_ = false;
        return;
    }
    if (next_ > std::min<int>(127, last_)) {
        if (outstanding_ == 0) {
            running_ = false;
            std::sort(found_.begin(), found_.end(), [](const auto& a, const auto& b) { return a.node < b.node; });
            if (done_) done_(found_);
        }
        return;
    }
    if (outstanding_ >= maxOutstanding_) return;  // nodeDone() calls back
    probe(static_cast<uint8_t>(next_++));
    // One new request per interval.
    pacer_->start(intervalMs_);
}

void NetworkScan::probe(uint8_t node) {
    ++outstanding_;
    SdoOptions o;
    o.timeoutMs = timeoutMs_;
    QPointer<NetworkScan> self(this);
    sdo_->upload(
        node, 0x1000, 0,
        [self, node](const SdoResult& r) {
            if (!self) return;
            ++self->probed_;
            // Any answer, even an abort, means a node is there.
            if (!r.ok && !r.serverAborted) return self->nodeDone();
            auto found = std::make_shared<ScannedNode>();
            found->node = node;
            if (r.ok) found->deviceType = u32(r.data);
            self->readIdentity(found, 1);
        },
        o);
}

void NetworkScan::readIdentity(std::shared_ptr<ScannedNode> found, uint8_t sub) {
    if (!sdo_) return;
    if (sub > 4) return readStrings(found, 0);
    SdoOptions o;
    o.timeoutMs = timeoutMs_;
    QPointer<NetworkScan> self(this);
    sdo_->upload(
        found->node, 0x1018, sub,
        [self, found, sub](const SdoResult& r) {
            if (!self) return;
            if (r.ok) {
                const uint32_t v = u32(r.data);
                switch (sub) {
                case 1: found->vendorId = v; break;
                case 2: found->productCode = v; break;
                case 3: found->revision = v; break;
                case 4: found->serial = v; break;
                }
            } else if (sub <= 1) {
                found->error = r.error;  // 1018h:01 is mandatory; the rest are optional
            }
            self->readIdentity(found, static_cast<uint8_t>(sub + 1));
        },
        o);
}

// 1008h device name, 1009h hardware version, 100Ah software version: VISIBLE_STRING, optional.
void NetworkScan::readStrings(std::shared_ptr<ScannedNode> found, int which) {
    static constexpr uint16_t kIndex[] = {0x1008, 0x1009, 0x100A};
    static constexpr uint8_t kBit[] = {NodeInfo::kNoDeviceName, NodeInfo::kNoHardwareVersion,
                                       NodeInfo::kNoSoftwareVersion};
    if (!sdo_) return;
    if (which >= 3) return finishNode(found);
    SdoOptions o;
    o.timeoutMs = timeoutMs_;
    QPointer<NetworkScan> self(this);
    sdo_->upload(
        found->node, kIndex[which], 0,
        [self, found, which](const SdoResult& r) {
            if (!self) return;
            if (r.ok) {
                const QString text =
                    QString::fromUtf8(r.data).section(QChar(0), 0, 0).trimmed();  // some devices pad with NULs
                (which == 0 ? found->deviceName : which == 1 ? found->hardwareVersion : found->softwareVersion) = text;
            } else if (r.serverAborted) {
                found->notPresent |= kBit[which];
            }
            self->readStrings(found, which + 1);
        },
        o);
}

void NetworkScan::finishNode(std::shared_ptr<ScannedNode> found) {
    if (matcher_) found->dictionary = matcher_(*found);
    NodeTable& table = sdo_->context().nodes();
    const int id = found->node;
    table.markScanned(id);
    table.update(id, [&](NodeInfo& info) { info.deviceType = found->deviceType; });
    table.setIdentity(id, found->vendorId, found->productCode, found->revision, found->serial);
    // An optional string read or refused is written; one not answered leaves what was known.
    static constexpr uint16_t kIndex[] = {0x1008, 0x1009, 0x100A};
    static constexpr uint8_t kBit[] = {NodeInfo::kNoDeviceName, NodeInfo::kNoHardwareVersion,
                                       NodeInfo::kNoSoftwareVersion};
    const std::optional<QString>* texts[] = {&found->deviceName, &found->hardwareVersion, &found->softwareVersion};
    for (int i = 0; i < 3; ++i)
        if (*texts[i] || (found->notPresent & kBit[i])) table.setOptionalText(id, kIndex[i], *texts[i]);
    if (!found->dictionary.isEmpty()) {
        table.setDictionary(id, found->dictionary);
        sdo_->context().setNodeDictionary(found->node, found->dictionary);
    }
    found_.push_back(*found);
    nodeDone();
}

void NetworkScan::nodeDone() {
    --outstanding_;
    if (!pacer_->isActive()) launchMore();
}

}  // namespace coscope::canopen
