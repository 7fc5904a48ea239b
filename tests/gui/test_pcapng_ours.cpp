// SPDX-License-Identifier: GPL-3.0-or-later
// A saved and reopened pcapng keeps which frames were ours (issue 35, item 7): on the virtual
// network the user scans the bus (Bus ▸ Scan network: our SDO requests), saves the trace as
// pcapng (File ▸ Save trace as) and opens it again (File ▸ Open log): the same frames show "Tx"
// in the trace's direction column, the drives' answers "Rx" (pcapng epb_flags, section 4.3.1).
#include "app/gui/MainWindow.h"
#include "app/gui/session/Workspace.h"
#include "app/gui/trace/LogSaveJob.h"
#include "app/gui/trace/TraceDock.h"
#include "app/gui/trace/TraceModel.h"
#include "eds/SimulatorDictionaries.h"

#include <QFileInfo>
#include <QSettings>
#include <QTemporaryDir>
#include <QtTest>

#include "tests/gui/MenuClick.h"
#include "tests/gui/ModalAnswer.h"
#include "tests/gui/WaitFor.h"

using namespace coscope;
using namespace coscope::gui;
using coscope::testing::answerFileDialog;
using coscope::testing::clickMenuItem;
using coscope::testing::waitFor;

namespace {
// The frame numbers of the trace whose direction column says "Tx".
std::vector<int> ours(MainWindow& w) {
    std::vector<int> out;
    TraceModel* m = w.traceDock()->model();
    for (int r = 0; r < m->rowCount(); ++r)
        if (m->data(m->index(r, TraceModel::Direction), Qt::DisplayRole).toString() == u"Tx") out.push_back(r);
    return out;
}
}  // namespace

class TestPcapngOurs : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;

    bool chooseFile(MainWindow& w, const QString& item, const QString& path) {
        auto name = answerFileDialog(path);
        if (!clickMenuItem(w, QStringLiteral("File"), item) || !waitFor([&] { return name->answered(); })) return false;
        w.activateWindow();  // offscreen there is no window manager to give the focus back
        return QTest::qWaitForWindowActive(&w);
    }

private slots:
    void initTestCase() {
        QCoreApplication::setOrganizationName(QStringLiteral("CoScopeTest"));
        QCoreApplication::setApplicationName(QStringLiteral("gui_pcapng_ours"));
        QSettings().clear();
        eds::installSimulatorDictionaries();
        QVERIFY(dir_.isValid());
    }

    void savedAndReopenedKeepsTx() {
        MainWindow w;
        w.setQuiet(true);
        w.show();
        QVERIFY(QTest::qWaitForWindowActive(&w));
        QVERIFY(w.connectBus(QStringLiteral("sim://")));
        QVERIFY(waitFor([&] { return w.workspace()->bus()->state() == CanBus::State::Open; }));
        QString asked;
        auto yes = coscope::testing::answerBox(QMessageBox::Yes, &asked);
        QVERIFY(clickMenuItem(w, QStringLiteral("Bus"), QStringLiteral("Scan network")));
        QVERIFY(waitFor([&] { return yes->answered(); }));
        QVERIFY(waitFor(
            [&] {
                w.refresh();
                return ours(w).size() >= 3 && w.traceDock()->model()->rowCount() > int(ours(w).size());
            },
            10000));
        w.disconnectBus();
        w.refresh();
        const std::vector<int> before = ours(w);
        const int rows = w.traceDock()->model()->rowCount();

        const QString out = dir_.filePath(QStringLiteral("ours.pcapng"));
        QVERIFY(chooseFile(w, QStringLiteral("Save trace as"), out));
        QVERIFY(waitFor([&] { return w.saveJob() == nullptr && QFileInfo::exists(out); }));
        QVERIFY(chooseFile(w, QStringLiteral("Open log"), out));
        QVERIFY(waitFor([&] {
            w.refresh();
            return w.workspace()->loadJob() && w.workspace()->loadJob()->isDone() &&
                   w.traceDock()->model()->rowCount() == rows;
        }));
        QCOMPARE(ours(w), before);
        QVERIFY(int(before.size()) < rows);  // the drives' answers stay Rx
    }
};

QTEST_MAIN(TestPcapngOurs)
#include "test_pcapng_ours.moc"
