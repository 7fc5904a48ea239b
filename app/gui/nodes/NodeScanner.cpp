// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/nodes/NodeScanner.h"

#include "core/canopen/NodeTable.h"
#include "core/canopen/SdoClient.h"
#include "eds/DictionaryLibrary.h"

#include <spdlog/spdlog.h>

#include <memory>

namespace coscope::gui {

namespace {
uint32_t u32le(const QByteArray& b) {
    uint32_t v = 0;
    for (int i = 0; i < b.size() && i < 4; ++i) v |= static_cast<uint32_t>(static_cast<uint8_t>(b[i])) << (8 * i);
    return v;
}
}  // namespace

NodeScanner::NodeScanner(canopen::SdoClient* sdo, canopen::NodeTable* table, QObject* parent) : QObject(parent), sdo_(sdo), table_(table) {}

void NodeScanner::scan(int firstNode, int lastNode, int timeoutMs) {
    if (!sdo_ || isRunning()) return;
    found_.clear();
    canopen::SdoOptions options;
    options.timeoutMs = timeoutMs;
    for (int node = firstNode; node <= lastNode; ++node) {
        ++outstanding_;
        // 1000h device type is mandatory on every CANopen device (CiA 301 §7.5.2.1).
        sdo_->upload(static_cast<uint8_t>(node), 0x1000, 0, [this, node](const canopen::SdoResult& r) {
            if (r.ok || r.serverAborted) {
                found_.insert(node);
                table_->markScanned(node);
                // The scan is finished only once the identities are in: whoever acts on
                // finished() may use the matched dictionaries, and may delete the scanner.
                ++outstanding_;
                identifyThen(node, [this] { done(); });
            }
            done();
        }, options);
    }
}

void NodeScanner::identify(int node) { identifyThen(node, {}); }

void NodeScanner::identifyThen(int node, std::function<void()> then) {
    if (!sdo_) {
        if (then) then();
        return;
    }
    const auto id = static_cast<uint8_t>(node);
    // Per-node transfers run in order: 1000h, 1008h, 1009h, 100Ah, 1018h:01..04; sub 4 is the last.
    auto device = std::make_shared<eds::DeviceIdentity>();
    sdo_->upload(id, 0x1000, 0, [device](const canopen::SdoResult& r) {
        if (r.ok) device->deviceType = u32le(r.data);
    });
    // 1008h device name, 1009h hardware and 100Ah software version are optional (CiA 301
    // §7.5.2.9-11): a node without one aborts the read, which is normal (not present).
    for (const uint16_t index : {uint16_t(0x1008), uint16_t(0x1009), uint16_t(0x100A)}) {
        sdo_->upload(id, index, 0, [this, node, index, device](const canopen::SdoResult& r) {
            if (r.ok) {
                const QString text = QString::fromLatin1(r.data).remove(QChar(0)).trimmed();
                if (index == 0x1008) device->deviceName = text;
                if (index == 0x100A) device->softwareVersion = text;
                table_->setOptionalText(node, index, text);
            } else if (r.serverAborted) {
                table_->setOptionalText(node, index, std::nullopt);
            }
        });
    }
    // 1018h identity object: 1 vendor-ID, 2 product code, 3 revision, 4 serial (CiA 301 §7.5.2.21).
    auto serial = std::make_shared<std::optional<uint32_t>>();
    for (uint8_t sub = 1; sub <= 4; ++sub) {
        sdo_->upload(id, 0x1018, sub, [this, node, sub, device, serial, then](const canopen::SdoResult& r) {
            if (r.ok) (sub == 1 ? device->vendorId : sub == 2 ? device->productCode : sub == 3 ? device->revision : *serial) = u32le(r.data);
            if (sub != 4) return;
            table_->setIdentity(node, device->vendorId, device->productCode, device->revision, *serial);
            if (const auto* e = eds::DictionaryLibrary::shared().match(*device)) {
                table_->setDictionary(node, e->name);
                sdo_->context().setNodeDictionary(static_cast<uint8_t>(node), e->name);
            }
            if (then) then();
        });
    }
}

void NodeScanner::done() {
    if (--outstanding_ == 0) {
        spdlog::info("scan finished: {} nodes answered", found_.size());
        emit finished(static_cast<int>(found_.size()));
    }
}

}  // namespace coscope::gui
