// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/wizards/pdo/PdoWizard.h"
#include "app/gui/language/CoreText.h"

#include "app/gui/session/Workspace.h"
#include "app/gui/wizards/common/BusLossAdvice.h"
#include "app/gui/wizards/common/ScriptPreview.h"
#include "app/gui/wizards/common/WizardButtons.h"
#include "app/gui/wizards/common/WizardFramesPane.h"
#include "app/gui/wizards/pdo/PdoApplyPage.h"
#include "app/gui/wizards/pdo/PdoChoosePage.h"
#include "app/gui/wizards/pdo/PdoMappingPage.h"
#include "app/gui/wizards/pdo/PdoTimingPage.h"
#include "app/gui/wizards/pdo/PdoVendorNotes.h"
#include "core/canopen/NmtMaster.h"
#include "core/canopen/SdoClient.h"
#include "eds/DictionaryLibrary.h"

#include <QVBoxLayout>

#include <algorithm>
#include <map>

#include <spdlog/spdlog.h>

namespace coscope::gui {

namespace {
// Dictionaries by name, loaded once per process (GUI thread only).
std::shared_ptr<const od::ObjectDictionary> dictionaryNamed(const QString& name) {
    static std::map<QString, std::shared_ptr<const od::ObjectDictionary>> cache;
    if (name.isEmpty()) return nullptr;
    auto it = cache.find(name);
    if (it != cache.end()) return it->second;
    eds::ReadResult r = eds::loadDictionaryByPathOrName(name);
    std::shared_ptr<const od::ObjectDictionary> d;
    if (r.usable) d = std::make_shared<const od::ObjectDictionary>(std::move(r.dictionary));
    else spdlog::warn("PDO wizard: cannot load dictionary {}", name.toStdString());
    cache.emplace(name, d);
    return d;
}
// "save" (CiA 301 §7.5.2.13: 1010h signature 65766173h).
constexpr uint32_t kSaveSignature = 0x65766173u;
QByteArray le32(uint32_t v) {
    QByteArray b(4, 0);
    for (int i = 0; i < 4; ++i) b[i] = static_cast<char>(v >> (8 * i));
    return b;
}
}  // namespace

PdoWizard::PdoWizard(Workspace* workspace, int node, QWidget* parent) : QWizard(parent), workspace_(workspace) {
    setWindowTitle(tr("PDO mapping — CoScope"));
    setWizardStyle(QWizard::ClassicStyle);
    nameWizardButtons(this);
    setOption(QWizard::NoCancelButtonOnLastPage, true);
    setOption(QWizard::NoBackButtonOnStartPage, true);
    setProperty("screenshotReady", false);
    frames_ = new WizardFramesPane(workspace, this);
    frames_->setObjectName(QStringLiteral("pdoFrames"));
    frames_->setMinimumHeight(150);
    choose_ = new PdoChoosePage(this);
    mapping_ = new PdoMappingPage(this);
    timing_ = new PdoTimingPage(this);
    applyPage_ = new PdoApplyPage(this);
    setPage(ChoosePageId, choose_);
    setPage(MappingPageId, mapping_);
    setPage(TimingPageId, timing_);
    setPage(ApplyPageId, applyPage_);
    resize(1040, 820);
    connect(this, &QWizard::currentIdChanged, this, &PdoWizard::movePaneTo);
    connect(workspace_, &Workspace::sourceChanged, this, &PdoWizard::dropServices);
    connect(workspace_, &Workspace::busStateChanged, this, [this](CanBus::State s) {
        if (s != CanBus::State::Lost || !applying_) return;  // issue 16: stop, say what may be left
        const QString reason = workspace_->bus() ? workspace_->bus()->errorString() : QString();
        dropServices();
        finishApply(false, BusLossAdvice::pdoMessage(reason, state_.node, state_.pdo.name(),
                                                     BusLossAdvice::lastNmtState(workspace_->nodes(), state_.node)));
    });
    frames_->markStart();
    movePaneTo(ChoosePageId);
    autoPick_ = node <= 0;
    if (node > 0) selectTarget(node, canopen::PdoId{true, 1});
    else choose_->refreshNodes();
    choose_->showTarget();
}

PdoWizard::~PdoWizard() {
    configurator_.reset();
    nmt_.reset();
}

ScriptPreview* PdoWizard::preview() const { return applyPage_->preview(); }

void PdoWizard::movePaneTo(int pageId) {
    QWizardPage* p = page(pageId);
    if (!p) return;
    if (auto* slot = p->findChild<QVBoxLayout*>(QStringLiteral("framesSlot"))) {
        slot->addWidget(frames_);
        frames_->show();
    }
}

QString PdoWizard::sendRefusal() const {
    CanBus* bus = workspace_->bus();
    if (!bus || !workspace_->sdo() || !workspace_->master())
        return tr("Not connected to a bus: this wizard talks to the drive, so connect first (File ▸ Connect).");
    if (bus->isListenOnly())
        return tr(
            "The bus is open listen-only: CoScope never transmits on it, so this wizard can neither read nor change "
            "the drive. "
            "Reconnect without listen-only to use it.");
    if (!workspace_->canTransmit()) return tr("The bus is not open (yet): wait for it to connect.");
    return {};
}

bool PdoWizard::isDryRunOnly() const {
    const CanBus* bus = workspace_->bus();
    return bus && bus->isListenOnly() && workspace_->sdo() && workspace_->master();
}

// The PDO as the dictionary's defaults describe it (CiA 306 DefaultValue of 1400h-1BFFh), for a
// dry run on a bus where the drive cannot be asked.
bool PdoWizard::takeDictionaryDefaults() {
    const od::ObjectDictionary* d = state_.dictionary.get();
    if (!d) return false;
    const auto node = static_cast<uint8_t>(state_.node);
    auto value = [&](uint16_t index, uint8_t sub) -> std::optional<uint64_t> {
        const od::SubObject* e = d->entry(index, sub);
        if (!e) return std::nullopt;
        const auto v = e->resolvedDefault(node);
        return v ? v->toUInt64() : std::nullopt;
    };
    const auto count = value(state_.pdo.mappingIndex(), 0);
    if (!count) return false;
    canopen::PdoConfig c;
    c.cobId = static_cast<uint32_t>(value(state_.pdo.communicationIndex(), 1).value_or(state_.pdo.defaultCobId(node)));
    c.transmissionType = static_cast<uint8_t>(value(state_.pdo.communicationIndex(), 2).value_or(0xFF));
    if (const auto t = value(state_.pdo.communicationIndex(), 3)) c.inhibitTime = static_cast<uint16_t>(*t);
    if (const auto t = value(state_.pdo.communicationIndex(), 5)) c.eventTimer = static_cast<uint16_t>(*t);
    for (uint64_t i = 1; i <= std::min<uint64_t>(*count, 64); ++i)
        if (const auto raw = value(state_.pdo.mappingIndex(), static_cast<uint8_t>(i)); raw && *raw)
            c.entries.push_back(canopen::PdoMapEntry::decode(static_cast<uint32_t>(*raw)));
    state_.current = c;
    state_.wanted = c;
    state_.haveCurrent = true;
    state_.fromDictionary = true;
    return true;
}

canopen::PdoConfigurator* PdoWizard::configurator() {
    canopen::SdoClient* sdo = workspace_->sdo();
    if (!sdo || !workspace_->master()) return nullptr;
    if (servicesFor_ != sdo || !configurator_) {
        configurator_.reset();
        nmt_ = std::make_unique<canopen::NmtMaster>(*workspace_->master());
        configurator_ = std::make_unique<canopen::PdoConfigurator>(*sdo, nmt_.get());
        servicesFor_ = sdo;
    }
    return configurator_.get();
}

void PdoWizard::dropServices() {
    configurator_.reset();
    nmt_.reset();
    servicesFor_ = nullptr;
    if (reading_) {
        reading_ = false;
        readError_ = tr("the connection changed while reading");
        emit currentRead(false);
    }
    if (applying_)
        finishApply(false, tr("The connection was closed while the PDO was being changed. Connect again and read the "
                              "PDO to see what is in force."));
}

void PdoWizard::loadDictionary(int node) {
    QString name;
    if (const auto info = workspace_->nodes().node(node)) name = info->dictionary;
    if (name.isEmpty() && workspace_->master()) name = workspace_->master()->nodeDictionary(static_cast<uint8_t>(node));
    if (name == state_.dictionaryName && (state_.dictionary || name.isEmpty())) return;
    state_.dictionaryName = name;
    state_.dictionary = dictionaryNamed(name);
}

void PdoWizard::selectTarget(int node, canopen::PdoId pdo) {
    if (applying_ || node < 1 || node > 127) return;
    state_.node = node;
    state_.pdo = pdo;
    state_.haveCurrent = false;
    state_.fromDictionary = false;
    state_.current = {};
    state_.wanted = {};
    readError_.clear();
    loadDictionary(node);
    frames_->setNode(node);
    const uint64_t generation = ++readGeneration_;
    const QString refusal = sendRefusal();
    canopen::PdoConfigurator* cfg = refusal.isEmpty() ? configurator() : nullptr;
    if (!cfg) {
        reading_ = false;
        readError_ = refusal;
        if (isDryRunOnly() && takeDictionaryDefaults()) {
            setProperty("screenshotReady", true);
            choose_->showTarget();
            emit currentRead(true);
            return;
        }
        choose_->showTarget();
        emit currentRead(false);
        return;
    }
    reading_ = true;
    choose_->showTarget();
    emit choose_->completeChanged();
    QPointer<PdoWizard> self(this);
    cfg->read(static_cast<uint8_t>(node), pdo, [self, generation](const canopen::PdoReadResult& r) {
        if (!self || generation != self->readGeneration_) return;
        self->reading_ = false;
        if (self->autoPick_ && r.ok && r.config.entries.empty()) {
            // Opened without a node: pass over a node whose PDO is empty if another may show more.
            self->autoTried_.push_back(self->state_.node);
            for (const canopen::NodeInfo& n : self->workspace_->nodes().snapshot())
                if (!n.dictionary.isEmpty() &&
                    std::find(self->autoTried_.begin(), self->autoTried_.end(), n.node) == self->autoTried_.end()) {
                    self->selectTarget(n.node, self->state_.pdo);
                    return;
                }
        }
        if (r.ok) {
            self->state_.current = r.config;
            self->state_.wanted = r.config;
            self->state_.haveCurrent = true;
            self->setProperty("screenshotReady", true);
        } else {
            self->readError_ = r.error;
        }
        emit self->currentRead(r.ok);
    });
}

void PdoWizard::setStoreAfterApply(bool on) {
    if (store_ == on) return;
    store_ = on;
    applyPage_->syncOptions();
}

void PdoWizard::setStartAfterApply(bool on) {
    if (start_ == on) return;
    start_ = on;
    applyPage_->syncOptions();
}

bool PdoWizard::canStore() const { return state_.dictionary && state_.dictionary->entry(0x1010, 1); }

canopen::CommandScript PdoWizard::dryRun(QString* error) const {
    canopen::CommandScript script;
    auto fail = [&](const QString& why) {
        if (error) *error = why;
        return script;
    };
    if (state_.node < 1) return fail(tr("Choose a drive first."));
    if (!state_.haveCurrent) return fail(tr("The PDO has not been read from the drive yet."));
    auto* cfg = const_cast<PdoWizard*>(this)->configurator();
    if (!cfg) return fail(sendRefusal());
    QString why;
    script = cfg->plan(static_cast<uint8_t>(state_.node), state_.pdo, state_.wanted, state_.dictionary.get(), &why);
    if (script.steps.empty()) return fail(coreText(why));
    script.title = tr("PDO mapping: %1 of node %2").arg(state_.pdo.name()).arg(state_.node);
    if (store_ && canStore()) {
        canopen::ScriptStep s;
        s.kind = canopen::ScriptStep::Kind::SdoWrite;
        s.node = static_cast<uint8_t>(state_.node);
        s.index = 0x1010;
        s.sub = 1;
        s.data = le32(kSaveSignature);
        s.why = tr("Keep the settings after power-off: store all parameters (1010h:01 = \"save\", CiA 301 §7.5.2.13)");
        script.steps.push_back(s);
    }
    if (start_) {
        canopen::ScriptStep s;
        s.kind = canopen::ScriptStep::Kind::Nmt;
        s.nmt = canopen::NmtCommand::Start;
        s.node = static_cast<uint8_t>(state_.node);
        s.why = tr("Start process data: the drive goes operational and sends/uses its PDOs (NMT start)");
        script.steps.push_back(s);
    }
    if (error) error->clear();
    return script;
}

bool PdoWizard::apply(QString* why) {
    auto refuse = [&](const QString& text) {
        if (why) *why = text;
        return false;
    };
    if (const QString r = sendRefusal(); !r.isEmpty()) return refuse(r);
    if (applying_) return refuse(tr("A change is already being applied."));
    QString error;
    applied_ = dryRun(&error);
    if (applied_.steps.empty()) return refuse(error);
    auto* cfg = configurator();
    if (!cfg) return refuse(sendRefusal());
    preview()->setScript(applied_);
    applying_ = true;
    outcome_ = Outcome::None;
    outcomeText_.clear();
    lastWrite_ = {};
    spdlog::info("PDO wizard: applying {} of node {}", state_.pdo.name().toStdString(), state_.node);
    QPointer<PdoWizard> self(this);
    cfg->write(static_cast<uint8_t>(state_.node), state_.pdo, state_.wanted, state_.dictionary.get(),
               [self](const canopen::PdoWriteResult& r) {
                   if (self && self->applying_) self->afterWrite(r);
               });
    return true;
}

void PdoWizard::afterWrite(const canopen::PdoWriteResult& r) {
    lastWrite_ = r;
    // Rows of the preview: [0] NMT pre-operational, then the SDO writes, then the checks,
    // then store and start (see dryRun()).
    int writes = 0, planRows = 0;
    for (const auto& s : applied_.steps) {
        if (s.kind == canopen::ScriptStep::Kind::SdoWrite && s.index != 0x1010) ++writes;
        if (!(s.index == 0x1010 || (s.kind == canopen::ScriptStep::Kind::Nmt && s.nmt == canopen::NmtCommand::Start)))
            ++planRows;
    }
    ScriptPreview* pv = preview();
    if (!r.ok) {
        int failedRow = 0;
        if (r.failedStepNumber >= 0) failedRow = 1 + r.failedStepNumber;
        else if (r.failedStep == u"verify") failedRow = 1 + writes;
        for (int i = 0; i < failedRow; ++i) pv->markStep(i, true);
        pv->markStep(failedRow, false, coreText(r.error));
        const QString stepWhy = failedRow < static_cast<int>(applied_.steps.size())
                                    ? coreLines(applied_.steps[static_cast<size_t>(failedRow)].why)
                                    : QString();
        QStringList lines;
        lines << tr("Stopped at step %1 of %2: %3%4.")
                     .arg(failedRow + 1)
                     .arg(applied_.steps.size())
                     .arg(stepWhy, r.failedStep.isEmpty() ? QString() : QStringLiteral(" [%1]").arg(r.failedStep));
        // r.error: "<step> failed: <answer>; previous mapping restored" -> the answer alone.
        QString answer = r.error;
        if (!r.failedStep.isEmpty() && answer.startsWith(r.failedStep + QStringLiteral(" failed: ")))
            answer = answer.mid(r.failedStep.size() + 9);
        for (const QString& tail : {QStringLiteral("; previous mapping restored"),
                                    QStringLiteral("; restoring the previous mapping failed too: ")}) {
            const qsizetype at = answer.indexOf(tail);
            if (at >= 0) answer.truncate(at);
        }
        lines << tr("What the drive answered: %1").arg(coreText(answer));
        const bool timedOut = r.error.contains(QStringLiteral("timed out"), Qt::CaseInsensitive) ||
                              r.error.contains(QStringLiteral("no answer"), Qt::CaseInsensitive);
        lines << tr("What to check: %1").arg(pdoFailureAdvice(r.abortCode, timedOut, state_.dictionaryName));
        if (r.restored) {
            lines << tr("The previous settings were written back: %1 works as before (%2 objects, %3 bits). The drive "
                        "was left pre-operational.")
                         .arg(state_.pdo.name())
                         .arg(r.previous.entries.size())
                         .arg(r.previous.totalBits());
            state_.current = r.previous;
        } else if (!r.steps.isEmpty()) {
            lines << tr("Writing the previous settings back failed as well (%1): read the PDO again and check it "
                        "before starting the drive.")
                         .arg(coreText(
                             r.error.section(QStringLiteral("; restoring the previous mapping failed too: "), 1)));
        } else {
            lines << tr("Nothing was changed on the drive.");
        }
        finishApply(false, lines.join(QLatin1Char('\n')));
        return;
    }
    for (int i = 0; i < planRows; ++i) pv->markStep(i, true);
    state_.current = r.written;
    state_.wanted = r.written;
    runStoreAndStart(planRows);
}

void PdoWizard::runStoreAndStart(int row) {
    const uint8_t node = static_cast<uint8_t>(state_.node);
    QString done = tr("Done: %1 of node %2 now carries %3 objects (%4 bits), checked by reading back. The trace and "
                      "the plot decode it with the new layout from now on.")
                       .arg(state_.pdo.name())
                       .arg(node)
                       .arg(state_.current.entries.size())
                       .arg(state_.current.totalBits());
    auto start = [this, node, row](int at, QString text) {
        if (!start_) {
            text += tr(" The drive is pre-operational: start it (NMT start) to make PDOs flow.");
            return finishApply(true, text);
        }
        QString error;
        if (!nmt_ || !nmt_->start(node, &error)) {
            preview()->markStep(at, false, error);
            return finishApply(false, text + tr(" Starting the drive failed: %1").arg(coreText(error)));
        }
        preview()->markStep(at, true);
        Q_UNUSED(row);
        finishApply(true, text + tr(" The drive was started (operational)."));
    };
    if (!(store_ && canStore())) return start(row, done);
    QPointer<PdoWizard> self(this);
    workspace_->sdo()->download(
        node, 0x1010, 1, le32(kSaveSignature), [self, row, done, start](const canopen::SdoResult& r) {
            if (!self || !self->applying_) return;
            self->preview()->markStep(row, r.ok, r.ok ? QString() : coreText(r.error));
            if (!r.ok)
                return self->finishApply(
                    false,
                    done + tr("\nBut storing failed (%1): the new mapping works now and is lost at power-off. %2")
                               .arg(coreText(r.error), pdoFailureAdvice(r.serverAborted ? r.abortCode : 0, r.timedOut,
                                                                        self->state_.dictionaryName)));
            start(row + 1, done + tr(" Stored in the drive (kept after power-off)."));
        });
}

void PdoWizard::finishApply(bool ok, const QString& text) {
    applying_ = false;
    outcome_ = ok ? Outcome::Succeeded : Outcome::Failed;
    outcomeText_ = text;
    (ok ? spdlog::info("PDO wizard: {}", text.toStdString()) : spdlog::warn("PDO wizard: {}", text.toStdString()));
    emit applyFinished(ok);
}

}  // namespace coscope::gui
