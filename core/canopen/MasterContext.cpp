// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/canopen/MasterContext.h"

#include "core/canopen/PeriodicSender.h"

namespace coscope::canopen {

MasterContext::MasterContext(CanBus* bus, NodeTable* nodes)
    : bus_(bus), ownNodes_(nodes ? nullptr : std::make_unique<NodeTable>()), nodes_(nodes ? nodes : ownNodes_.get()) {}

MasterContext::~MasterContext() = default;

PeriodicSender& MasterContext::periodic() {
    std::lock_guard lock(mutex_);
    if (!periodic_)
        periodic_ =
            std::make_unique<PeriodicSender>([this](const CanFrame& f, QString* error) { return send(f, error); });
    return *periodic_;
}

bool MasterContext::send(const CanFrame& frame, QString* error) {
    if (!bus_) {
        if (error) *error = QStringLiteral("no bus");
        return false;
    }
    QString why;
    if (bus_->send(frame, &why)) return true;
    // CanBus::send names the bus in its own refusals (listen-only, not open).
    if (error)
        *error = why.contains(bus_->url().toString())
                     ? why
                     : QStringLiteral("cannot send on %1: %2").arg(bus_->url().toString(), why);
    return false;
}

void MasterContext::setNodeDictionary(uint8_t node, const QString& name) {
    nodes_->setDictionary(node, name);
    abortTable(name);  // read now, not on the first abort
}

// The vendor abort table of a dictionary, read once; null when it has none (CiA texts only).
std::shared_ptr<VendorAbortTable> MasterContext::abortTable(const QString& dictionary) const {
    if (dictionary.isEmpty()) return nullptr;
    std::lock_guard lock(mutex_);
    auto it = tables_.find(dictionary);
    if (it == tables_.end()) {
        auto table = std::make_shared<VendorAbortTable>();
        if (!table->loadDictionaryTable(dictionary)) table.reset();
        it = tables_.emplace(dictionary, std::move(table)).first;
    }
    return it->second;
}

QString MasterContext::abortText(uint8_t node, uint32_t code) const {
    return describeSdoAbort(code, abortTable(nodes_->dictionary(node)).get());
}

}  // namespace coscope::canopen
