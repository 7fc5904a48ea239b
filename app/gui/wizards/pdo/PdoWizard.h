// SPDX-License-Identifier: GPL-3.0-or-later
// Folder app/gui/wizards/pdo/ owns the PDO mapping wizard: one file per page (choose, mapping,
// timing, apply), its state, the frame layout picture and vendor notes.
#pragma once

#include "app/gui/wizards/pdo/PdoWizardState.h"
#include "core/canopen/CommandScript.h"
#include "core/canopen/PdoConfigurator.h"

#include <QPointer>
#include <QWizard>

#include <memory>
#include <vector>

namespace coscope::canopen {
class NmtMaster;
}

namespace coscope::gui {

class Workspace;
class WizardFramesPane;
class ScriptPreview;
class PdoChoosePage;
class PdoMappingPage;
class PdoTimingPage;
class PdoApplyPage;

// The PDO mapping wizard (Commission ▸ PDO mapping…): choose a node and one of its PDOs, read
// what it carries now, edit the mapped objects and the transmission settings, see the exact
// SDO/NMT sequence (dry run, savable as a script), then apply it with PdoConfigurator (CiA 301
// order, read-back verify, rollback on failure), optionally store it (1010h) and start the node.
// Every request and response shows in the frames pane at the bottom. Nothing blocks the GUI
// thread; nothing is sent in listen-only mode.
class PdoWizard : public QWizard {
    Q_OBJECT
public:
    enum PageId { ChoosePageId, MappingPageId, TimingPageId, ApplyPageId };
    enum class Outcome { None, Succeeded, Failed };

    // `node` -1: the first node with a dictionary, TPDO1, as soon as one is known.
    PdoWizard(Workspace* workspace, int node, QWidget* parent = nullptr);
    ~PdoWizard() override;

    Workspace* workspace() const { return workspace_; }
    PdoWizardState& state() { return state_; }
    const PdoWizardState& state() const { return state_; }

    // Targets `node`'s `pdo` and reads its configuration (currentRead() when done).
    void selectTarget(int node, canopen::PdoId pdo);
    bool isReading() const { return reading_; }
    // Opened without a node: the first node with a dictionary whose PDO carries something is
    // shown (nodes with an empty one are passed over) until the user picks one.
    void stopAutoPick() { autoPick_ = false; }
    QString readError() const { return readError_; }
    // Why the wizard may not send now ("" = it may): no bus, listen-only, closed.
    QString sendRefusal() const;
    // Listen-only bus: the wizard prepares the steps from the dictionary's defaults and saves
    // them as a script, but sends nothing (Apply disabled with the reason shown).
    bool isDryRunOnly() const;

    // Options of the last page.
    void setStoreAfterApply(bool on);
    bool storeAfterApply() const { return store_; }
    void setStartAfterApply(bool on);
    bool startAfterApply() const { return start_; }
    bool canStore() const;  // the node's dictionary has 1010h:01

    // The exact sequence apply() sends for the edited configuration (nothing is sent).
    canopen::CommandScript dryRun(QString* error = nullptr) const;
    // Applies the edited configuration; false + *why when refused before anything is sent.
    bool apply(QString* why = nullptr);
    bool isApplying() const { return applying_; }
    Outcome outcome() const { return outcome_; }
    QString outcomeText() const { return outcomeText_; }  // plain text of the last apply
    const canopen::PdoWriteResult& lastWrite() const { return lastWrite_; }

    WizardFramesPane* framesPane() const { return frames_; }
    PdoChoosePage* choosePage() const { return choose_; }
    PdoMappingPage* mappingPage() const { return mapping_; }
    PdoTimingPage* timingPage() const { return timing_; }
    PdoApplyPage* applyPage() const { return applyPage_; }
    ScriptPreview* preview() const;

signals:
    void currentRead(bool ok);
    void applyFinished(bool ok);

private:
    canopen::PdoConfigurator* configurator();
    void dropServices();
    void loadDictionary(int node);
    bool takeDictionaryDefaults();
    void finishApply(bool ok, const QString& text);
    void afterWrite(const canopen::PdoWriteResult& r);
    void runStoreAndStart(int row);
    void movePaneTo(int pageId);

    Workspace* workspace_;
    PdoWizardState state_;
    std::unique_ptr<canopen::NmtMaster> nmt_;
    std::unique_ptr<canopen::PdoConfigurator> configurator_;
    const void* servicesFor_ = nullptr;  // the SdoClient the configurator was made for
    WizardFramesPane* frames_ = nullptr;
    PdoChoosePage* choose_ = nullptr;
    PdoMappingPage* mapping_ = nullptr;
    PdoTimingPage* timing_ = nullptr;
    PdoApplyPage* applyPage_ = nullptr;
    bool reading_ = false;
    bool autoPick_ = false;
    std::vector<int> autoTried_;
    QString readError_;
    uint64_t readGeneration_ = 0;
    bool store_ = false;
    bool start_ = false;
    bool applying_ = false;
    Outcome outcome_ = Outcome::None;
    QString outcomeText_;
    canopen::PdoWriteResult lastWrite_;
    canopen::CommandScript applied_;  // the script being applied (rows of the preview)
};

}  // namespace coscope::gui
