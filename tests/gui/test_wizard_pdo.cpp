// SPDX-License-Identifier: GPL-3.0-or-later
// The PDO mapping wizard driven end to end against the virtual drives of every personality:
// read the current mapping, remap, dry run (nothing sent), apply (CiA 301 order, verified,
// read back from the device), the trace decodes the next PDO with the new layout; a mapping
// entry the drive rejects (fault injection) is reported with the step and the abort text and
// the old mapping stays in force; the saved script parses and replays as a dry run in the CLI;
// listen-only refuses.
#include <QAbstractButton>  // before ModalAnswer.h, which uses it
#include "app/gui/session/Workspace.h"
#include "app/gui/wizards/WizardMenu.h"
#include "app/gui/wizards/common/ScriptPreview.h"
#include "app/gui/wizards/common/WizardFramesPane.h"
#include "app/gui/wizards/pdo/PdoApplyPage.h"
#include "app/gui/wizards/pdo/PdoChoosePage.h"
#include "app/gui/wizards/pdo/PdoFrameLayout.h"
#include "app/gui/wizards/pdo/PdoMappingPage.h"
#include "app/gui/wizards/pdo/PdoTimingPage.h"
#include "app/gui/wizards/pdo/PdoWizard.h"
#include "core/canopen/CommandScript.h"
#include "core/canopen/PdoConfigurator.h"
#include "core/sim/SimBus.h"
#include "core/sim/VirtualDevice.h"
#include "eds/SimulatorDictionaries.h"
#include "tests/CliRun.h"
#include "tests/gui/ModalAnswer.h"

#include <QLabel>
#include <QPushButton>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest>

#include "tests/gui/WaitFor.h"

using namespace coscope;
using namespace coscope::gui;
using canopen::PdoMapEntry;

namespace {
using coscope::testing::waitFor;

// "6041:00" -> index, sub
std::pair<uint16_t, uint8_t> obj(const QString& text) {
    const QStringList p = text.split(QLatin1Char(':'));
    return {static_cast<uint16_t>(p[0].toUInt(nullptr, 16)), static_cast<uint8_t>(p[1].toUInt(nullptr, 16))};
}

QByteArray le32(uint32_t v) {
    QByteArray b(4, 0);
    for (int i = 0; i < 4; ++i) b[i] = static_cast<char>(v >> (8 * i));
    return b;
}

size_t txFrames(const TraceStore& s) {
    size_t n = 0;
    for (size_t i = 0; i < s.size(); ++i) n += (s.record(static_cast<FrameNo>(i)).flags & CanFrame::Tx) ? 1 : 0;
    return n;
}

// A live workspace on the virtual network with one drive whose dictionary is known.
struct Live {
    Workspace ws;
    int node = 0;
    bool open(const QString& url, int n, const QString& dictionary) {
        node = n;
        QString error;
        if (!ws.connectBus(url, &error)) return false;
        if (!waitFor([&] { return ws.bus()->state() == CanBus::State::Open; })) return false;
        ws.nodes().setDictionary(n, dictionary);
        if (ws.master()) ws.master()->setNodeDictionary(static_cast<uint8_t>(n), dictionary);
        ws.syncDictionaries();
        return true;
    }
    sim::SimNetwork* network() { return static_cast<SimBus*>(ws.bus())->network(); }
    void onDevice(const std::function<void(sim::VirtualDevice&)>& fn) {
        network()->runOnNetworkThread([&] {
            if (auto* d = network()->device(static_cast<uint8_t>(node))) fn(*d);
        });
    }
    // The PDO as the device reports it now (SDO reads through the same client).
    canopen::PdoReadResult readBack(canopen::PdoId pdo) {
        canopen::PdoConfigurator cfg(*ws.sdo());
        std::optional<canopen::PdoReadResult> r;
        cfg.read(static_cast<uint8_t>(node), pdo, [&](const canopen::PdoReadResult& x) { r = x; });
        waitFor([&] { return r.has_value(); });
        return r.value_or(canopen::PdoReadResult{});
    }
};

bool waitApplied(PdoWizard& w) {
    return waitFor([&] { return !w.isApplying(); }, 30000);
}
}  // namespace

class TestWizardPdo : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;

private slots:
    void initTestCase() {
        eds::installSimulatorDictionaries();
        QVERIFY(dir_.isValid());
    }

    void registeredInTheCommissionMenu() {
        bool found = false;
        for (const WizardEntry& e : wizardEntries())
            if (e.id == u"pdo") found = e.title == QStringLiteral("PDO mapping…");
        QVERIFY(found);
    }

    void endToEnd_data() {
        QTest::addColumn<QString>("personality");
        QTest::addColumn<int>("node");
        QTest::addColumn<QString>("a");  // new mapping: a, b
        QTest::addColumn<QString>("b");
        QTest::addColumn<QString>("c");  // failure case: a, b, c with c rejected by the drive
        QTest::newRow("delta-asda-a2") << "delta-asda-a2" << 1 << "6041:00"
                                       << "606C:00"
                                       << "6061:00";
        QTest::newRow("aimotor") << "aimotor" << 2 << "6041:00"
                                 << "606C:00"
                                 << "6061:00";
        QTest::newRow("dexmart-dev") << "dexmart-dev" << 3 << "3046:05"
                                     << "3046:16"
                                     << "3046:17";
        QTest::newRow("generic-cia402") << "generic-cia402" << 4 << "6041:00"
                                        << "606C:00"
                                        << "6061:00";
    }

    void endToEnd() {
        QFETCH(QString, personality);
        QFETCH(int, node);
        QFETCH(QString, a);
        QFETCH(QString, b);
        QFETCH(QString, c);
        Live live;
        QVERIFY(live.open(QStringLiteral("sim://?nodes=%1:%2").arg(node).arg(personality), node, personality));
        const canopen::PdoId tpdo1{true, 1};
        const auto before = live.readBack(tpdo1);
        QVERIFY2(before.ok, qPrintable(before.error));

        PdoWizard wiz(&live.ws, node);
        wiz.show();
        // Page 1: the current mapping is read from the device.
        QVERIFY2(waitFor([&] { return wiz.state().haveCurrent; }), qPrintable(wiz.readError()));
        QVERIFY(wiz.property("screenshotReady").toBool());
        QCOMPARE(wiz.state().current.entries, before.config.entries);
        QCOMPARE(wiz.state().dictionaryName, personality);
        QCOMPARE(wiz.choosePage()->currentRows(), std::max<int>(1, static_cast<int>(before.config.entries.size())));
        QVERIFY(wiz.choosePage()->isComplete());

        // Page 2: remap to a, b; reorder; the frame layout and bit total follow.
        wiz.next();
        QCOMPARE(wiz.currentId(), int(PdoWizard::MappingPageId));
        PdoMappingPage* map = wiz.mappingPage();
        QVERIFY(map->availableCount() > 3);
        map->setFilter(b.left(4));
        QVERIFY(map->availableCount() >= 1);
        map->setFilter(QString());
        map->clearMapping();
        QString why;
        QVERIFY(!map->addObject(0x1000, 0, &why));  // device type: not mappable
        QVERIFY2(why.contains(QStringLiteral("not PDO-mappable")) || why.contains(QStringLiteral("does not exist")),
                 qPrintable(why));
        const auto [ai, as] = obj(a);
        const auto [bi, bs] = obj(b);
        const auto [ci, cs] = obj(c);
        QVERIFY2(map->addObject(bi, bs, &why), qPrintable(why));
        QVERIFY2(map->addObject(ai, as, &why), qPrintable(why));
        map->moveUp(1);  // a first
        QCOMPARE(map->mappedCount(), 2);
        const auto wanted = wiz.state().wanted.entries;
        QCOMPARE(wanted[0].index, ai);
        QCOMPARE(wanted[1].index, bi);
        const int bits = wanted[0].bits + wanted[1].bits;
        QCOMPARE(map->frameLayout()->totalBits(), bits);
        QVERIFY2(map->frameLayout()->layoutText().startsWith(QStringLiteral("byte 0-1: ")) ||
                     map->frameLayout()->layoutText().startsWith(QStringLiteral("byte 0: ")),
                 qPrintable(map->frameLayout()->layoutText()));
        QVERIFY(map->isComplete());

        // Page 3: every SYNC.
        wiz.next();
        QCOMPARE(wiz.currentId(), int(PdoWizard::TimingPageId));
        wiz.timingPage()->setTransmissionType(1);
        QCOMPARE(wiz.state().wanted.transmissionType, uint8_t(1));

        // Page 4: the dry run shows the exact sequence and sends nothing.
        const size_t txBefore = txFrames(*live.ws.store());
        wiz.next();
        QCOMPARE(wiz.currentId(), int(PdoWizard::ApplyPageId));
        wiz.setStartAfterApply(true);
        QString error;
        const canopen::CommandScript dry = wiz.dryRun(&error);
        QVERIFY2(!dry.steps.empty(), qPrintable(error));
        QCOMPARE(dry.steps.front().kind, canopen::ScriptStep::Kind::Nmt);
        QCOMPARE(dry.steps.front().nmt, canopen::NmtCommand::EnterPreOperational);
        QCOMPARE(dry.steps.back().nmt, canopen::NmtCommand::Start);
        // CiA 301 order: COB-ID invalid first, mapping sub0 = 0 before the entries, sub0 = 2, COB-ID valid last of the writes.
        std::vector<const canopen::ScriptStep*> writes;
        for (const auto& s : dry.steps)
            if (s.kind == canopen::ScriptStep::Kind::SdoWrite) writes.push_back(&s);
        QVERIFY(writes.size() >= 5);
        QCOMPARE(writes.front()->index, uint16_t(0x1800));
        // DEXMART DEV's COB-ID is read-only (extract-dexmart §4.6): it cannot be switched off.
        const bool cobFixed = personality == u"dexmart-dev";
        QCOMPARE(std::count_if(writes.begin(), writes.end(),
                               [](const canopen::ScriptStep* w) { return w->index == 0x1800 && w->sub == 1; }),
                 cobFixed ? 0 : 2);
        if (!cobFixed) QVERIFY(uint8_t(writes.front()->data[3]) & 0x80);
        int entryAt = -1;
        for (size_t i = 0; i < writes.size(); ++i)
            if (writes[i]->index == 0x1A00 && writes[i]->sub == 1) entryAt = static_cast<int>(i);
        QVERIFY(entryAt > 0);
        QCOMPARE(writes[static_cast<size_t>(entryAt - 1)]->index, uint16_t(0x1A00));
        QCOMPARE(writes[static_cast<size_t>(entryAt - 1)]->data, QByteArray(1, '\0'));
        QCOMPARE(writes[static_cast<size_t>(entryAt)]->data, le32(wanted[0].encode()));
        if (!cobFixed) {
            QCOMPARE(writes.back()->index, uint16_t(0x1800));
            QCOMPARE(writes.back()->sub, uint8_t(1));
            QVERIFY(!(uint8_t(writes.back()->data[3]) & 0x80));
        }
        QCOMPARE(wiz.preview()->script().steps.size(), dry.steps.size());
        QTest::qWait(300);
        QCOMPARE(txFrames(*live.ws.store()), txBefore);  // the dry run sent nothing

        // Apply: verified, and the device reads back the new mapping.
        QVERIFY2(wiz.apply(&why), qPrintable(why));
        QVERIFY(wiz.isApplying());
        QVERIFY(waitApplied(wiz));
        // DEXMART DEV remaps with its read-only COB-ID left valid (manual: the mapping can be
        // changed by SDO); the virtual drive allows it.
        QVERIFY2(wiz.outcome() == PdoWizard::Outcome::Succeeded, qPrintable(wiz.outcomeText()));
        QVERIFY(wiz.outcomeText().contains(QStringLiteral("checked by reading back")));
        // The frames pane showed the requests and the drive's answers.
        wiz.framesPane()->poll();
        QVERIFY(wiz.framesPane()->rowCount() >= 2 * int(writes.size()));
        bool sawRequest = false, sawAnswer = false;
        for (int r = 0; r < wiz.framesPane()->rowCount(); ++r) {
            const QString row = wiz.framesPane()->rowText(r);
            sawRequest |= row.startsWith(QStringLiteral("Tx %1 ")
                                             .arg(0x600 + node, 3, 16, QChar(u'0'))
                                             .toUpper()
                                             .replace(QStringLiteral("TX"), QStringLiteral("Tx")));
            sawAnswer |= row.startsWith(QStringLiteral("Rx %1 ")
                                            .arg(0x580 + node, 3, 16, QChar(u'0'))
                                            .toUpper()
                                            .replace(QStringLiteral("RX"), QStringLiteral("Rx")));
        }
        QVERIFY2(sawRequest && sawAnswer, qPrintable(wiz.framesPane()->rowText(0)));
        const auto after = live.readBack(tpdo1);
        QVERIFY2(after.ok, qPrintable(after.error));
        QCOMPARE(after.config.entries, wanted);
        QCOMPARE(after.config.transmissionType, uint8_t(1));
        canopen::NmtState state = canopen::NmtState::BootUp;
        live.onDevice([&](sim::VirtualDevice& d) { state = d.nmtState(); });
        QCOMPARE(state, canopen::NmtState::Operational);

        // The trace decodes the next TPDO1 with the new layout (learned from the SDO writes).
        const uint32_t cob = after.config.cobId & 0x7FF;
        const size_t from = live.ws.store()->size();
        FrameNo pdoFrame = kNoFrame;
        QVERIFY(waitFor([&] {
            QString e;
            live.ws.bus()->send(CanFrame::classic(0x080, {}), &e);  // SYNC
            QTest::qWait(30);
            const TraceStore& s = *live.ws.store();
            for (size_t i = from; i < s.size(); ++i)
                if (s.record(static_cast<FrameNo>(i)).id == cob &&
                    !(s.record(static_cast<FrameNo>(i)).flags & CanFrame::Tx)) {
                    pdoFrame = static_cast<FrameNo>(i);
                    return true;
                }
            return false;
        }));
        QCOMPARE(int(live.ws.store()->record(pdoFrame).len), (bits + 7) / 8);
        dissect::Dissection d;
        d.reset(dissect::Dissection::Level::Flat);
        live.ws.traceDecoder().decodeAt(*live.ws.store(), pdoFrame, d);
        QVERIFY2(d.signalCount == 2, qPrintable(d.summary));
        QCOMPARE(d.pdoSignals[0].index, ai);
        QCOMPARE(d.pdoSignals[1].index, bi);
        QCOMPARE(int(d.pdoSignals[1].bitOffset), int(wanted[0].bits));

        // Failure: the drive rejects the third entry; the wizard says which step and what the
        // drive answered, and the old mapping (a, b) is in force again.
        live.onDevice([&](sim::VirtualDevice& dev) {
            dev.sdoFaults().abortOn = std::make_tuple(uint16_t(0x1A00), uint8_t(3), uint32_t(0x06040041));
        });
        wiz.back();
        wiz.back();
        QCOMPARE(wiz.currentId(), int(PdoWizard::MappingPageId));
        QVERIFY2(map->addObject(ci, cs, &why), qPrintable(why));
        QCOMPARE(map->mappedCount(), 3);
        wiz.next();
        wiz.next();
        wiz.setStartAfterApply(false);
        QVERIFY2(wiz.apply(&why), qPrintable(why));
        QVERIFY(waitApplied(wiz));
        QCOMPARE(wiz.outcome(), PdoWizard::Outcome::Failed);
        const QString text = wiz.outcomeText();
        QVERIFY2(text.contains(QStringLiteral("1A00:03")), qPrintable(text));
        QVERIFY2(
            text.contains(
                QStringLiteral("What the drive answered: node %1 aborted 1A00:03: Object cannot be mapped").arg(node)),
            qPrintable(text));
        QVERIFY2(text.contains(QStringLiteral("0x06040041")), qPrintable(text));
        QVERIFY2(text.contains(QStringLiteral("What to check:")), qPrintable(text));
        QVERIFY2(text.contains(QStringLiteral("written back")), qPrintable(text));
        QVERIFY(wiz.lastWrite().restored);
        QCOMPARE(wiz.lastWrite().abortCode, 0x06040041u);
        QVERIFY(wiz.applyPage()->resultText().contains(QStringLiteral("Stopped at step")));
        live.onDevice([](sim::VirtualDevice& dev) { dev.sdoFaults().abortOn.reset(); });
        const auto restored = live.readBack(tpdo1);
        QVERIFY2(restored.ok, qPrintable(restored.error));
        QCOMPARE(restored.config.entries, wanted);
        QCOMPARE(restored.config.cobId & 0x7FF, cob);
        QVERIFY(restored.config.valid());
    }

    void savedScriptReplaysAsDryRun() {
        Live live;
        QVERIFY(live.open(QStringLiteral("sim://?nodes=2:aimotor"), 2, QStringLiteral("aimotor")));
        PdoWizard wiz(&live.ws, 2);
        QVERIFY(waitFor([&] { return wiz.state().haveCurrent; }));
        wiz.next();
        wiz.mappingPage()->removeAt(1);  // drop 6061h: 6041h + 6064h
        wiz.next();
        wiz.timingPage()->setTransmissionType(255);
        wiz.next();
        wiz.setStoreAfterApply(true);
        wiz.applyPage()->refreshPreview();
        QString error;
        const canopen::CommandScript dry = wiz.dryRun(&error);
        QVERIFY2(!dry.steps.empty(), qPrintable(error));
        QCOMPARE(dry.steps.back().index, uint16_t(0x1010));  // store
        const QString path = dir_.filePath(QStringLiteral("tpdo1.cos"));
        QVERIFY2(wiz.preview()->saveTo(path, &error), qPrintable(error));
        const auto loaded = canopen::CommandScript::load(path, &error);
        QVERIFY2(loaded, qPrintable(error));
        QCOMPARE(loaded->steps.size(), dry.steps.size());
        for (size_t i = 0; i < dry.steps.size(); ++i)
            QVERIFY2(loaded->steps[i].sameAs(dry.steps[i]), qPrintable(dry.steps[i].toLine()));
        // The CLI prints it without sending.
        const Run r = cli({QStringLiteral("script"), QStringLiteral("run"), QStringLiteral("--dry-run"),
                           QStringLiteral("sim://?nodes=2:aimotor"), path},
                          30000);
        QVERIFY2(r.code == 0, qPrintable(r.err));
        QVERIFY2(r.out.contains(QStringLiteral("1A00"), Qt::CaseInsensitive), qPrintable(r.out));
    }

    // Issue 12 item 10: run the wizard by clicks on a virtual drive; the frames pane writes the
    // mapping entries and COB-IDs as the rest of the app does (60410010h, 182h), not in decimal.
    void framesPaneWritesHex() {
        Live live;
        QVERIFY(live.open(QStringLiteral("sim://?nodes=2:aimotor"), 2, QStringLiteral("aimotor")));
        PdoWizard wiz(&live.ws, 2);
        wiz.show();
        QVERIFY(QTest::qWaitForWindowExposed(&wiz));
        QAbstractButton* next = wiz.button(QWizard::NextButton);
        for (int i = 0; i < 3; ++i) {
            QTRY_VERIFY_WITH_TIMEOUT(next->isEnabled() && next->isVisible(), 10000);
            QTest::mouseClick(next, Qt::LeftButton);
        }
        QCOMPARE(wiz.currentId(), int(PdoWizard::ApplyPageId));
        auto* apply = wiz.currentPage()->findChild<QPushButton*>(QStringLiteral("pdoApply"));
        QVERIFY(apply && apply->isEnabled());
        QTest::mouseClick(apply, Qt::LeftButton);
        QVERIFY(waitApplied(wiz));
        QCOMPARE(wiz.outcome(), PdoWizard::Outcome::Succeeded);
        auto* pane = wiz.findChild<WizardFramesPane*>(QStringLiteral("pdoFrames"));
        QVERIFY(pane);
        auto paneText = [pane] {
            QStringList rows;
            for (int r = 0; r < pane->rowCount(); ++r) rows << pane->rowText(r);
            return rows.join(u'\n');
        };
        QTRY_VERIFY_WITH_TIMEOUT(paneText().contains(QStringLiteral("1A00:01")), 5000);
        const QString all = paneText();
        QVERIFY2(all.contains(QRegularExpression(QStringLiteral("1A00:01[^=\n]*= 60[0-9A-F]{6}h"))), qPrintable(all));
        QVERIFY2(all.contains(QRegularExpression(QStringLiteral("1800:01[^=\n]*= 182h"))), qPrintable(all));
        QVERIFY2(!all.contains(QRegularExpression(QStringLiteral("1A00:0[1-8][^=\n]*= \\d{6,}\\b"))), qPrintable(all));
        wiz.grab().save(QStringLiteral(COSCOPE_TEST_BINARY_DIR) + QStringLiteral("/wizard_pdo_frames_hex.png"));
    }

    // Issue 12 item 8: on a listen-only bus the wizard is a dry run: Next works from the
    // dictionary's defaults, the steps are prepared and saved as a script by clicks, Apply is
    // disabled with the reason on the page, and nothing is transmitted.
    void listenOnlyDryRun() {
        Live live;
        QVERIFY(live.open(QStringLiteral("sim://?nodes=2:aimotor&listen-only=1"), 2, QStringLiteral("aimotor")));
        PdoWizard wiz(&live.ws, 2);
        wiz.show();
        QVERIFY(QTest::qWaitForWindowExposed(&wiz));
        QAbstractButton* next = wiz.button(QWizard::NextButton);
        for (int i = 0; i < 3; ++i) {
            QTRY_VERIFY_WITH_TIMEOUT(next->isEnabled() && next->isVisible(), 5000);
            QTest::mouseClick(next, Qt::LeftButton);
        }
        QCOMPARE(wiz.currentId(), int(PdoWizard::ApplyPageId));
        QWizardPage* page = wiz.currentPage();
        auto* apply = page->findChild<QPushButton*>(QStringLiteral("pdoApply"));
        QVERIFY(apply && !apply->isEnabled());
        bool reasonShown = false;
        for (QLabel* l : page->findChildren<QLabel*>())
            reasonShown = reasonShown || (l->isVisible() && l->text().contains(QStringLiteral("listen-only")));
        QVERIFY(reasonShown);
        QVERIFY(wiz.preview()->rowCount() > 2);
        wiz.grab().save(QStringLiteral(COSCOPE_TEST_BINARY_DIR) + QStringLiteral("/wizard_pdo_listen_only.png"));

        auto* save = page->findChild<QPushButton*>(QStringLiteral("saveScript"));
        QVERIFY(save && save->isEnabled() && save->isVisible());
        const QString path = dir_.filePath(QStringLiteral("listen-only-dry-run.txt"));
        auto answer = coscope::testing::answerFileDialog(path);
        QTest::mouseClick(save, Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(QFile::exists(path), 10000);
        QFile f(path);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QString text = QString::fromUtf8(f.readAll());
        QVERIFY2(text.contains(QStringLiteral("sdo write 2 0x1a00:01")), qPrintable(text));

        QTest::mouseClick(apply, Qt::LeftButton);  // disabled: nothing happens
        QTest::qWait(300);
        QVERIFY(!wiz.isApplying());
        QCOMPARE(txFrames(*live.ws.store()), size_t(0));
    }
};

QTEST_MAIN(TestWizardPdo)
#include "test_wizard_pdo.moc"
