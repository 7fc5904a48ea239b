// SPDX-License-Identifier: GPL-3.0-or-later
// Issue 16 "Lost adapter" as the technician sees it: the virtual drives served over socketcand,
// the CiA 402 wizard enables a drive by clicks, then the server dies. The status bar says
// "lost, retrying in N s", the wizard stops and says the drive may still be enabled, the Nodes
// table shows the node states as unknown; the server comes back: "open", the trace marks the gap.
#include "app/gui/MainWindow.h"
#include "app/gui/nodes/NodesDock.h"
#include "app/gui/nodes/NodesModel.h"
#include "app/gui/session/Workspace.h"
#include "app/gui/status/BusStatusBar.h"
#include "app/gui/trace/TraceModel.h"
#include "app/gui/wizards/WizardMenu.h"
#include "app/gui/wizards/ds402/Ds402Wizard.h"
#include "core/sim/SimNetwork.h"
#include "core/sim/SocketcandServer.h"
#include "core/sim/VirtualDevice.h"
#include "eds/SimulatorDictionaries.h"

#include <QLabel>
#include <QMessageBox>
#include <QPointer>
#include <QPushButton>
#include <QSignalSpy>
#include <QTableView>
#include <QtTest>

#include "tests/gui/ModalAnswer.h"

using namespace coscope;
using namespace coscope::gui;
using canopen::ds402::Command;
using canopen::ds402::State;

namespace {
bool clickStep(Ds402Wizard& w, Command c) {
    QPushButton* b = w.stepButton(c);
    if (!b || !QTest::qWaitFor([&] { return b->isEnabled(); }, 5000)) return false;
    QSignalSpy done(&w, &Ds402Wizard::stepFinished);
    QTest::mouseClick(b, Qt::LeftButton);
    return (done.count() > 0 || done.wait(6000)) && done.first().first().toBool();
}

std::unique_ptr<sim::SocketcandServer> serve(const std::shared_ptr<sim::SimNetwork>& net, quint16 port) {
    auto server = std::make_unique<sim::SocketcandServer>(net);
    QString error;
    if (!server->listen(QHostAddress::LocalHost, port, &error)) qWarning("listen: %s", qPrintable(error));
    return server;
}
}  // namespace

class TestLostAdapter : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() {
        QCoreApplication::setOrganizationName(QStringLiteral("CoScopeTest"));
        QCoreApplication::setApplicationName(QStringLiteral("gui_lost_adapter"));
        eds::installSimulatorDictionaries();
    }

    void lostShownWizardStoppedAndBack() {
        QString error;
        std::shared_ptr<sim::SimNetwork> net = sim::SimNetwork::fromSpec(QStringLiteral("1:generic-cia402"), &error);
        QVERIFY2(net, qPrintable(error));
        net->start();
        // The drive produces a heartbeat every 500 ms (1017h), as a commissioned drive does.
        net->runOnNetworkThread([&] { net->device(1)->writeFromSdo(0x1017, 0, QByteArray::fromHex("f401")); });
        auto server = serve(net, 0);
        const quint16 port = server->serverPort();
        QVERIFY(port != 0);

        MainWindow w;
        w.setQuiet(true);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QVERIFY(w.connectBus(QStringLiteral("socketcand://127.0.0.1:%1/can0").arg(port)));
        QTRY_VERIFY_WITH_TIMEOUT(w.busStatus()->stateText().startsWith(QStringLiteral("open")), 10000);

        QPointer<QWidget> window = openWizard(QStringLiteral("ds402"), w.workspace(), 1, &w);
        auto* wiz = qobject_cast<Ds402Wizard*>(window.data());
        QVERIFY(wiz);
        QVERIFY(QTest::qWaitForWindowExposed(wiz));
        QVERIFY(QTest::qWaitFor([&] { return wiz->shownState() == State::SwitchOnDisabled; }, 10000));
        QVERIFY(clickStep(*wiz, Command::Shutdown));
        QVERIFY(clickStep(*wiz, Command::SwitchOn));
        {
            QString asked;
            auto yes = coscope::testing::answerBox(QMessageBox::Yes, &asked);
            QVERIFY(clickStep(*wiz, Command::EnableOperation));
        }
        QVERIFY(wiz->shownState() == State::OperationEnabled);
        QTRY_VERIFY_WITH_TIMEOUT(w.workspace()->nodes().node(1).has_value(), 5000);

        server.reset();  // the socketcand server dies
        QTRY_VERIFY_WITH_TIMEOUT(w.busStatus()->stateText().startsWith(QStringLiteral("lost, retrying in")), 5000);
        QVERIFY2(QTest::qWaitFor([&] { return wiz->message().contains(QStringLiteral("may still be enabled")); }, 3000),
                 qPrintable(wiz->message()));
        QVERIFY2(wiz->message().contains(QStringLiteral("Operation enabled")), qPrintable(wiz->message()));
        QVERIFY2(wiz->message().contains(QStringLiteral("Check at the drive")), qPrintable(wiz->message()));
        QVERIFY(!wiz->stepButton(Command::DisableOperation) ||
                !wiz->stepButton(Command::DisableOperation)->isEnabled());
        QAbstractItemModel* nodes = w.nodesDock()->view()->model();
        QTRY_VERIFY_WITH_TIMEOUT(nodes->rowCount() > 0 && nodes->index(0, NodesModel::State).data().toString() ==
                                                              QStringLiteral("unknown (gap)"),
                                 3000);
        const size_t eventsBefore = w.workspace()->events().size();
        QTest::qWait(2500);  // longer than the heartbeat timeout (3 periods, at least 1.5 s)

        server = serve(net, port);  // back
        QTRY_VERIFY_WITH_TIMEOUT(w.busStatus()->stateText().startsWith(QStringLiteral("open")), 10000);
        QTRY_VERIFY_WITH_TIMEOUT(w.workspace()->store()->gaps().size() == 1, 3000);
        QVERIFY2(wiz->message().contains(QStringLiteral("may still be enabled")),
                 qPrintable(wiz->message()));  // kept on return
        // The technician reads the drive again: it is indeed still enabled.
        QPushButton* read = nullptr;
        for (QPushButton* b : wiz->findChildren<QPushButton*>())
            if (b->text() == QStringLiteral("Read state")) read = b;
        QVERIFY(read);
        QTest::mouseClick(read, Qt::LeftButton);
        QVERIFY2(QTest::qWaitFor([&] { return wiz->shownState() == State::OperationEnabled; }, 8000),
                 qPrintable(wiz->message()));
        // The drive's next heartbeat makes its state known again.
        QTRY_VERIFY_WITH_TIMEOUT(
            nodes->index(0, NodesModel::State).data().toString() != QStringLiteral("unknown (gap)"), 8000);
        // A heartbeat cannot arrive while the adapter is gone: the loss is one event, not a
        // heartbeat timeout per node.
        for (const TraceEvent& e : w.workspace()->events().since(eventsBefore))
            QVERIFY2(e.kind != TraceEvent::Kind::HeartbeatTimeout, qPrintable(e.text));
        net->stop();
    }
};

QTEST_MAIN(TestLostAdapter)
#include "test_lost_adapter.moc"
