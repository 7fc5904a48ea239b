// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/session/SimulationDemo.h"

#include "app/gui/nodes/NodeScanner.h"
#include "app/gui/session/Workspace.h"
#include "core/canopen/MasterContext.h"
#include "core/canopen/Nmt.h"
#include "core/canopen/SdoClient.h"
#include "core/od/Value.h"
#include "eds/DictionaryLibrary.h"

#include <QTimer>

#include <spdlog/spdlog.h>

namespace coscope::gui {

void startSimulationDemo(Workspace* ws) {
    auto* poll = new QTimer(ws);
    poll->setInterval(50);
    QObject::connect(poll, &QTimer::timeout, ws, [ws, poll] {
        CanBus* bus = ws->bus();
        if (!bus || bus->url().scheme != u"sim") {
            poll->deleteLater();
            return;
        }
        if (!ws->canTransmit() || !ws->sdo()) return;  // still opening
        poll->stop();
        poll->deleteLater();
        auto* scanner = new NodeScanner(ws->sdo(), &ws->nodes(), ws);
        QObject::connect(scanner, &NodeScanner::finished, ws, [ws, scanner] {
            scanner->deleteLater();
            if (!ws->canTransmit()) return;
            for (const NodeInfo& n : ws->nodes().snapshot()) {
                if (!n.scanned) continue;
                // Producer heartbeat time 1017h = 500 ms, encoded as the node's dictionary
                // declares it (CiA 301 says UNSIGNED16; AIMOTOR declares UNSIGNED32). One write,
                // never retried.
                const auto node = static_cast<uint8_t>(n.node);
                od::DataType type = od::DataType::Unsigned16;
                if (!n.dictionary.isEmpty()) {
                    const eds::ReadResult dict = eds::loadDictionaryByPathOrName(n.dictionary);
                    if (const od::SubObject* e = dict.dictionary.entry(0x1017, 0)) type = e->dataType;
                }
                QString encodeError;
                const QByteArray value = od::Value::unsignedInt(500).encode(type, &encodeError);
                if (value.isEmpty()) {
                    spdlog::warn("simulation: node {} 1017h: {}", node, encodeError.toStdString());
                    continue;
                }
                ws->sdo()->download(node, 0x1017, 0, value, [](const canopen::SdoResult& r) {
                    if (!r.ok) spdlog::warn("simulation: {}", r.error.toStdString());
                });
            }
            QString error;
            if (!ws->master()->send(canopen::nmtFrame(canopen::NmtCommand::Start, 0), &error)) spdlog::warn("simulation: {}", error.toStdString());
            spdlog::info("simulation: nodes identified, heartbeats on, network started");
        });
        scanner->scan(1, 127, 200);
    });
    poll->start();
}

}  // namespace coscope::gui
