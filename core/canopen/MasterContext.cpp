// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/canopen/MasterContext.h"

namespace coscope::canopen {

MasterContext::MasterContext(CanBus* bus) : bus_(bus) {}

bool MasterContext::send(const CanFrame& frame, QString* error) {
    if (!bus_) {
        if (error) *error = QStringLiteral("no bus");
        return false;
    }
    QString why;
    if (bus_->send(frame, &why)) return true;
    if (error) *error = QStringLiteral("cannot send on %1: %2").arg(bus_->url().toString(), why);
    return false;
}

void MasterContext::setNodeDictionary(uint8_t node, const QString& name) {
    std::lock_guard lock(mutex_);
    dictionaries_[node] = name;
    if (name.isEmpty() || tables_.count(name)) return;
    auto table = std::make_shared<VendorAbortTable>();
    if (!table->loadDictionaryTable(name)) table.reset();  // no vendor table: CiA texts only
    tables_[name] = table;
}

QString MasterContext::nodeDictionary(uint8_t node) const {
    std::lock_guard lock(mutex_);
    auto it = dictionaries_.find(node);
    return it == dictionaries_.end() ? QString() : it->second;
}

QString MasterContext::abortText(uint8_t node, uint32_t code) const {
    std::shared_ptr<VendorAbortTable> table;
    {
        std::lock_guard lock(mutex_);
        auto d = dictionaries_.find(node);
        if (d != dictionaries_.end()) {
            auto t = tables_.find(d->second);
            if (t != tables_.end()) table = t->second;
        }
    }
    return describeSdoAbort(code, table.get());
}

}  // namespace coscope::canopen
