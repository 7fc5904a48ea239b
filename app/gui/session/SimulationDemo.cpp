// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/session/SimulationDemo.h"

#include "app/gui/nodes/NodeScanner.h"
#include "app/gui/session/Workspace.h"
#include "core/canopen/MasterContext.h"
#include "core/canopen/Nmt.h"
#include "core/canopen/SdoClient.h"
#include "core/canopen/SyncProducer.h"
#include "core/od/Value.h"
#include "eds/DictionaryLibrary.h"

#include <QTimer>

#include <functional>
#include <iterator>
#include <memory>
#include <vector>

#include <spdlog/spdlog.h>

namespace coscope::gui {

namespace {

struct Write {
    uint16_t index;
    uint8_t sub;
    QByteArray data;
};
QByteArray le(int64_t v, int bytes) {
    QByteArray b;
    for (int i = 0; i < bytes; ++i) b.append(static_cast<char>((v >> (8 * i)) & 0xFF));
    return b;
}

// One SDO write after the other (one outstanding request, as drives like); `done` after the last.
void writeInOrder(Workspace* ws, uint8_t node, std::shared_ptr<std::vector<Write>> writes, size_t i,
                  std::function<void()> done) {
    if (i >= writes->size()) {
        done();
        return;
    }
    if (!ws->sdo()) return;
    const Write& w = (*writes)[i];
    ws->sdo()->download(node, w.index, w.sub, w.data, [ws, node, writes, i, done, w](const canopen::SdoResult& r) {
        if (!r.ok) {
            spdlog::warn("simulation: node {} {:04X}h:{:02X}: {}", node, w.index, w.sub, r.error.toStdString());
            return;  // never retried; the demo stops here
        }
        writeInOrder(ws, node, writes, i + 1, done);
    });
}

// The AIMOTOR drive runs a gentle profile-velocity cycle so that its TPDOs (TPDO1: 6041h,
// 6061h, 6064h; TPDO2: 606Ch, 6077h, sent on every SYNC: extract-aimotor §3.6 default
// mappings, transmission type 1) show motion. Virtual network only.
void startMotion(Workspace* ws, uint8_t node) {
    auto writes = std::make_shared<std::vector<Write>>(std::vector<Write>{
        {0x2002, 0x01, le(8, 2)},      // H02-00 = 8: CANopen control (extract-aimotor notes)
        {0x6060, 0x00, le(3, 1)},      // modes of operation: profile velocity (CiA 402-2 Table 35)
        {0x6083, 0x00, le(20000, 4)},  // profile acceleration, pulse/s²
        {0x6084, 0x00, le(20000, 4)},  // profile deceleration
        {0x60FF, 0x00, le(0, 4)},      // target velocity 0 until enabled
        {0x6040, 0x00, le(0x06, 2)},   // shutdown -> READY TO SWITCH ON
        {0x6040, 0x00, le(0x07, 2)},   // switch on -> SWITCHED ON
        {0x6040, 0x00, le(0x0F, 2)},   // enable operation -> OPERATION ENABLED
    });
    writeInOrder(ws, node, writes, 0, [ws, node] {
        if (!ws->master()) return;
        // The bus's own SYNC producer (Bus ▸ SYNC producer shows it running and stops it).
        canopen::SyncProducer* sync = ws->syncProducer();
        if (!sync) return;
        auto* holder = new QObject(ws);
        sync->setPeriodUs(10000);  // 100 Hz SYNC: the TPDOs follow it
        QString error;
        if (!sync->start(&error)) spdlog::warn("simulation: SYNC: {}", error.toStdString());
        auto* step = new QTimer(holder);
        step->setInterval(2000);
        auto index = std::make_shared<size_t>(0);
        QObject::connect(step, &QTimer::timeout, holder, [ws, node, index] {
            // Target velocities in pulse/s (1000 pulses = 1 rev: 3000 pulse/s = 180 rpm).
            static const int64_t profile[] = {3000, 6000, 4000, -2000, -5000, 0};
            const int64_t v = profile[(*index)++ % std::size(profile)];
            if (ws->sdo()) ws->sdo()->download(node, 0x60FF, 0x00, le(v, 4), [](const canopen::SdoResult&) {});
        });
        step->start();
        QMetaObject::invokeMethod(step, "timeout");  // first target at once
        // The master context goes with the source: stop before anything else runs.
        QObject::connect(ws, &Workspace::sourceChanged, holder, [holder, step] {
            step->stop();
            holder->deleteLater();
        });
        spdlog::info("simulation: node {} enabled in profile velocity, SYNC every 10 ms", node);
    });
}

}  // namespace

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
        auto* scanner = new NodeScanner(ws->sdo(), ws);
        // The scanner's identity reads may still be under way when it reports finished: it
        // lives until the source changes (its SDO client is gone by then).
        QObject::connect(ws, &Workspace::sourceChanged, scanner, &QObject::deleteLater);
        QObject::connect(scanner, &NodeScanner::finished, ws, [ws] {
            if (!ws->canTransmit()) return;
            for (const canopen::NodeInfo& n : ws->nodes().snapshot()) {
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
            if (!ws->master()->send(canopen::nmtFrame(canopen::NmtCommand::Start, 0), &error))
                spdlog::warn("simulation: {}", error.toStdString());
            spdlog::info("simulation: nodes identified, heartbeats on, network started");
            // The AIMOTOR moves once the node table knows it (identity reads may still run).
            auto tries = std::make_shared<int>(0);
            auto* wait = new QTimer(ws);
            wait->setInterval(250);
            QObject::connect(wait, &QTimer::timeout, ws, [ws, wait, tries] {
                for (const canopen::NodeInfo& n : ws->nodes().snapshot())
                    if (n.scanned && n.dictionary == u"aimotor" && ws->canTransmit()) {
                        wait->deleteLater();
                        startMotion(ws, static_cast<uint8_t>(n.node));
                        return;
                    }
                // A minute: identity reads of a loaded machine or a sanitizer build come late.
                if (++*tries >= 240 || !ws->canTransmit()) {
                    if (*tries >= 240)
                        spdlog::warn(
                            "simulation: the AIMOTOR was not identified within 60 s; the demo does not move it");
                    wait->deleteLater();
                }
            });
            QObject::connect(ws, &Workspace::sourceChanged, wait, &QObject::deleteLater);
            wait->start();
        });
        // The simulated nodes exist: wait as long as the SDO default (1 s) so that a loaded
        // machine or a sanitizer build, whose simulator answers late, still finds them.
        scanner->scan(1, 127, 1000);
    });
    poll->start();
}

}  // namespace coscope::gui
