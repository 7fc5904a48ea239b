// SPDX-License-Identifier: GPL-3.0-or-later
// The Help menu (issue 36 item 7): F1 opens the guide at the section of the dock or wizard page
// that has the focus, in the UI language; Keyboard shortcuts lists the window's real shortcuts;
// About shows the version and the licenses.
#include "app/BuildInfo.h"
#include "app/gui/MainWindow.h"
#include "app/gui/help/HelpWindow.h"
#include "app/gui/language/Language.h"
#include "app/gui/nodes/NodesDock.h"
#include "app/gui/session/Workspace.h"
#include "app/gui/trace/TraceDock.h"
#include "app/gui/trace/TraceModel.h"
#include "eds/SimulatorDictionaries.h"

#include <QAbstractItemView>
#include <QMessageBox>
#include <QScrollBar>
#include <QSettings>
#include <QTextBrowser>
#include <QTreeWidget>
#include <QWizard>
#include <QtTest>

#include "tests/gui/MenuClick.h"
#include "tests/gui/ModalAnswer.h"
#include "tests/gui/WaitFor.h"

using namespace coscope;
using namespace coscope::gui;
using coscope::testing::clickMenuItem;
using coscope::testing::ModalAnswerer;
using coscope::testing::waitFor;

namespace {
help::HelpWindow* helpOf(MainWindow& w) { return help::HelpWindow::of(&w); }

// The text of the heading at the top of the browser's viewport.
QString headingInView(QTextBrowser* b) {
    const QTextCursor c = b->cursorForPosition(QPoint(4, 4));
    for (QTextBlock block = c.block(); block.isValid(); block = block.next())
        if (block.blockFormat().headingLevel() > 0) return block.text();
    return {};
}

// Clicks in the middle of a widget (gives it the focus as a user's click does), then presses F1.
void focusAndF1(QWidget* w) {
    QTest::mouseClick(w, Qt::LeftButton, {}, w->rect().center());
    QTest::keyClick(w, Qt::Key_F1);
}
}  // namespace

class TestHelpMenu : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() {
        QCoreApplication::setOrganizationName(QStringLiteral("CoScopeTest"));
        QCoreApplication::setApplicationName(QStringLiteral("gui_help_menu"));
        QSettings().clear();
        eds::installSimulatorDictionaries();
    }

    void cleanup() { language::apply(QStringLiteral("en")); }

    // F1 in the Nodes dock, then in the Trace dock: the guide at each one's section.
    void f1OpensTheDocksSection() {
        MainWindow w;
        w.setQuiet(true);
        w.show();
        QVERIFY(QTest::qWaitForWindowActive(&w));
        QAbstractItemView* nodes = w.nodesDock()->findChild<QAbstractItemView*>(QStringLiteral("nodesView"));
        QVERIFY(nodes);
        focusAndF1(nodes->viewport());
        QVERIFY(waitFor([&] { return helpOf(w) && helpOf(w)->isVisible(); }));
        QCOMPARE(helpOf(w)->section(), QStringLiteral("nodes"));
        QTextBrowser* b = helpOf(w)->browser();
        QVERIFY(waitFor([&] { return headingInView(b) == QStringLiteral("Nodes"); }));
        QVERIFY(b->verticalScrollBar()->value() > 0);

        w.activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(&w));
        focusAndF1(w.traceDock()->view()->viewport());
        QVERIFY(waitFor([&] { return helpOf(w)->section() == QStringLiteral("trace"); }));
        QVERIFY(waitFor([&] { return headingInView(b) == QStringLiteral("Trace"); }));
        // Every dock of the window has its section in the guide.
        for (const char* anchor :
             {"trace", "nodes", "od", "plot", "events", "health", "console", "transmit", "processdata"})
            QVERIFY2(helpOf(w)->anchors().contains(QLatin1String(anchor)), anchor);
    }

    // F1 on a wizard page (a window of its own): that page's section.
    void f1OnAWizardPage() {
        MainWindow w;
        w.setQuiet(true);
        w.show();
        QVERIFY(QTest::qWaitForWindowActive(&w));
        QVERIFY(w.connectBus(QStringLiteral("sim://")));
        QVERIFY(waitFor([&] { return w.workspace()->canTransmit(); }));
        QTest::qWait(100);  // the window's pull enables the Commission menu
        QVERIFY(clickMenuItem(w, QStringLiteral("Commission"), QStringLiteral("PDO mapping")));
        QWizard* wizard = nullptr;
        QVERIFY(waitFor([&] {
            for (QWidget* top : QApplication::topLevelWidgets())
                if (auto* x = qobject_cast<QWizard*>(top); x && x->isVisible()) wizard = x;
            return wizard != nullptr;
        }));
        QVERIFY(QTest::qWaitForWindowActive(wizard));
        // The window manager activates the window the user clicks in; offscreen, do its part
        // (the closing Commission menu gave the activation back to the main window).
        wizard->activateWindow();
        QVERIFY(waitFor([&] { return QApplication::activeWindow() == wizard; }));
        // F1 where the keyboard is in the wizard (its first field, as a user finds it).
        QTest::keyClick(wizard->focusWidget() ? wizard->focusWidget() : wizard, Qt::Key_F1);
        QVERIFY(waitFor([&] { return helpOf(w) && helpOf(w)->isVisible(); }));
        QCOMPARE(helpOf(w)->section(), QStringLiteral("wizard-pdo-choose"));
        QVERIFY(waitFor(
            [&] { return headingInView(helpOf(w)->browser()).startsWith(QStringLiteral("1. Drive and message")); }));
        wizard->close();
    }

    // The guide in the UI language: Traditional Chinese when the UI speaks it.
    void guideInTheUiLanguage() {
        QStringList en, tw, cn;
        help::HelpWindow::guideText(QStringLiteral("en"), &en);
        const QString twText = help::HelpWindow::guideText(QStringLiteral("zh_TW"), &tw);
        const QString cnText = help::HelpWindow::guideText(QStringLiteral("zh_CN"), &cn);
        QCOMPARE(tw, en);  // the same sections in the same order
        QCOMPARE(cn, en);
        QVERIFY(twText.contains(QStringLiteral("節點")));
        QVERIFY(cnText.contains(QStringLiteral("节点")));
        MainWindow w;
        w.setQuiet(true);
        w.show();
        QVERIFY(QTest::qWaitForWindowActive(&w));
        w.setLanguage(QStringLiteral("zh_TW"), false);
        QTest::qWait(100);  // the old menus (and their F1) go at the next turn of the event loop
        focusAndF1(w.nodesDock()->findChild<QAbstractItemView*>(QStringLiteral("nodesView"))->viewport());
        QVERIFY(waitFor([&] { return helpOf(w) && helpOf(w)->isVisible(); }));
        QCOMPARE(helpOf(w)->language(), QStringLiteral("zh_TW"));
        QCOMPARE(helpOf(w)->section(), QStringLiteral("nodes"));
        QVERIFY(waitFor([&] { return headingInView(helpOf(w)->browser()) == QStringLiteral("節點"); }));
    }

    // Help ▸ Keyboard shortcuts: read from the actions, so Ctrl+Q (Quit), Ctrl+O and F1 are there.
    void shortcutsList() {
        MainWindow w;
        w.setQuiet(true);
        w.show();
        QVERIFY(QTest::qWaitForWindowActive(&w));
        QVERIFY(clickMenuItem(w, QStringLiteral("Help"), QStringLiteral("Keyboard shortcuts")));
        QTreeWidget* list = nullptr;
        QVERIFY(waitFor(
            [&] { return (list = w.findChild<QTreeWidget*>(QStringLiteral("shortcutsList"))) && list->isVisible(); }));
        QStringList rows;
        for (int i = 0; i < list->topLevelItemCount(); ++i)
            rows << list->topLevelItem(i)->text(0) + u'|' + list->topLevelItem(i)->text(1) + u'|' +
                        list->topLevelItem(i)->text(2);
        const QString all = rows.join(u'\n');
        QVERIFY2(rows.contains(QStringLiteral("Ctrl+Q|Quit|File")), qPrintable(all));
        QVERIFY2(rows.contains(QStringLiteral("Ctrl+O|Open log|File")), qPrintable(all));
        QVERIFY2(rows.contains(QStringLiteral("F1|CoScope guide|Help")), qPrintable(all));
        QVERIFY2(rows.contains(QStringLiteral("Ctrl+B|Bookmark|Trace")), qPrintable(all));
        QTest::keyClick(list->window(), Qt::Key_Escape);
    }

    // Help ▸ About CoScope: version, revision, licenses.
    void aboutBox() {
        MainWindow w;
        w.setQuiet(true);
        w.show();
        QVERIFY(QTest::qWaitForWindowActive(&w));
        QString text;
        ModalAnswerer about([&](QWidget* modal) {
            auto* box = qobject_cast<QMessageBox*>(modal);
            if (!box) return false;
            text = box->text();
            QTest::mouseClick(box->button(QMessageBox::Ok), Qt::LeftButton);
            return true;
        });
        QVERIFY(clickMenuItem(w, QStringLiteral("Help"), QStringLiteral("About CoScope")));
        QVERIFY(waitFor([&] { return about.answered(); }));
        QVERIFY2(text.contains(buildinfo::version()) && text.contains(buildinfo::revision()), qPrintable(text));
        for (const char* license : {"GPL-3.0-or-later", "LGPLv3", "QCustomPlot", "MIT"})
            QVERIFY2(text.contains(QLatin1String(license)), license);
    }
};

QTEST_MAIN(TestHelpMenu)
#include "test_help_menu.moc"
