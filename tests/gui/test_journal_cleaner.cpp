// SPDX-License-Identifier: GPL-3.0-or-later
// The clean-up of old capture journals (issue 16, File ▸ Capture settings: keep N days, M MB)
// runs on a worker thread, not the GUI thread, and never removes a journal the window still
// needs: the one offered for reopening, the log opened, the last capture's (the trace pages from
// it), however old they are.
#include "app/gui/JournalOffer.h"
#include "app/gui/MainWindow.h"
#include "app/gui/session/CaptureSettingsDialog.h"
#include "app/gui/session/JournalCleaner.h"
#include "app/gui/session/Workspace.h"
#include "core/trace/CaptureJournal.h"
#include "eds/SimulatorDictionaries.h"

#include <QDialogButtonBox>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QPushButton>
#include <QSettings>
#include <QSpinBox>
#include <QTemporaryDir>
#include <QtTest>

#include <thread>

#include "tests/gui/MenuClick.h"
#include "tests/gui/ModalAnswer.h"
#include "tests/gui/WaitFor.h"

using namespace coscope;
using namespace coscope::gui;
using coscope::testing::answerFileDialog;
using coscope::testing::clickMenuItem;
using coscope::testing::waitFor;

namespace {
QString capturesFolder() { return qEnvironmentVariable("XDG_DATA_HOME") + QStringLiteral("/CoScope/captures"); }

bool setModified(const QString& path, const QDateTime& when) {
    QFile f(path);
    return f.open(QIODevice::ReadWrite) && f.setFileTime(when, QFileDevice::FileModificationTime);
}

// A journal of 50 frames, `daysAgo` days old; `unclosed`: as a killed app leaves it (its
// sidecar naming a process that is gone).
QString makeJournal(const QString& name, int daysAgo, bool unclosed) {
    QDir().mkpath(capturesFolder());
    const QString path = capturesFolder() + u'/' + name;
    CaptureJournal j;
    if (!j.open(path, {QStringLiteral("can0")})) return {};
    std::vector<CanFrame> v;
    for (int i = 0; i < 50; ++i) {
        CanFrame f = CanFrame::classic(0x181, {uint8_t(i)});
        f.timestampNs = 1'700'000'000'000'000'000LL + i * 1'000'000LL;
        v.push_back(f);
    }
    j.append(v);
    j.close();
    if (unclosed) {
        QFile s(CaptureJournal::sidecarOf(path));
        if (!s.open(QIODevice::WriteOnly)) return {};
        s.write("2147483646\n");
    }
    return setModified(path, QDateTime::currentDateTime().addDays(-daysAgo)) ? path : QString();
}

void typeInto(QSpinBox* box, const QString& text) {
    box->setFocus();
    QTest::keyClick(box, Qt::Key_A, Qt::ControlModifier);
    QTest::keyClicks(box, text);
}

// File ▸ Capture settings: keep `days` days, `megabytes` MB; OK.
bool applyKeep(MainWindow& w, const QString& days, const QString& megabytes) {
    if (!clickMenuItem(w, QStringLiteral("File"), QStringLiteral("Capture settings"))) return false;
    CaptureSettingsDialog* d = nullptr;
    if (!waitFor([&] { return (d = w.findChild<CaptureSettingsDialog*>()) && d->isVisible(); })) return false;
    typeInto(d->keepDays(), days);
    typeInto(d->keepMegabytes(), megabytes);
    QTest::mouseClick(d->buttons()->button(QDialogButtonBox::Ok), Qt::LeftButton);
    return waitFor([&] { return !w.findChild<CaptureSettingsDialog*>(); });
}
}  // namespace

class TestJournalCleaner : public QObject {
    Q_OBJECT
    QTemporaryDir data_;

private slots:
    void initTestCase() {
        QVERIFY(data_.isValid());
        qputenv("XDG_DATA_HOME", data_.path().toUtf8());
        QCoreApplication::setOrganizationName(QStringLiteral("CoScopeTest"));
        QCoreApplication::setApplicationName(QStringLiteral("gui_journal_cleaner"));
        QSettings().clear();
        eds::installSimulatorDictionaries();
    }

    void oldJournalsGoOnAWorkerNeededOnesStay() {
        const QString old = makeJournal(QStringLiteral("capture-old.pcapng"), 10, false);
        const QString offered = makeJournal(QStringLiteral("capture-offered.pcapng"), 10, true);
        const QString opened = makeJournal(QStringLiteral("capture-opened.pcapng"), 10, false);
        QVERIFY(!old.isEmpty() && !offered.isEmpty() && !opened.isEmpty());
        MainWindow w;
        w.setQuiet(true);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QCOMPARE(w.journalOffer()->offeredPath(), offered);
        // The clean-up at start (14 days by default) keeps them all.
        QVERIFY(waitFor([&] { return w.journalCleaner()->running() == 0; }));
        QVERIFY(QFileInfo::exists(old));

        // The technician opens one of the old journals as a log (File ▸ Open log).
        auto name = answerFileDialog(opened);
        QVERIFY(clickMenuItem(w, QStringLiteral("File"), QStringLiteral("Open log")));
        QVERIFY(waitFor([&] { return name->answered(); }));
        QVERIFY(waitFor([&] {
            return w.workspace()->loadJob() && w.workspace()->loadJob()->isDone() &&
                   w.workspace()->store()->size() == 50;
        }));

        // Then captures from the virtual drives; stops; that journal is old now too (the trace
        // still pages from it).
        QVERIFY(clickMenuItem(w, QStringLiteral("Bus"), QStringLiteral("Connect to virtual drives")));
        QVERIFY(waitFor([&] { return w.workspace()->journal() && w.workspace()->journal()->framesWritten() > 0; }));
        const QString live = w.workspace()->journalPath();
        QVERIFY(QFileInfo::exists(live));
        QVERIFY(clickMenuItem(w, QStringLiteral("Bus"), QStringLiteral("Disconnect")));
        QVERIFY(waitFor([&] { return !QFileInfo::exists(CaptureJournal::sidecarOf(live)); }));
        QVERIFY(setModified(live, QDateTime::currentDateTime().addDays(-10)));

        // Keep 3 days, 1 MB: every journal here is too old.
        QVERIFY(applyKeep(w, QStringLiteral("3"), QStringLiteral("1")));
        QVERIFY(waitFor([&] { return !QFileInfo::exists(old); }));
        QVERIFY(waitFor([&] { return w.journalCleaner()->running() == 0; }));
        QVERIFY(w.journalCleaner()->lastThread() != std::thread::id());
        QVERIFY(w.journalCleaner()->lastThread() != std::this_thread::get_id());  // a worker
        QVERIFY(QFileInfo::exists(offered));                                      // offered for reopening
        QVERIFY(QFileInfo::exists(opened));                                       // the log opened
        QVERIFY(QFileInfo::exists(live));  // the last capture, which the trace pages from

        // Dismissed, the offered one is an ordinary old journal: the next clean-up removes it.
        QTest::mouseClick(w.journalOffer()->dismissButton(), Qt::LeftButton);
        QVERIFY(applyKeep(w, QStringLiteral("3"), QStringLiteral("1")));
        QVERIFY(waitFor([&] { return !QFileInfo::exists(offered); }));
        QVERIFY(QFileInfo::exists(opened) && QFileInfo::exists(live));
    }
};

QTEST_MAIN(TestJournalCleaner)
#include "test_journal_cleaner.moc"
