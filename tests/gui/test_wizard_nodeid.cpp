// SPDX-License-Identifier: GPL-3.0-or-later
// The "Baud rate and node-ID" wizard end to end against the virtual drives (sim://): node-ID by
// LSS and by the drive's own parameter for every personality, bit rate with reconnect, a device
// without node-ID found by LSS Fastscan, failures (SDO abort, LSS store error) stop and explain,
// the dry run sends nothing, listen-only refuses. The technician's tests at the end act only
// through input events (clicks, keys, the wheel), in the wizard and in the main window.
#include "app/gui/MainWindow.h"
#include "app/gui/nodes/NodesDock.h"
#include "app/gui/nodes/NodesModel.h"
#include "app/gui/session/Workspace.h"
#include "app/gui/wizards/WizardMenu.h"
#include "app/gui/wizards/common/ScriptPreview.h"
#include "app/gui/wizards/common/WizardFramesPane.h"
#include "app/gui/wizards/nodeid/NodeIdPages.h"
#include "app/gui/wizards/nodeid/NodeIdWizard.h"
#include "core/sim/SimBus.h"
#include "core/sim/VirtualDevice.h"
#include "eds/SimulatorDictionaries.h"

#include <QApplication>
#include <QComboBox>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QMenuBar>
#include <QPushButton>
#include <QRadioButton>
#include <QSpinBox>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QWheelEvent>
#include <QtTest>

#include "tests/gui/WaitFor.h"

#include "tests/CliRun.h"
#include "tests/gui/ModalAnswer.h"

using namespace coscope;
using namespace coscope::gui;

namespace {
using coscope::testing::waitFor;

// --- input events, as a hand on the mouse and keyboard gives them
void click(QAbstractButton* b) { QTest::mouseClick(b, Qt::LeftButton, {}, b->rect().center()); }
void clickNext(QWizard* w) { click(w->button(QWizard::NextButton)); }
// Selects what is in the field and types `text` over it.
void typeInto(QWidget* w, const QString& text) {
    QTest::mouseClick(w, Qt::LeftButton, {}, w->rect().center());
    QTest::keyClick(w, Qt::Key_A, Qt::ControlModifier);
    QTest::keyClicks(w, text);
}
// One notch of the mouse wheel (120 = one step) up (+) or down (-) over `w`.
void wheel(QWidget* w, int notches) {
    const QPointF pos = QRectF(w->rect()).center();
    QWheelEvent e(pos, w->mapToGlobal(pos), QPoint(), QPoint(0, 120 * notches), Qt::NoButton, Qt::NoModifier,
                  Qt::NoScrollPhase, false);
    QApplication::sendEvent(w, &e);
}
// Clicks the row of `node` in a table whose first column holds the node-ID.
bool clickNodeRow(QTableWidget* table, int node) {
    for (int r = 0; r < table->rowCount(); ++r)
        if (table->item(r, 0) && table->item(r, 0)->text() == QString::number(node)) {
            const QRect cell = table->visualItemRect(table->item(r, 0));
            QTest::mouseClick(table->viewport(), Qt::LeftButton, {}, cell.center());
            return true;
        }
    return false;
}
// Chooses `text` in a combo box with the keyboard: Home, then Down until it shows.
bool pickFromList(QComboBox* box, const QString& text) {
    if (box->findText(text) < 0) return false;
    QTest::keyClick(box, Qt::Key_Home);
    for (int i = 0; i < box->count() && box->currentText() != text; ++i) QTest::keyClick(box, Qt::Key_Down);
    return box->currentText() == text;
}
// Opens `menuText` in the window's menu bar and clicks the entry whose text contains `entry`.
bool clickMenu(QMainWindow& w, const QString& menuText, const QString& entry) {
    QMenuBar* bar = w.menuBar();
    for (QAction* top : bar->actions()) {
        if (QString(top->text()).remove(u'&') != menuText || !top->menu()) continue;
        QTest::mouseClick(bar, Qt::LeftButton, {}, bar->actionGeometry(top).center());
        QMenu* menu = top->menu();
        if (!waitFor([&] { return menu->isVisible(); }, 3000)) return false;
        for (QAction* a : menu->actions())
            if (QString(a->text()).remove(u'&').contains(entry)) {
                QTest::mouseClick(menu, Qt::LeftButton, {}, menu->actionGeometry(a).center());
                return true;
            }
        menu->hide();
    }
    return false;
}
template <typename W>
W* findTopLevel() {
    for (QWidget* w : QApplication::topLevelWidgets())
        if (auto* t = qobject_cast<W*>(w); t && t->isVisible()) return t;
    return nullptr;
}
void grabPage(QWidget* w, const QString& name) {
    if (const QString dir = qEnvironmentVariable("COSCOPE_GRAB_DIR"); !dir.isEmpty())
        w->grab().save(dir + QStringLiteral("/%1.png").arg(name));
}
// More than two periods of the find page's refresh (400 ms): whatever a refresh would put back is back.
constexpr int kRefreshesMs = 1000;

const QString kAll = QStringLiteral("sim://?nodes=1:delta-asda-a2,2:aimotor,3:dexmart-dev,4:generic-cia402");

// A workspace connected to a virtual network, and the wizard on it.
struct Bench {
    Workspace ws;
    std::unique_ptr<NodeIdWizard> wizard;
    bool open(const QString& url = kAll, int node = -1, bool scan = true) {
        QString error;
        if (!ws.connectBus(url, &error)) return false;
        if (!waitFor([&] { return ws.bus() && ws.bus()->state() == CanBus::State::Open; })) return false;
        if (!waitFor([&] { return ws.nodes().snapshot().size() >= 1; })) return false;
        wizard = std::make_unique<NodeIdWizard>(&ws, node);
        wizard->show();
        if (!scan || ws.bus()->isListenOnly()) return true;
        QSignalSpy spy(wizard.get(), &NodeIdWizard::scanFinished);
        click(wizard->findPage()->scanButton());
        return spy.wait(15000);
    }
    template <typename T>
    T* child(const char* name) const {
        return wizard->findChild<T*>(QString::fromLatin1(name));
    }
    // --- what the technician does, page by page
    // Back to the first page by its Back button.
    void backToStart() {
        for (int i = 0; i < 3 && wizard->currentId() != NodeIdWizard::FindPageId; ++i)
            click(wizard->button(QWizard::BackButton));
    }
    // Clicks the node in the list on the first page.
    bool pickNode(int node) {
        if (!clickNodeRow(wizard->findPage()->nodeTable(), node)) return false;
        return waitFor([&] { return child<QLabel>("target")->text().contains(QStringLiteral("node %1").arg(node)); },
                       3000);
    }
    // Chooses the device type in its list on the first page.
    bool pickDictionary(const QString& name) { return pickFromList(child<QComboBox>("dictionary"), name); }
    // Second page.
    void pickChange(NodeIdWizard::Change c) {
        click(child<QRadioButton>(c == NodeIdWizard::Change::NodeId ? "changeNodeId" : "changeBitRate"));
    }
    void pickMethod(NodeIdWizard::Method m) {
        click(child<QRadioButton>(m == NodeIdWizard::Method::Lss ? "viaLss" : "viaVendor"));
    }
    void typeNodeId(int id) {
        typeInto(child<QAbstractSpinBox>("newNodeId")->findChild<QLineEdit*>(), QString::number(id));
    }
    bool pickBitRate(int rate) { return pickFromList(child<QComboBox>("newBitRate"), canopen::bitRateText(rate)); }
    sim::SimNetwork* net() const { return static_cast<SimBus*>(ws.bus())->network(); }
    int nodeIdOfSerial(uint8_t firstId) {
        int id = -1;
        net()->runOnNetworkThread([&] {
            for (const auto& n : net()->nodes())
                if (auto* d = dynamic_cast<sim::VirtualDevice*>(n.get());
                    d && d->serialNumber() == 0x51000000u + firstId)
                    id = d->nodeId();
        });
        return id;
    }
    template <typename F>
    void onDevice(uint8_t node, F fn) {
        net()->runOnNetworkThread([&] {
            if (auto* d = net()->device(node)) fn(*d);
        });
    }
    // Clicks Next to the last page (dry run) and waits for the sequence.
    bool toRunPage() {
        QSignalSpy ready(wizard.get(), &NodeIdWizard::dryRunReady);
        while (wizard->currentId() != NodeIdWizard::RunPageId) {
            if (!wizard->button(QWizard::NextButton)->isEnabled()) return false;
            clickNext(wizard.get());
        }
        return (ready.count() > 0 || ready.wait(8000)) && ready.last().at(0).toBool();
    }
    // The dry run's "Save as script…", the file name typed into its dialog; true once saved.
    bool saveScript(const QString& file) {
        QSignalSpy saved(wizard->preview(), &ScriptPreview::saved);
        auto answer = coscope::testing::answerFileDialog(file);
        QPushButton* save = nullptr;
        for (auto* p : wizard->preview()->findChildren<QPushButton*>())
            if (p->text().startsWith(QStringLiteral("Save as script"))) save = p;
        if (!save) return false;
        click(save);
        return saved.count() > 0 || saved.wait(5000);
    }
    // Clicks "Change it now" and waits for the outcome.
    bool run(int timeoutMs = 30000) {
        QSignalSpy done(wizard.get(), &NodeIdWizard::finished);
        click(wizard->runPage()->runButton());
        return done.wait(timeoutMs) && done.last().at(0).toBool();
    }
};
}  // namespace

class TestWizardNodeId : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { eds::installSimulatorDictionaries(); }

    void registeredInTheCommissionMenu() {
        bool found = false;
        for (const auto& e : wizardEntries()) found |= e.id == u"nodeid";
        QVERIFY(found);
    }

    void nodeIdByLssForEveryPersonality() {
        Bench b;
        QVERIFY(b.open());
        QVERIFY(b.child<QLabel>("target")->text().contains(
            QStringLiteral("node 1")));  // the first node found is preselected
        for (uint8_t node = 1; node <= 4; ++node) {
            b.backToStart();
            QVERIFY(b.pickNode(node));
            clickNext(b.wizard.get());
            b.pickChange(NodeIdWizard::Change::NodeId);
            b.pickMethod(NodeIdWizard::Method::Lss);
            b.typeNodeId(40 + node);
            QVERIFY2(b.toRunPage(), qPrintable(b.wizard->planError() + b.wizard->blockingProblem()));
            QVERIFY(b.wizard->preview()->script().steps.front().toLine().startsWith(
                QStringLiteral("lss switch-selective")));
            QVERIFY2(b.run(), qPrintable(b.wizard->outcomeText()));
            QCOMPARE(b.nodeIdOfSerial(node), 40 + node);
            QVERIFY(b.wizard->runPage()->statusLabel()->text().contains(QStringLiteral("node-ID %1").arg(40 + node)));
        }
        // The frames pane showed the LSS and NMT traffic.
        QVERIFY(waitFor([&] { return b.wizard->framesPane()->rowCount() > 10; }));
    }

    // Issue 13: AIMOTOR and DEXMART DEV both answer 1018h with 0/0. The scan tells them apart by
    // 1000h and 1008h: node 3 is shown as the DEXMART DEV, not as an AIMOTOR.
    void scanTellsDexmartFromAimotor() {
        Bench b;
        QVERIFY(b.open());
        auto* dictionary = b.child<QComboBox>("dictionary");
        const std::pair<int, QString> cases[] = {
            {3, QStringLiteral("dexmart-dev")}, {2, QStringLiteral("aimotor")}, {1, QStringLiteral("delta-asda-a2")}};
        for (const auto& [node, name] : cases) {
            QVERIFY(b.pickNode(node));
            QVERIFY2(waitFor([&] { return dictionary->currentData().toString() == name; }, 3000),
                     qPrintable(dictionary->currentText()));
        }
    }

    void nodeIdByVendorParameter() {
        Bench b;
        QVERIFY(b.open());
        const std::pair<uint8_t, QString> cases[] = {
            {1, QStringLiteral("delta-asda-a2")}, {2, QStringLiteral("aimotor")}, {3, QStringLiteral("dexmart-dev")}};
        for (const auto& [node, dict] : cases) {
            b.backToStart();
            QVERIFY(b.pickNode(node));
            QVERIFY(b.pickDictionary(dict));  // the technician confirms the device type
            clickNext(b.wizard.get());
            b.pickChange(NodeIdWizard::Change::NodeId);
            QVERIFY(b.child<QRadioButton>("viaVendor")->isEnabled());
            b.pickMethod(NodeIdWizard::Method::Vendor);
            b.typeNodeId(50 + node);
            // The page says which parameter and when it takes effect.
            QVERIFY(b.wizard->changePage()->explanationLabel()->text().contains(QStringLiteral("Takes effect")));
            QVERIFY2(b.toRunPage(), qPrintable(b.wizard->planError()));
            QVERIFY(b.wizard->preview()->script().steps.front().toLine().startsWith(
                QStringLiteral("sdo write %1 ").arg(node)));
            QVERIFY2(b.run(), qPrintable(b.wizard->outcomeText()));
            QCOMPARE(b.nodeIdOfSerial(node), 50 + node);
        }
        // Generic CiA 402: no vendor parameter, LSS only.
        b.backToStart();
        QVERIFY(b.pickNode(4));
        clickNext(b.wizard.get());
        QVERIFY(!b.child<QRadioButton>("viaVendor")->isEnabled());
        QVERIFY(b.child<QRadioButton>("viaLss")->isChecked());
    }

    void bitRateByLssAndByVendorReconnects() {
        Bench b;
        QVERIFY(b.open());
        // AIMOTOR by LSS to 250 kbit/s: the wizard warns about the other nodes, reconnects,
        // finds the node at the new rate.
        QVERIFY(b.pickNode(2));
        clickNext(b.wizard.get());
        b.pickChange(NodeIdWizard::Change::BitRate);
        b.pickMethod(NodeIdWizard::Method::Lss);
        QVERIFY(b.pickBitRate(250000));
        const QString text = b.wizard->changePage()->explanationLabel()->text();
        QVERIFY2(text.contains(QStringLiteral("Every other node")) && text.contains(QStringLiteral("nodes 1, 3, 4")),
                 qPrintable(text));
        grabPage(b.wizard.get(), QStringLiteral("nodeid-change"));
        QVERIFY(b.toRunPage());
        QVERIFY(b.wizard->runPage()->statusLabel()->text().contains(
            QStringLiteral("reconnect at %1").arg(canopen::bitRateText(250000))));
        QVERIFY2(b.run(), qPrintable(b.wizard->outcomeText()));
        grabPage(b.wizard.get(), QStringLiteral("nodeid-run"));
        QCOMPARE(b.ws.bus()->url().bitrate(), 250000);
        uint32_t rate = 0;
        b.onDevice(2, [&](sim::VirtualDevice& d) { rate = d.bitRate(); });
        QCOMPARE(rate, 250000u);
        // Node 1 (Delta, still at 500 kbit/s) is not heard at 250 kbit/s; now Delta by P3-01:
        // reconnect at 500 kbit/s first, then change it to 1 Mbit/s.
        QString error;
        b.wizard.reset();
        QVERIFY(b.ws.connectBus(
            b.ws.bus()->url().toString().replace(QStringLiteral("bitrate=250000"), QStringLiteral("bitrate=500000")),
            &error));
        QVERIFY(waitFor([&] { return b.ws.canTransmit() && b.ws.nodes().node(1).has_value(); }));
        b.wizard = std::make_unique<NodeIdWizard>(&b.ws, 1);
        b.wizard->show();
        QVERIFY(b.pickDictionary(QStringLiteral("delta-asda-a2")));
        clickNext(b.wizard.get());
        b.pickChange(NodeIdWizard::Change::BitRate);
        b.pickMethod(NodeIdWizard::Method::Vendor);
        QVERIFY(b.pickBitRate(1000000));
        QVERIFY(b.toRunPage());
        QCOMPARE(b.wizard->preview()->script().steps.front().toLine(), QStringLiteral("sdo write 1 0x2301:00 0x0403"));
        QVERIFY2(b.run(), qPrintable(b.wizard->outcomeText()));
        QCOMPARE(b.ws.bus()->url().bitrate(), 1000000);
        b.onDevice(1, [&](sim::VirtualDevice& d) { rate = d.bitRate(); });
        QCOMPARE(rate, 1000000u);
    }

    void deviceWithoutNodeIdByFastscan() {
        Bench b;
        QVERIFY(b.open(QStringLiteral("sim://?nodes=1:delta-asda-a2,5:aimotor"), 1, false));
        b.onDevice(5, [](sim::VirtualDevice& d) { d.makeUnconfigured(); });
        QSignalSpy found(b.wizard.get(), &NodeIdWizard::fastscanFinished);
        click(b.wizard->findPage()->fastscanButton());
        QVERIFY(found.wait(20000));
        QVERIFY2(found.last().at(0).toBool(), qPrintable(found.last().at(1).toString()));
        QVERIFY(b.child<QLabel>("target")->text().contains(QStringLiteral("without node-ID")));
        clickNext(b.wizard.get());
        QVERIFY(!b.child<QRadioButton>("changeBitRate")->isEnabled());
        b.typeNodeId(9);
        QVERIFY(b.toRunPage());
        QVERIFY2(b.run(), qPrintable(b.wizard->outcomeText()));
        QCOMPARE(b.nodeIdOfSerial(5), 9);
    }

    void sdoAbortStopsAndExplains() {
        Bench b;
        QVERIFY(b.open());
        b.onDevice(1, [](sim::VirtualDevice& d) {
            d.sdoFaults().abortOn = std::make_tuple(uint16_t(0x2300), uint8_t(0), uint32_t(0x08000022));
        });
        QVERIFY(b.pickNode(1));
        QVERIFY(b.pickDictionary(QStringLiteral("delta-asda-a2")));
        clickNext(b.wizard.get());
        b.pickMethod(NodeIdWizard::Method::Vendor);
        b.typeNodeId(12);
        QVERIFY(b.toRunPage());
        QVERIFY(!b.run());
        const QString text = b.wizard->runPage()->statusLabel()->text();
        QVERIFY2(text.contains(QStringLiteral("step 1")) && text.contains(QStringLiteral("2300h")), qPrintable(text));
        QVERIFY2(text.contains(QStringLiteral("08000022")), qPrintable(text));  // the device's answer
        QVERIFY(text.contains(QStringLiteral("What to check")));
        QCOMPARE(b.nodeIdOfSerial(1), 1);
    }

    void lssStoreErrorIsUndone() {
        Bench b;
        QVERIFY(b.open());
        b.onDevice(4, [](sim::VirtualDevice& d) { d.lssFaults().storeError = 2; });
        QVERIFY(b.pickNode(4));
        clickNext(b.wizard.get());
        b.pickMethod(NodeIdWizard::Method::Lss);
        b.typeNodeId(14);
        QVERIFY(b.toRunPage());
        QVERIFY(!b.run());
        const QString text = b.wizard->runPage()->statusLabel()->text();
        QVERIFY2(text.contains(QStringLiteral("store")) && text.contains(QStringLiteral("Put back")), qPrintable(text));
        int pending = 0;
        b.onDevice(4, [&](sim::VirtualDevice& d) { pending = d.pendingNodeId(); });
        QCOMPARE(pending, 4);
        QCOMPARE(b.nodeIdOfSerial(4), 4);
    }

    void dryRunSendsNothingAndSaves() {
        Bench b;
        QVERIFY(b.open());
        QVERIFY(b.pickNode(2));
        clickNext(b.wizard.get());
        b.pickMethod(NodeIdWizard::Method::Lss);
        b.typeNodeId(22);
        QTest::qWait(300);
        const uint64_t tx = b.ws.bus()->counters().tx;
        QVERIFY(b.toRunPage());
        QTest::qWait(300);
        QCOMPARE(b.ws.bus()->counters().tx, tx);  // the identity came from the scan
        QCOMPARE(b.wizard->preview()->rowCount(), int(b.wizard->plan()->whole().steps.size()));
        // "Save as script…", a file name typed into the dialog.
        QTemporaryDir dir;
        const QString file = dir.filePath(QStringLiteral("nodeid.txt"));
        QVERIFY(b.saveScript(file));
        QString error;
        const auto script = canopen::CommandScript::load(file, &error);
        QVERIFY2(script, qPrintable(error));
        QCOMPARE(script->steps.size(), b.wizard->plan()->whole().steps.size());
        QCOMPARE(b.nodeIdOfSerial(2), 2);
    }

    // Issue 13: the bit-rate change saved as a script (dry run, "Save as script…") has the
    // reconnect as a step: `coscope-cli script run` replays it on a fresh virtual network,
    // reopens the adapter at 250 kbit/s and finds the node there; it answers SDO at that rate.
    void savedBitRateScriptReconnectsWhenReplayed() {
        Bench b;
        QVERIFY(b.open());
        QVERIFY(b.pickNode(2));  // AIMOTOR, by LSS
        clickNext(b.wizard.get());
        b.pickChange(NodeIdWizard::Change::BitRate);
        b.pickMethod(NodeIdWizard::Method::Lss);
        QVERIFY(b.pickBitRate(250000));
        QVERIFY(b.toRunPage());
        QTemporaryDir dir;
        const QString file = dir.filePath(QStringLiteral("bitrate.txt"));
        QVERIFY(b.saveScript(file));
        QCOMPARE(b.ws.bus()->url().bitrate() > 0 ? b.ws.bus()->url().bitrate() : 500000,
                 500000);  // nothing was run here
        // The node answers SDO at the new rate after the replay's reconnect.
        QFile f(file);
        QVERIFY(f.open(QIODevice::Append));
        f.write("sdo read 2 0x1000:00\n");
        f.close();
        const Run r = cli({QStringLiteral("script"), QStringLiteral("run"), kAll, file});
        QVERIFY2(r.code == 0, qPrintable(r.out + r.err));
        auto stepOk = [&](const QString& line) {
            for (const QString& l : r.out.split(u'\n'))
                if (l.contains(QStringLiteral(" ok ")) && l.contains(line)) return true;
            return false;
        };
        QVERIFY2(stepOk(QStringLiteral("reconnect 250000")), qPrintable(r.out));
        QVERIFY2(stepOk(QStringLiteral("wait-node 2")), qPrintable(r.out));
        QVERIFY2(stepOk(QStringLiteral("sdo read 2 0x1000:00")), qPrintable(r.out));
    }

    // Issue 12 item 2: the new node-ID takes typing, the arrow keys and the wheel; the drive's own
    // parameter stays chosen however long the page is open; the run sends what the user set.
    void typedNodeIdAndVendorParameterAreApplied() {
        Bench b;
        QVERIFY(b.open());
        NodeIdWizard* w = b.wizard.get();
        QVERIFY(clickNodeRow(w->findPage()->nodeTable(), 1));  // Delta ASDA-A2: P3-00 is its node-ID
        QTRY_VERIFY(
            w->findPage()->findChild<QLabel*>(QStringLiteral("target"))->text().contains(QStringLiteral("node 1")));
        grabPage(w, QStringLiteral("nodeid-1-find"));
        clickNext(w);
        QCOMPARE(w->currentId(), int(NodeIdWizard::ChangePageId));
        auto* page = w->changePage();
        auto* vendor = page->findChild<QRadioButton*>(QStringLiteral("viaVendor"));
        auto* lss = page->findChild<QRadioButton*>(QStringLiteral("viaLss"));
        auto* spin = page->findChild<QAbstractSpinBox*>(QStringLiteral("newNodeId"));
        auto* edit = spin->findChild<QLineEdit*>();
        QVERIFY(vendor->isEnabled() && edit);
        click(vendor);
        QVERIFY(vendor->isChecked());
        typeInto(edit, QStringLiteral("42"));
        QCOMPARE(edit->text(), QStringLiteral("42"));
        QTest::keyClick(spin, Qt::Key_Up);
        QCOMPARE(edit->text(), QStringLiteral("43"));
        wheel(spin, 1);
        QCOMPARE(edit->text(), QStringLiteral("44"));
        QTest::qWait(kRefreshesMs);
        QCOMPARE(edit->text(), QStringLiteral("44"));
        QVERIFY(vendor->isChecked() && !lss->isChecked());
        QVERIFY2(page->explanationLabel()->text().contains(QStringLiteral("P3-00")),
                 qPrintable(page->explanationLabel()->text()));
        grabPage(w, QStringLiteral("nodeid-2-change"));
        // The dry run writes 44 (2Ch) to P3-00 (2300h).
        QSignalSpy ready(w, &NodeIdWizard::dryRunReady);
        clickNext(w);
        QVERIFY(ready.count() > 0 || ready.wait(8000));
        const QString line = w->preview()->script().steps.front().toLine();
        QVERIFY2(line.startsWith(QStringLiteral("sdo write 1 0x2300:00 ")), qPrintable(line));
        QCOMPARE(line.section(u' ', -1).toUInt(nullptr, 0), 44u);
        grabPage(w, QStringLiteral("nodeid-3-dry-run"));
        QSignalSpy done(w, &NodeIdWizard::finished);
        click(w->runPage()->runButton());
        QVERIFY(done.wait(30000));
        QVERIFY2(done.last().at(0).toBool(), qPrintable(w->runPage()->statusLabel()->text()));
        QVERIFY(w->runPage()->statusLabel()->text().contains(QStringLiteral("node-ID 44")));
        QCOMPARE(b.nodeIdOfSerial(1), 44);
        grabPage(w, QStringLiteral("nodeid-4-done"));
    }

    // The device type the user chooses on the first page stays chosen, even "(unknown)" for a
    // node the scan matched: the page's periodic refresh does not put the scan's match back.
    void deviceTypeChosenByHandStays() {
        Bench b;
        QVERIFY(b.open());
        NodeIdWizard* w = b.wizard.get();
        QVERIFY(clickNodeRow(w->findPage()->nodeTable(), 1));
        auto* type = w->findPage()->findChild<QComboBox*>(QStringLiteral("dictionary"));
        QTRY_COMPARE(type->currentText(), QStringLiteral("delta-asda-a2"));
        QTest::keyClick(type, Qt::Key_Home);  // "(unknown — LSS only)"
        QCOMPARE(type->currentIndex(), 0);
        QTest::qWait(kRefreshesMs);
        QCOMPARE(type->currentIndex(), 0);
        auto* target = w->findPage()->findChild<QLabel*>(QStringLiteral("target"));
        QVERIFY2(!target->text().contains(QStringLiteral("delta")), qPrintable(target->text()));
        clickNext(w);
        QVERIFY(!w->changePage()->findChild<QRadioButton*>(QStringLiteral("viaVendor"))->isEnabled());
        QVERIFY(w->changePage()->findChild<QRadioButton*>(QStringLiteral("viaLss"))->isChecked());
    }

    // Issue 12 item 2: the new bit rate list takes typing, the arrow keys and the wheel.
    void chosenBitRateStaysAndIsPlanned() {
        Bench b;
        QVERIFY(b.open());
        NodeIdWizard* w = b.wizard.get();
        QVERIFY(clickNodeRow(w->findPage()->nodeTable(), 2));
        QTRY_VERIFY(
            w->findPage()->findChild<QLabel*>(QStringLiteral("target"))->text().contains(QStringLiteral("node 2")));
        clickNext(w);
        auto* page = w->changePage();
        click(page->findChild<QRadioButton*>(QStringLiteral("changeBitRate")));
        auto* rate = page->findChild<QComboBox*>(QStringLiteral("newBitRate"));
        QTRY_VERIFY(rate->isEnabled());
        QTest::keyClicks(rate, QStringLiteral("8"));  // 800 kbit/s
        QCOMPARE(rate->currentText(), canopen::bitRateText(800000));
        QTest::keyClick(rate, Qt::Key_Down);  // 750 kbit/s
        QCOMPARE(rate->currentText(), canopen::bitRateText(750000));
        for (int i = 0; i < 3; ++i) wheel(rate, -1);  // 500, 250, 125 kbit/s
        QCOMPARE(rate->currentText(), canopen::bitRateText(125000));
        QTest::qWait(kRefreshesMs);
        QCOMPARE(rate->currentText(), canopen::bitRateText(125000));
        QVERIFY2(page->explanationLabel()->text().contains(canopen::bitRateText(125000)),
                 qPrintable(page->explanationLabel()->text()));
        grabPage(w, QStringLiteral("nodeid-2-change-bitrate"));
        QSignalSpy ready(w, &NodeIdWizard::dryRunReady);
        clickNext(w);
        QVERIFY(ready.count() > 0 || ready.wait(8000));
        QVERIFY2(ready.last().at(0).toBool(), qPrintable(w->runPage()->statusLabel()->text()));
        QVERIFY2(w->runPage()->statusLabel()->text().contains(
                     QStringLiteral("reconnect at %1").arg(canopen::bitRateText(125000))),
                 qPrintable(w->runPage()->statusLabel()->text()));
    }

    // Issue 12 item 4, as a technician does it in the main window: connect to the virtual drives,
    // Commission ▸ Baud rate and node-ID…, scan, node 3 to node 7. The Nodes dock then lists
    // node 7 with its dictionary and no node 3; the header no longer says nothing was sent.
    void nodeIdChangeShowsInTheNodesDock() {
        MainWindow mw;
        mw.setQuiet(true);
        mw.resize(1200, 800);
        mw.show();
        QVERIFY(QTest::qWaitForWindowExposed(&mw));
        QVERIFY(clickMenu(mw, QStringLiteral("Bus"), QStringLiteral("virtual drives")));
        QVERIFY(waitFor([&] { return mw.workspace()->canTransmit(); }));
        NodesModel* nodes = mw.nodesDock()->model();
        QVERIFY(waitFor([&] { return nodes->rowOfNode(3) >= 0; }));
        QVERIFY(clickMenu(mw, QStringLiteral("Commission"), QStringLiteral("node-ID")));
        NodeIdWizard* w = nullptr;
        QVERIFY(waitFor([&] { return (w = findTopLevel<NodeIdWizard>()) != nullptr; }));
        QSignalSpy scanned(w, &NodeIdWizard::scanFinished);
        click(w->findPage()->scanButton());
        QVERIFY(scanned.wait(15000));
        auto dictionaryOf = [&](int node) {
            const int row = nodes->rowOfNode(node);
            return row < 0 ? QString()
                           : nodes->data(nodes->index(row, NodesModel::Dictionary), Qt::DisplayRole).toString();
        };
        QVERIFY(waitFor([&] { return dictionaryOf(3) == u"generic-cia402"; }));
        QVERIFY(clickNodeRow(w->findPage()->nodeTable(), 3));
        QTRY_VERIFY(
            w->findPage()->findChild<QLabel*>(QStringLiteral("target"))->text().contains(QStringLiteral("node 3")));
        clickNext(w);
        typeInto(w->changePage()->findChild<QAbstractSpinBox*>(QStringLiteral("newNodeId"))->findChild<QLineEdit*>(),
                 QStringLiteral("7"));
        QSignalSpy ready(w, &NodeIdWizard::dryRunReady);
        clickNext(w);
        QVERIFY(ready.count() > 0 || ready.wait(8000));
        auto headerSays = [&](const QString& text) {
            for (QLabel* l : w->findChildren<QLabel*>())
                if (l->isVisible() && l->text().contains(text)) return true;
            return false;
        };
        QVERIFY(headerSays(QStringLiteral("nothing has been sent yet")));
        QSignalSpy done(w, &NodeIdWizard::finished);
        click(w->runPage()->runButton());
        QVERIFY(done.wait(30000));
        QVERIFY2(done.last().at(0).toBool(), qPrintable(w->runPage()->statusLabel()->text()));
        QVERIFY(!headerSays(QStringLiteral("nothing has been sent yet")));
        grabPage(w, QStringLiteral("nodeid-4-done-3-to-7"));
        QVERIFY2(waitFor([&] { return dictionaryOf(7) == u"generic-cia402"; }), qPrintable(dictionaryOf(7)));
        QVERIFY(waitFor([&] { return nodes->rowOfNode(3) < 0; }));
        QTest::qWait(kRefreshesMs);  // and it stays so
        QCOMPARE(nodes->rowOfNode(3), -1);
        QCOMPARE(dictionaryOf(7), QStringLiteral("generic-cia402"));
        // The main window goes (its bus with it) while the wizard is still open: the wizard lets
        // go of its LSS services before the bus's dispatcher goes (this used to abort).
    }

    void listenOnlyRefuses() {
        Bench b;
        QVERIFY(b.open(QStringLiteral("sim://?listen-only=1"), 1, false));
        QVERIFY(!b.wizard->button(QWizard::NextButton)->isEnabled());
        QVERIFY(!b.wizard->findPage()->scanButton()->isEnabled());
        QVERIFY(!b.wizard->findPage()->fastscanButton()->isEnabled());
        QVERIFY(b.wizard->findPage()->refusalLabel()->isVisible());
        QVERIFY(b.wizard->findPage()->refusalLabel()->text().contains(QStringLiteral("listen-only")));
        click(b.wizard->button(QWizard::NextButton));
        click(b.wizard->findPage()->scanButton());
        QTest::qWait(300);
        QCOMPARE(b.wizard->currentId(), int(NodeIdWizard::FindPageId));
        QCOMPARE(b.ws.bus()->counters().tx, uint64_t(0));
    }
};

QTEST_MAIN(TestWizardNodeId)
#include "test_wizard_nodeid.moc"
