// SPDX-License-Identifier: GPL-3.0-or-later
// What ObjectDictionaryDock learns from the rest of the app (issue 35): a value another part of
// the app wrote over SDO (the CiA 402 wizard's Disable writes 6040h) shows the value the node
// confirmed, for the shown node at once and for a node shown before when it is shown again; a
// node moved to another node-ID (the node-ID wizard) is followed to its new ID, and what was
// read at the old ID is dropped (nothing answers there any more).
#include "app/gui/od/ObjectDictionaryDock.h"

#include "app/gui/od/OdTreeModel.h"
#include "app/gui/session/Workspace.h"
#include "core/canopen/DeviceConfiguration.h"
#include "core/canopen/SdoClient.h"

#include <QLabel>

namespace coscope::gui {

void ObjectDictionaryDock::watchSdo() {
    disconnect(sdoWritten_);
    if (auto* sdo = workspace_->sdo())
        sdoWritten_ = connect(sdo, &canopen::SdoClient::written, this, &ObjectDictionaryDock::onWritten);
    movesSeen_ = workspace_->nodes().moves().size();
}

void ObjectDictionaryDock::onWritten(quint8 node, quint16 index, quint8 sub, const QByteArray& data) {
    if (node == node_ && model_->hasDictionary()) {
        const od::SubObject* e = model_->dictionary().entry(index, sub);
        // The confirmed download is what the node holds now (CiA 301 §7.2.4.3.3/§7.2.4.3.5).
        if (e && canopen::DeviceConfiguration::decodeUpload(e->dataType, data).ok())
            model_->setUploaded(index, sub, data);
        updateHeader();
        return;
    }
    if (auto kept = kept_.find(node); kept != kept_.end()) kept->second.written[(uint32_t(index) << 8) | sub] = data;
}

void ObjectDictionaryDock::applyWritten(const KeptNode& kept) {
    for (const auto& [key, data] : kept.written) {
        const auto index = static_cast<uint16_t>(key >> 8);
        const auto sub = static_cast<uint8_t>(key & 0xFF);
        const od::SubObject* e = model_->dictionary().entry(index, sub);
        if (e && canopen::DeviceConfiguration::decodeUpload(e->dataType, data).ok())
            model_->setUploaded(index, sub, data);
    }
}

void ObjectDictionaryDock::followMoves() {
    const std::vector<canopen::NodeTable::Move> moves = workspace_->nodes().moves();
    if (moves.size() < movesSeen_) movesSeen_ = 0;  // the table was cleared
    for (size_t i = movesSeen_; i < moves.size(); ++i) {
        const auto [from, to] = moves[i];
        // The device's values were read at `from`; what was kept for `to` was another device.
        kept_.erase(to);
        if (node_ == from) {
            setNode(to);
            showMessage(tr("Node %1 now answers at node-ID %2: showing node %2. Values read at node %1 were dropped; "
                           "read them again.")
                            .arg(from)
                            .arg(to));
        }
        kept_.erase(from);
    }
    movesSeen_ = moves.size();
}

}  // namespace coscope::gui
