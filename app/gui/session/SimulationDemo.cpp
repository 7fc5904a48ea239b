// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/session/SimulationDemo.h"

#include "app/gui/nodes/NodeScanner.h"
#include "app/gui/session/Workspace.h"
#include "core/canopen/MasterContext.h"
#include "core/canopen/Nmt.h"
#include "core/canopen/SdoClient.h"

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
                // 1017h is UNSIGNED16 (CiA 301 §7.5.2.31); some dictionaries declare it wider.
                const auto node = static_cast<uint8_t>(n.node);
                ws->sdo()->download(node, 0x1017, 0, QByteArray("\xF4\x01", 2), [ws, node](const canopen::SdoResult& r) {
                    if (r.ok || !ws->sdo()) return;
                    if ((r.abortCode & 0xFFFFFFF0u) == 0x06070010u)
                        ws->sdo()->download(node, 0x1017, 0, QByteArray("\xF4\x01\x00\x00", 4), [](const canopen::SdoResult&) {});
                    else
                        spdlog::warn("simulation: {}", r.error.toStdString());
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
