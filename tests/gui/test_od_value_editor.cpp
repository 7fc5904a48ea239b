// SPDX-License-Identifier: GPL-3.0-or-later
// The Object Dictionary dock's integer editor as a technician uses it (issue 35): double-click
// (or F2) on 6040h's value in the real main window on sim://, type "0x1F", "1Fh" or "31", Enter,
// answer the confirmation by a click; the SDO download carries 1F 00 and the drive holds 001Fh,
// which the editor shows when opened again. Text that does not read is refused with the reason,
// nothing sent. F2 edits here and does not jump to the trace's bookmarks. Values read stay with
// their node when another node is shown.
#include "app/gui/MainWindow.h"
#include "app/gui/nodes/NodesDock.h"
#include "app/gui/nodes/NodesModel.h"
#include "app/gui/od/IntegerSpinBox.h"
#include "app/gui/od/ObjectDictionaryDock.h"
#include "app/gui/od/OdFilterModel.h"
#include "app/gui/od/OdTreeModel.h"
#include "app/gui/session/Workspace.h"
#include "core/sim/SimBus.h"
#include "core/sim/SimNetwork.h"
#include "core/sim/VirtualDevice.h"
#include "eds/SimulatorDictionaries.h"

#include <QAction>
#include <QLabel>
#include <QMessageBox>
#include <QSettings>
#include <QTableView>
#include <QToolBar>
#include <QTreeView>
#include <QtTest>

#include "tests/gui/ModalAnswer.h"
#include "tests/gui/WaitFor.h"

using namespace coscope;
using namespace coscope::gui;
using coscope::testing::waitFor;

namespace {
// The data of the SDO download requests to node 1 (601h, ours) from frame `from` on.
std::vector<QByteArray> downloadsFrom(MainWindow& w, size_t from) {
    std::vector<QByteArray> out;
    const auto& s = *w.workspace()->store();
    for (size_t n = from; n < s.size(); ++n) {
        const auto& r = s.record(static_cast<FrameNo>(n));
        if (r.id == 0x601 && (r.flags & CanFrame::Tx) && r.len == 8 && (r.data[0] & 0xE0) == 0x20)
            out.emplace_back(reinterpret_cast<const char*>(r.data), 8);
    }
    return out;
}
}  // namespace

class TestOdValueEditor : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() {
        QCoreApplication::setOrganizationName(QStringLiteral("CoScopeTest"));
        QCoreApplication::setApplicationName(QStringLiteral("gui_od_value_editor"));
        QSettings().clear();
        eds::installSimulatorDictionaries();
    }

    void controlwordTypedInEveryNotation() {
        MainWindow w;
        w.setQuiet(true);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        w.activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(&w));
        w.showView(QStringLiteral("od"));
        QVERIFY(w.connectBus(QStringLiteral("sim://")));
        QVERIFY(waitFor([&] {
            return w.workspace()->bus()->state() == CanBus::State::Open && w.workspace()->nodes().node(1).has_value();
        }));
        w.nodesDock()->assignDictionary(1, QStringLiteral("delta-asda-a2"));
        ObjectDictionaryDock* dock = w.odDock();
        dock->setNode(1);
        w.refresh();
        QVERIFY(dock->model()->hasDictionary());
        QTreeView* view = dock->view();
        const QModelIndex cell = dock->filter()->mapFromSource(dock->model()->indexOf(0x6040, 0, OdTreeModel::Value));
        QVERIFY(cell.flags() & Qt::ItemIsEditable);
        view->scrollTo(cell);
        auto sim = [&] { return static_cast<SimBus*>(w.workspace()->bus())->network(); };
        auto controlword = [&] {
            uint64_t v = ~0ull;
            sim()->runOnNetworkThread(
                [&] { v = sim()->device(1)->value(0x6040, 0).value_or(od::Value{}).toUInt64().value_or(~0ull); });
            return v;
        };
        auto editor = [&] { return view->findChild<IntegerSpinBox*>(QStringLiteral("odValueEditor")); };

        // Each text typed into the editor opened by a double-click on the value (first round) or
        // by F2 on the row: 1F 00 goes out; 0 between, so each write changes the value.
        struct Typed {
            const char* text;
            uint16_t expected;
            bool byF2;
        };
        int round = 0;
        for (const Typed& t :
             {Typed{"0x1F", 0x1F, false}, Typed{"0", 0, true}, Typed{"1Fh", 0x1F, true}, Typed{"0X00", 0, false},
              Typed{"1fh", 0x1F, true}, Typed{"0", 0, true}, Typed{"31", 0x1F, false}}) {
            ++round;
            // A window manager gives the focus back to the main window when the question closes;
            // offscreen there is none, so do its part.
            w.activateWindow();
            QVERIFY(QTest::qWaitForWindowActive(&w));
            if (t.byF2) {
                QTest::mouseClick(view->viewport(), Qt::LeftButton, {},
                                  view->visualRect(cell.siblingAtColumn(OdTreeModel::Name)).center());
                QTest::keyClick(view, Qt::Key_F2);
            } else {
                const QPoint at = view->visualRect(cell).center();
                // What the mouse sends for a double click: press, release, double-click, release.
                QTest::mouseClick(view->viewport(), Qt::LeftButton, {}, at);
                QTest::mouseDClick(view->viewport(), Qt::LeftButton, {}, at);
                QTest::mouseRelease(view->viewport(), Qt::LeftButton, {}, at);
            }
            QVERIFY2(waitFor([&] { return editor() != nullptr; }, 2000), t.text);
            IntegerSpinBox* spin = editor();
            QTest::keyClick(spin, Qt::Key_A, Qt::ControlModifier);
            QTest::keyClicks(spin, QString::fromLatin1(t.text));
            const size_t before = w.workspace()->store()->size();
            QString asked;
            auto yes = coscope::testing::answerBox(QMessageBox::Yes, &asked);
            QTest::keyClick(spin, Qt::Key_Return);
            QVERIFY2(waitFor([&] { return !downloadsFrom(w, before).empty(); }), t.text);
            QVERIFY2(asked.contains(QStringLiteral("Write 6040h:00")), qPrintable(asked));
            // Expedited download of 2 bytes (CiA 301 §7.2.4.3.3: 2Bh), 6040h:00, little-endian.
            const QByteArray frame = downloadsFrom(w, before).front();
            QCOMPARE(frame.toHex(' '), QByteArray("2b 40 60 00").append(t.expected ? " 1f 00 00 00" : " 00 00 00 00"));
            QVERIFY2(waitFor([&] { return controlword() == t.expected; }), t.text);
            QVERIFY(waitFor([&] {
                return dock->model()->actualValue(0x6040, 0) &&
                       dock->model()->actualValue(0x6040, 0)->toUInt64() == t.expected;
            }));
        }
        QCOMPARE(round, 7);

        // Opened again: the editor shows the value in the controlword's notation.
        w.activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(&w));
        QTest::mouseClick(view->viewport(), Qt::LeftButton, {},
                          view->visualRect(cell.siblingAtColumn(OdTreeModel::Name)).center());
        QTest::keyClick(view, Qt::Key_F2);
        QVERIFY(waitFor([&] { return editor() != nullptr; }, 2000));
        QCOMPARE(editor()->text(), QStringLiteral("001Fh"));
        QCOMPARE(view->model()->data(cell).toString(), QStringLiteral("001Fh"));

        // Not a number: refused with the reason, nothing asked, nothing sent.
        for (const char* bad : {"0x1G", "1F", "70000"}) {
            IntegerSpinBox* spin = editor();
            if (!spin) {
                QTest::keyClick(view, Qt::Key_F2);
                QVERIFY(waitFor([&] { return editor() != nullptr; }, 2000));
                spin = editor();
            }
            QTest::keyClick(spin, Qt::Key_A, Qt::ControlModifier);
            QTest::keyClicks(spin, QString::fromLatin1(bad));
            const size_t before = w.workspace()->store()->size();
            QString asked;
            auto no = coscope::testing::answerBox(QMessageBox::Cancel, &asked);
            QTest::keyClick(spin, Qt::Key_Return);
            QTest::qWait(200);
            QVERIFY2(asked.isEmpty(), qPrintable(asked));
            QVERIFY(downloadsFrom(w, before).empty());
            const QString why = dock->messageText();
            if (QByteArray(bad) == "70000")
                QVERIFY2(why.contains(QStringLiteral("70000 is out of range: 0000h … FFFFh")), qPrintable(why));
            else
                QVERIFY2(why.contains(QStringLiteral("“%1” is not a number").arg(QString::fromLatin1(bad))) &&
                             why.contains(QStringLiteral("0x1F or 1Fh")),
                         qPrintable(why));
            QCOMPARE(controlword(), uint64_t(0x1F));
        }
    }

    // Values read are kept per node (issue 35, item 7): Read all on node 1 (its toolbar button),
    // node 2 chosen in the Nodes dock shows node 2's header and status line, node 1 again shows
    // its values, "n read" and its status line, not "0 read".
    void valuesKeptPerNode() {
        MainWindow w;
        w.setQuiet(true);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        w.showView(QStringLiteral("od"));
        QVERIFY(w.connectBus(QStringLiteral("sim://")));
        QVERIFY(waitFor(
            [&] { return w.workspace()->nodes().node(1).has_value() && w.workspace()->nodes().node(2).has_value(); }));
        w.nodesDock()->assignDictionary(1, QStringLiteral("delta-asda-a2"));
        w.nodesDock()->assignDictionary(2, QStringLiteral("aimotor"));
        w.refresh();
        ObjectDictionaryDock* dock = w.odDock();
        auto choose = [&](int node) {
            QTableView* nodes = w.nodesDock()->view();
            const int row = w.nodesDock()->model()->rowOfNode(node);
            QTest::mouseClick(nodes->viewport(), Qt::LeftButton, {},
                              nodes->visualRect(nodes->model()->index(row, 1)).center());
            w.refresh();
            return dock->model()->node() == node;
        };
        auto header = [&] { return dock->findChild<QLabel*>(QStringLiteral("odHeader"))->text(); };
        QVERIFY(choose(1));
        QAction* readAll = dock->findChild<QAction*>(QStringLiteral("odReadAll"));
        QVERIFY(readAll && readAll->isEnabled());
        QTest::mouseClick(dock->findChild<QToolBar*>()->widgetForAction(readAll), Qt::LeftButton);
        QVERIFY(waitFor([&] { return !dock->isBusy() && dock->model()->valuesRead() > 100; }, 30000));
        const int read = dock->model()->valuesRead();
        const auto statusword = dock->model()->actualValue(0x6041, 0);
        QVERIFY(statusword);
        QVERIFY2(dock->messageText().contains(QStringLiteral("values read")), qPrintable(dock->messageText()));
        QVERIFY(header().contains(QStringLiteral("%1 read").arg(read)));

        QVERIFY(choose(2));
        QVERIFY2(header().contains(QStringLiteral("Node 2")) && header().contains(QStringLiteral("aimotor")),
                 qPrintable(header()));
        QCOMPARE(dock->model()->valuesRead(), 0);
        QVERIFY2(!dock->messageText().contains(QStringLiteral("values read")), qPrintable(dock->messageText()));

        QVERIFY(choose(1));
        QVERIFY2(header().contains(QStringLiteral("Node 1")) && header().contains(QStringLiteral("%1 read").arg(read)),
                 qPrintable(header()));
        QCOMPARE(dock->model()->valuesRead(), read);
        QCOMPARE(dock->model()->actualValue(0x6041, 0), statusword);
        QVERIFY(!dock->model()
                     ->data(dock->model()->indexOf(0x6041, 0, OdTreeModel::Value), Qt::DisplayRole)
                     .toString()
                     .isEmpty());
        QVERIFY2(dock->messageText().contains(QStringLiteral("values read")), qPrintable(dock->messageText()));
    }
};

QTEST_MAIN(TestOdValueEditor)
#include "test_od_value_editor.moc"
