// SPDX-License-Identifier: GPL-3.0-or-later
// Issue 35 item 1, heartbeat consumer and node guarding per node from the Nodes dock: node 3 of
// sim:// (no heartbeat, 1017h = 0) set to node guarding 100 ms x 3 through its context menu and
// the dialog, by clicks and keys. CoScope's RTR on 703h goes out every guard time (CiA 301
// §7.2.8.3.2.1), the node answers with its state and a toggle bit that alternates, the Nodes
// dock shows "guarding 100 ms × 3: ok"; a node that falls silent is "lost" with an event in the
// Events, and "answers again" once it is back. Node 2 (the AIMOTOR, heartbeat on) gets a
// consumer time; its heartbeat switched off makes it lost. On a listen-only bus node guarding
// is off with the reason.
#include "app/gui/MainWindow.h"
#include "app/gui/events/EventLog.h"
#include "app/gui/nodes/NodesDock.h"
#include "app/gui/nodes/NodesModel.h"
#include "app/gui/session/Workspace.h"
#include "core/sim/SimBus.h"
#include "core/sim/SimNetwork.h"
#include "core/sim/VirtualDevice.h"
#include "eds/SimulatorDictionaries.h"

#include <QDialogButtonBox>
#include <QPushButton>
#include <QRadioButton>
#include <QSettings>
#include <QSpinBox>
#include <QTableView>
#include <QtTest>

#include "tests/gui/ContextMenuClick.h"
#include "tests/gui/MenuClick.h"
#include "tests/gui/ModalAnswer.h"
#include "tests/gui/WaitFor.h"

using namespace coscope;
using namespace coscope::gui;
using coscope::testing::clickMenuItem;
using coscope::testing::ModalAnswerer;
using coscope::testing::waitFor;

namespace {
void typeInto(QSpinBox* box, int value) {
    QTest::mouseClick(box, Qt::LeftButton);
    QTest::keyClick(box, Qt::Key_A, Qt::ControlModifier);  // typing replaces what is there
    QTest::keyClicks(box, QString::number(value));
}

// Answers the node's "Heartbeat and guarding" dialog: the radio button `choice`, the values typed.
std::unique_ptr<ModalAnswerer> answerWatchDialog(const QString& choice, std::vector<std::pair<QString, int>> values,
                                                 QString* guardingTip = nullptr) {
    return std::make_unique<ModalAnswerer>([=](QWidget* w) {
        if (w->objectName() != QStringLiteral("errorControlDialog")) return false;
        if (guardingTip) *guardingTip = w->findChild<QRadioButton*>(QStringLiteral("watchGuarding"))->toolTip();
        auto* radio = w->findChild<QRadioButton*>(choice);
        if (!radio || !radio->isEnabled()) {
            QTest::keyClick(w, Qt::Key_Escape);
            return true;
        }
        QTest::mouseClick(radio, Qt::LeftButton, {}, QPoint(5, radio->height() / 2));
        for (const auto& [name, value] : values) typeInto(w->findChild<QSpinBox*>(name), value);
        auto* buttons = w->findChild<QDialogButtonBox*>();
        QTest::mouseClick(buttons->button(QDialogButtonBox::Ok), Qt::LeftButton);
        return true;
    });
}

// The Error control cell of `node` in the Nodes dock.
QString watchCell(NodesDock* dock, int node) {
    NodesModel* m = dock->model();
    const int row = m->rowOfNode(node);
    return row < 0 ? QString() : m->data(m->index(row, NodesModel::ErrorControl), Qt::DisplayRole).toString();
}

bool hasEvent(Workspace* ws, int node, const QString& text) {
    for (const TraceEvent& e : ws->events().since(0))
        if (e.node == node && e.text.contains(text)) return true;
    return false;
}
}  // namespace

class TestNodeGuarding : public QObject {
    Q_OBJECT
    std::unique_ptr<MainWindow> w_;

    Workspace* ws() const { return w_->workspace(); }
    NodesDock* dock() const { return w_->nodesDock(); }
    sim::SimNetwork* net() const { return static_cast<SimBus*>(ws()->bus())->network(); }

    void connect(const QString& url) {
        w_ = std::make_unique<MainWindow>();
        w_->show();
        QVERIFY(QTest::qWaitForWindowActive(w_.get()));
        if (url == u"sim://")
            QVERIFY(clickMenuItem(*w_, QStringLiteral("Bus"), QStringLiteral("Connect to virtual drives")));
        else QVERIFY(w_->connectBus(url, false));
        QVERIFY(waitFor([&] { return ws()->bus() && ws()->bus()->state() == CanBus::State::Open; }));
    }

    // Right-click on the node's row, Heartbeat and guarding….
    bool openWatchDialog(int node) {
        QTableView* view = dock()->view();
        if (!waitFor([&] { return dock()->model()->rowOfNode(node) >= 0; }, 20000)) return false;
        const QPoint pos =
            view->visualRect(dock()->model()->index(dock()->model()->rowOfNode(node), NodesModel::Node)).center();
        QTest::mouseClick(view->viewport(), Qt::LeftButton, {}, pos);
        if (dock()->selectedNode() != node) return false;
        return coscope::testing::contextMenuClick(view, pos, QStringLiteral("Heartbeat and guarding…"));
    }

private slots:
    void initTestCase() {
        QCoreApplication::setOrganizationName(QStringLiteral("CoScopeTest"));
        QCoreApplication::setApplicationName(QStringLiteral("gui_node_guarding"));
        QSettings().clear();
        eds::installSimulatorDictionaries();
    }
    void cleanup() {
        if (w_) w_->setQuiet(true);
        w_.reset();
    }

    void guardingOkThenLostThenBack() {
        connect(QStringLiteral("sim://"));
        if (QTest::currentTestFailed()) return;
        QVERIFY(waitFor([&] { return dock()->model()->rowOfNode(3) >= 0; }, 20000));  // the scan on connect found it
        const size_t before = ws()->store()->size();
        {
            auto answer = answerWatchDialog(QStringLiteral("watchGuarding"), {{QStringLiteral("guardTime"), 100},
                                                                              {QStringLiteral("lifeTimeFactor"), 3}});
            QVERIFY(openWatchDialog(3));
            QVERIFY(waitFor([&] { return answer->answered(); }, 5000));
        }
        QVERIFY2(
            waitFor([&] { return watchCell(dock(), 3).startsWith(QStringLiteral("guarding 100 ms × 3: ok")); }, 3000),
            qPrintable(watchCell(dock(), 3)));
        QTest::qWait(1000);
        // The requests: RTR on 703h, ours, about every 100 ms; the answers: 703h with the NMT
        // state (7Fh pre-operational) and bit 7 alternating, starting with 0.
        std::vector<int64_t> requests;
        std::vector<uint8_t> answers;
        const TraceStore& store = *ws()->store();
        for (size_t n = before; n < store.size(); ++n) {
            const CanFrame f = store.frame(FrameNo(n));
            if (f.id != 0x703) continue;
            if (f.isTx() && f.isRemote()) requests.push_back(f.timestampNs);
            else if (!f.isTx() && !f.isRemote() && f.len == 1) answers.push_back(f.data[0]);
        }
        // At least 8 in the second waited (more when a loaded machine waited longer); their
        // rate is checked by the mean interval below.
        QVERIFY2(requests.size() >= 8, qPrintable(QString::number(requests.size())));
        const int64_t spanMs = (requests.back() - requests.front()) / 1'000'000;
        QVERIFY2(spanMs / int64_t(requests.size() - 1) >= 80 && spanMs / int64_t(requests.size() - 1) <= 130,
                 qPrintable(QString::number(spanMs)));
        QVERIFY(answers.size() + 1 >= requests.size());
        QCOMPARE(answers[0] & 0x80, 0);
        for (size_t i = 0; i < answers.size(); ++i) {
            QCOMPARE(answers[i] & 0x7F, 0x7F);
            QCOMPARE(bool(answers[i] & 0x80), i % 2 == 1);
        }
        // Every request was answered (above): no guarding error, however late this thread reads
        // the answers (the monitor counts misses in the bus's order).
        QCOMPARE(ws()->nodes().node(3)->guardingErrors, 0);

        // The node falls silent: lost after 300 ms, an event in the Events.
        sim::VirtualDevice* device = nullptr;  // found by its node-ID, which it loses now
        net()->runOnNetworkThread([&] {
            device = net()->device(3);
            device->makeUnconfigured();
        });
        QVERIFY2(waitFor([&] { return watchCell(dock(), 3).contains(QStringLiteral(": lost")); }, 2000),
                 qPrintable(watchCell(dock(), 3)));
        QVERIFY(waitFor([&] { return hasEvent(ws(), 3, QStringLiteral("Node guarding lost")); }, 2000));
        QVERIFY(ws()->nodes().node(3)->heartbeatLost);
        QVERIFY(ws()->nodes().node(3)->guardingErrors >= 1);  // the requests nobody answered
        // Back (power cycle: boot-up, the toggle starts at 0 again): ok, and an event says so.
        net()->runOnNetworkThread([&] { device->powerCycle(); });
        QVERIFY2(waitFor([&] { return watchCell(dock(), 3).contains(QStringLiteral(": ok")); }, 3000),
                 qPrintable(watchCell(dock(), 3)));
        QVERIFY(waitFor([&] { return hasEvent(ws(), 3, QStringLiteral("Node guarding answers again")); }, 2000));

        // Not watched any more: the requests stop.
        {
            auto answer = answerWatchDialog(QStringLiteral("watchNone"), {});
            QVERIFY(openWatchDialog(3));
            QVERIFY(waitFor([&] { return answer->answered(); }, 5000));
        }
        QVERIFY(waitFor([&] { return watchCell(dock(), 3).isEmpty(); }, 2000));
        QTest::qWait(200);
        const size_t after = ws()->store()->size();
        QTest::qWait(500);
        for (size_t n = after; n < ws()->store()->size(); ++n)
            QVERIFY(!(ws()->store()->frame(FrameNo(n)).id == 0x703 && ws()->store()->frame(FrameNo(n)).isRemote()));
    }

    void heartbeatConsumerTimeLost() {
        connect(QStringLiteral("sim://"));
        if (QTest::currentTestFailed()) return;
        QVERIFY(waitFor([&] { return dock()->model()->rowOfNode(2) >= 0; }, 20000));
        net()->runOnNetworkThread([&] { net()->device(2)->setValue(0x1017, 0, od::Value::unsignedInt(50)); });
        {
            auto answer = answerWatchDialog(QStringLiteral("watchHeartbeat"), {{QStringLiteral("consumerTime"), 300}});
            QVERIFY(openWatchDialog(2));
            QVERIFY(waitFor([&] { return answer->answered(); }, 5000));
        }
        QVERIFY2(waitFor([&] { return watchCell(dock(), 2).startsWith(QStringLiteral("heartbeat 300 ms: ok")); }, 3000),
                 qPrintable(watchCell(dock(), 2)));
        net()->runOnNetworkThread([&] { net()->device(2)->setValue(0x1017, 0, od::Value::unsignedInt(0)); });
        QVERIFY2(waitFor([&] { return watchCell(dock(), 2).contains(QStringLiteral(": lost")); }, 2000),
                 qPrintable(watchCell(dock(), 2)));
        QVERIFY(waitFor(
            [&] {
                return hasEvent(ws(), 2, QStringLiteral("Heartbeat lost: none within the consumer time of 300 ms"));
            },
            2000));
    }

    // Listen-only: node guarding is off in the dialog, with the reason; nothing is sent.
    void listenOnlyRefusesGuarding() {
        connect(QStringLiteral("sim://?listen-only=1"));
        if (QTest::currentTestFailed()) return;
        ws()->nodes().update(3,
                             [](canopen::NodeInfo&) {});  // a node the user sees (a listen-only bus cannot be scanned)
        QString tip;
        {
            auto answer = answerWatchDialog(QStringLiteral("watchGuarding"), {}, &tip);
            QVERIFY(openWatchDialog(3));
            QVERIFY(waitFor([&] { return answer->answered(); }, 5000));
        }
        QVERIFY2(tip.contains(QStringLiteral("Listen-only")), qPrintable(tip));
        QTest::qWait(300);
        QVERIFY(watchCell(dock(), 3).isEmpty());
        for (size_t n = 0; n < ws()->store()->size(); ++n) QVERIFY(!ws()->store()->frame(FrameNo(n)).isTx());
    }
};

QTEST_MAIN(TestNodeGuarding)
#include "test_node_guarding.moc"
