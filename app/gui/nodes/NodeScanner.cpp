// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/nodes/NodeScanner.h"

#include "app/gui/nodes/NodeTable.h"
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

NodeScanner::NodeScanner(canopen::SdoClient* sdo, NodeTable* table, QObject* parent) : QObject(parent), sdo_(sdo), table_(table) {}

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
    // 1008h device name, 1009h hardware and 100Ah software version are optional (CiA 301
    // §7.5.2.9-11): a node without one aborts the read, which is normal (not present).
    for (const uint16_t index : {uint16_t(0x1008), uint16_t(0x1009), uint16_t(0x100A)}) {
        sdo_->upload(id, index, 0, [this, node, index](const canopen::SdoResult& r) {
            if (r.ok) table_->setOptionalText(node, index, QString::fromLatin1(r.data).remove(QChar(0)).trimmed());
            else if (r.serverAborted) table_->setOptionalText(node, index, std::nullopt);
        });
    }
    // 1018h identity object: 1 vendor-ID, 2 product code, 3 revision, 4 serial (CiA 301 §7.5.2.21).
    auto parts = std::make_shared<std::array<std::optional<uint32_t>, 4>>();
    for (uint8_t sub = 1; sub <= 4; ++sub) {
        sdo_->upload(id, 0x1018, sub, [this, node, sub, parts, then](const canopen::SdoResult& r) {
            if (r.ok) (*parts)[sub - 1] = u32le(r.data);
            if (sub != 4) return;  // per-node transfers run in order: sub 4 is the last
            const auto& p = *parts;
            table_->setIdentity(node, p[0], p[1], p[2], p[3]);
            if (p[0] && p[1]) {
                const eds::DictionaryLibrary library;
                if (const auto* e = library.findByIdentity(*p[0], *p[1], p[2])) {
                    table_->setDictionary(node, e->name);
                    sdo_->context().setNodeDictionary(static_cast<uint8_t>(node), e->name);
                }
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
