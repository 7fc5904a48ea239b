// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/wizards/nodeid/NodeIdWizard.h"
#include "app/gui/language/CoreText.h"

#include "app/gui/nodes/NodeScanner.h"
#include "app/gui/session/Workspace.h"
#include "app/gui/wizards/common/BusLossAdvice.h"
#include "app/gui/wizards/common/ScriptPreview.h"
#include "app/gui/wizards/common/WizardButtons.h"
#include "app/gui/wizards/common/WizardFramesPane.h"
#include "app/gui/wizards/nodeid/NodeIdPages.h"
#include "core/canopen/LssMaster.h"
#include "core/canopen/MasterContext.h"
#include "core/sim/BusAtBitRate.h"

#include <QTimer>
#include <QVBoxLayout>

namespace coscope::gui {

using canopen::bitRateText;

NodeIdWizard::NodeIdWizard(Workspace* workspace, int node, QWidget* parent) : QWizard(parent), workspace_(workspace) {
    setWindowTitle(tr("Baud rate and node-ID — CoScope"));
    setWizardStyle(QWizard::ClassicStyle);
    nameWizardButtons(this);
    setOption(QWizard::NoBackButtonOnStartPage, true);
    setOption(QWizard::NoCancelButtonOnLastPage, true);
    setProperty("screenshotReady", false);
    request_.newNodeId = 0;
    request_.newBitRate = 0;
    frames_ = new WizardFramesPane(workspace, this);
    frames_->setObjectName(QStringLiteral("nodeIdFrames"));
    frames_->setMinimumHeight(140);
    frames_->setNode(-1);  // LSS, NMT and both node-IDs matter here
    find_ = new NodeIdFindPage(this);
    change_ = new NodeIdChangePage(this);
    run_ = new NodeIdRunPage(this);
    setPage(FindPageId, find_);
    setPage(ChangePageId, change_);
    setPage(RunPageId, run_);
    resize(1000, 760);
    connect(this, &QWizard::currentIdChanged, this, &NodeIdWizard::movePaneTo);
    // The services hang on the bus's dispatcher: let go of them while it still exists.
    connect(workspace_, &Workspace::aboutToDisconnect, this, &NodeIdWizard::dropServices);
    connect(workspace_, &Workspace::sourceChanged, this, &NodeIdWizard::dropServices);
    connect(workspace_, &Workspace::busStateChanged, this, [this](CanBus::State s) {
        if (s != CanBus::State::Lost || !running_ || reconnecting_) return;  // issue 16: stop, say what may be left
        const QString reason = workspace_->bus() ? workspace_->bus()->errorString() : QString();
        const int node = request_.node;
        changer_.reset();
        changerFor_ = nullptr;
        finish(false,
               BusLossAdvice::settingsMessage(reason, node, BusLossAdvice::lastNmtState(workspace_->nodes(), node)));
    });
    frames_->markStart();
    movePaneTo(FindPageId);
    if (node > 0) selectNode(node);
    find_->refresh();
}

NodeIdWizard::~NodeIdWizard() {
    changer_.reset();
    fastscanLss_.reset();
}

ScriptPreview* NodeIdWizard::preview() const { return run_->preview(); }

void NodeIdWizard::movePaneTo(int pageId) {
    QWizardPage* p = page(pageId);
    if (!p) return;
    if (auto* slot = p->findChild<QVBoxLayout*>(QStringLiteral("framesSlot"))) {
        slot->addWidget(frames_);
        frames_->show();
    }
}

QString NodeIdWizard::sendRefusal() const {
    CanBus* bus = workspace_->bus();
    if (!bus || !workspace_->sdo() || !workspace_->master())
        return tr("Not connected to a bus: this wizard talks to the devices, so connect first (File ▸ Connect).");
    if (bus->isListenOnly())
        return tr(
            "The bus is open listen-only: CoScope never transmits on it, so this wizard cannot change anything. "
            "Reconnect without listen-only to use it.");
    if (!workspace_->canTransmit()) return tr("The bus is not open (yet): wait for it to connect.");
    return {};
}

canopen::NodeSettingsChanger* NodeIdWizard::changer() {
    canopen::SdoClient* sdo = workspace_->sdo();
    if (!sdo || !workspace_->master()) return nullptr;
    if (changerFor_ != sdo || !changer_) {
        changer_ = std::make_unique<canopen::NodeSettingsChanger>(*workspace_->master(), *sdo);
        changerFor_ = sdo;
    }
    return changer_.get();
}

void NodeIdWizard::dropServices() {
    changer_.reset();
    fastscanLss_.reset();
    changerFor_ = nullptr;
    if (running_ && !reconnecting_)
        finish(false, tr("The connection was closed while the change was running. Connect again and scan to see where "
                         "the device is."));
}

std::vector<int> NodeIdWizard::knownNodes() const {
    std::vector<int> out;
    for (const auto& n : workspace_->nodes().snapshot()) out.push_back(n.node);
    std::sort(out.begin(), out.end());
    return out;
}

void NodeIdWizard::selectNode(int node) {
    if (running_ || node < 1 || node > 127) return;
    request_.node = static_cast<uint8_t>(node);
    identityKnown_ = false;
    request_.identity = {};
    QString dict;
    if (const auto info = workspace_->nodes().node(node)) {
        dict = info->dictionary;
        if (info->vendorId && info->productCode && info->revision && info->serial) {
            request_.identity = {*info->vendorId, *info->productCode, *info->revision, *info->serial};
            identityKnown_ = true;
        }
    }
    request_.dictionary = dict;
    if (!vendorMethodAvailable()) request_.method = Method::Lss;
    plan_.reset();
    frames_->setNode(node);
    setProperty("screenshotReady", true);
    emit targetChanged();
}

void NodeIdWizard::setDictionary(const QString& name) {
    request_.dictionary = name;
    if (!vendorMethodAvailable()) request_.method = Method::Lss;
    plan_.reset();
    emit targetChanged();
}

void NodeIdWizard::scan() {
    if (!sendRefusal().isEmpty() || isScanning()) return;
    delete scanner_;
    scanner_ = new NodeScanner(workspace_->sdo(), this);
    connect(scanner_, &NodeScanner::finished, this, [this](int) {
        workspace_->syncDictionaries();
        if (request_.node == 0) {
            const auto nodes = knownNodes();
            if (!nodes.empty()) selectNode(nodes.front());
        } else if (request_.node != 0xFF) {
            selectNode(request_.node);  // identity and dictionary are known now
        }
        emit scanFinished();
    });
    scanner_->scan(1, 127, 300);
}

bool NodeIdWizard::isScanning() const { return scanner_ && scanner_->isRunning(); }

void NodeIdWizard::findUnconfigured() {
    if (!sendRefusal().isEmpty() || running_) return;
    fastscanLss_ = std::make_unique<canopen::LssMaster>(*workspace_->master());
    QPointer<NodeIdWizard> self(this);
    fastscanLss_->fastscan([self](const canopen::LssResult& r) {
        if (!self) return;
        if (!r.ok) {
            emit self->fastscanFinished(
                false,
                r.noSlave
                    ? tr("No device without node-ID answered (LSS Fastscan). Every device on the bus has a node-ID.")
                    : coreText(r.error));
            return;
        }
        self->request_.node = 0xFF;
        self->request_.identity = r.identity;
        self->identityKnown_ = true;
        self->request_.method = Method::Lss;
        self->request_.change = Change::NodeId;
        self->request_.dictionary.clear();
        self->plan_.reset();
        self->frames_->setNode(-1);
        emit self->targetChanged();
        emit self->fastscanFinished(true, tr("Found a device without node-ID: vendor %1h, product %2h, serial %3h. It "
                                             "waits in LSS configuration state for its node-ID.")
                                              .arg(r.identity.vendorId, 8, 16, QChar(u'0'))
                                              .arg(r.identity.productCode, 8, 16, QChar(u'0'))
                                              .arg(r.identity.serial, 8, 16, QChar(u'0')));
    });
}

void NodeIdWizard::setChange(Change c) {
    request_.change = c;
    if (c == Change::BitRate && request_.node != 0xFF && request_.newBitRate == 0)
        request_.newBitRate = busBitRate() == 250000 ? 500000 : 250000;
    plan_.reset();
    emit targetChanged();
}

void NodeIdWizard::setMethod(Method m) {
    request_.method = m == Method::Vendor && !vendorMethodAvailable() ? Method::Lss : m;
    plan_.reset();
    emit targetChanged();
}

void NodeIdWizard::setNewNodeId(int id) {
    request_.newNodeId = static_cast<uint8_t>(std::clamp(id, 0, 127));
    plan_.reset();
    emit targetChanged();
}

void NodeIdWizard::setNewBitRate(int bitRate) {
    request_.newBitRate = bitRate;
    plan_.reset();
    emit targetChanged();
}

int NodeIdWizard::busBitRate() const {
    const int r = workspace_->bus() ? workspace_->bus()->url().bitrate() : 0;
    return r > 0 ? r : 500000;
}

bool NodeIdWizard::vendorMethodAvailable() const {
    const auto v = canopen::vendorNodeSettings(request_.dictionary);
    if (!v || request_.node == 0xFF) return false;
    return request_.change == Change::NodeId ? v->nodeId.has_value() : v->bitRate.has_value();
}

QString NodeIdWizard::vendorParameterName() const {
    const auto v = canopen::vendorNodeSettings(request_.dictionary);
    if (!v) return {};
    const auto& o = request_.change == Change::NodeId ? v->nodeId : v->bitRate;
    if (!o) return {};
    return QStringLiteral("%1 (%2h%3)")
        .arg(o->parameter)
        .arg(o->index, 4, 16, QChar(u'0'))
        .arg(o->sub ? QStringLiteral(":%1").arg(o->sub, 2, 16, QChar(u'0')) : QString())
        .toUpper()
        .replace(QStringLiteral("H"), QStringLiteral("h"));
}

QString NodeIdWizard::blockingProblem() const {
    if (request_.node == 0) return tr("Choose a device first.");
    if (request_.change == Change::NodeId) {
        if (request_.newNodeId < 1) return tr("Choose the new node-ID.");
        if (request_.newNodeId == request_.node) return tr("The device already has node-ID %1.").arg(request_.node);
        const auto nodes = knownNodes();
        if (request_.newNodeId != vacated_ &&
            std::find(nodes.begin(), nodes.end(), int(request_.newNodeId)) != nodes.end())
            return tr("Node-ID %1 is already used by another device on this bus: two devices with one node-ID break "
                      "communication.")
                .arg(request_.newNodeId);
    } else if (request_.newBitRate <= 0 || request_.newBitRate == busBitRate()) {
        return tr("Choose a bit rate other than the one the bus runs at now (%1).").arg(bitRateText(busBitRate()));
    }
    canopen::NodeSettingsRequest r = request_;
    r.bitRate = busBitRate();
    QString error;
    if (!canopen::planNodeSettings(r, &error)) return coreText(error);
    return {};
}

QString NodeIdWizard::explanation() const {
    canopen::NodeSettingsRequest r = request_;
    r.bitRate = busBitRate();
    QString error;
    const auto p = canopen::planNodeSettings(r, &error);
    QStringList parts;
    const QString who = request_.node == 0xFF ? tr("the device without node-ID") : tr("node %1").arg(request_.node);
    if (request_.method == Method::Lss)
        parts << tr("<b>How:</b> LSS (layer setting services, CiA 305) picks %1 by its identity (1018h) and gives it "
                    "the new setting; "
                    "the device stores it itself.")
                     .arg(who);
    else
        parts << tr("<b>How:</b> CoScope writes the drive's own parameter %1 over SDO (the way its manual describes).")
                     .arg(vendorParameterName());
    if (p) {
        QString when = coreText(p->takesEffect);
        while (when.endsWith(u'.')) when.chop(1);  // the sentence gets its own full stop
        parts << tr("<b>Takes effect:</b> %1.").arg(when.toHtmlEscaped());
    }
    if (const auto v = canopen::vendorNodeSettings(request_.dictionary))
        parts << tr("<b>About this drive:</b> %1").arg(coreText(v->note).toHtmlEscaped());
    if (request_.change == Change::BitRate) {
        QStringList others;
        for (int n : knownNodes())
            if (n != request_.node) others << QString::number(n);
        parts << tr("<b style='color:#a40000'>Every other node on this bus</b> (%1) stays at %2. After the change, %3 "
                    "only talks at %4: "
                    "the others cannot reach it until they are changed too. Change them all, one after another, then "
                    "the bus runs at %4.")
                     .arg(others.isEmpty() ? tr("none seen") : tr("nodes %1").arg(others.join(QStringLiteral(", "))),
                          bitRateText(busBitRate()), who,
                          bitRateText(request_.newBitRate > 0 ? request_.newBitRate : busBitRate()));
        parts << tr("CoScope reconnects at the new bit rate by itself and waits for %1 there.").arg(who);
    }
    if (p) parts << tr("<b>If it does not come back:</b> %1").arg(coreText(p->recovery).toHtmlEscaped());
    else if (!error.isEmpty())
        parts << tr("<b style='color:#a40000'>Cannot do this:</b> %1").arg(coreText(error).toHtmlEscaped());
    return parts.join(QStringLiteral("<br>"));
}

void NodeIdWizard::prepareDryRun() {
    plan_.reset();
    planError_.clear();
    const uint64_t gen = ++dryRunGeneration_;
    canopen::NodeSettingsRequest r = request_;
    r.bitRate = busBitRate();
    r.waitMs = request_.method == Method::Vendor ? 15000 : 5000;  // a power cycle by hand takes a while
    const bool needsReads = (r.method == Method::Lss && r.node != 0xFF && !identityKnown_) ||
                            (r.method == Method::Vendor && r.change == Change::BitRate);
    auto take = [this, gen](std::optional<canopen::NodeSettingsPlan> p, const QString& error) {
        if (gen != dryRunGeneration_) return;
        plan_ = std::move(p);
        planError_ = error;
        preview()->setScript(plan_ ? plan_->whole() : canopen::CommandScript{});
        emit dryRunReady(plan_.has_value());
    };
    if (!needsReads) {
        QString error;
        auto p = canopen::planNodeSettings(r, &error);
        take(std::move(p), error);
        return;
    }
    auto* c = sendRefusal().isEmpty() ? changer() : nullptr;
    if (!c) return take(std::nullopt, sendRefusal());
    QPointer<NodeIdWizard> self(this);
    c->prepare(r, [self, take](std::optional<canopen::NodeSettingsPlan> p, QString error) {
        if (self) take(std::move(p), error);
    });
}

bool NodeIdWizard::start(QString* why) {
    auto refuse = [why](const QString& text) {
        if (why) *why = text;
        return false;
    };
    if (running_) return refuse(tr("The change is already running."));
    if (const QString r = sendRefusal(); !r.isEmpty()) return refuse(r);
    if (!plan_) return refuse(planError_.isEmpty() ? tr("The sequence is not ready yet.") : planError_);
    running_ = true;
    outcome_ = Outcome::None;
    outcomeText_.clear();
    preview()->clearMarks();
    frames_->setNode(-1);  // the node answers at a new node-ID or bit rate: show everything
    emit progress(tr("Running…"));
    runPart(0);
    return true;
}

void NodeIdWizard::runPart(int part) {
    auto* c = changer();
    if (!c) return finish(false, tr("The connection is gone: %1").arg(sendRefusal()));
    // The preview shows plan_->whole(): the second part comes after the Reconnect step.
    const int offset = part == 0 ? 0 : static_cast<int>(plan_->beforeReconnect.steps.size()) + 1;
    QPointer<NodeIdWizard> self(this);
    c->run(
        *plan_, part,
        [self, offset](int step) {
            if (self) self->preview()->markRunning(offset + step);
        },
        [self, offset](int step, bool ok, const QString& detail) {
            if (self) self->preview()->markStep(offset + step, ok, detail);
        },
        [self, part](const canopen::NodeSettingsOutcome& out) {
            if (!self) return;
            if (!out.ok) {
                QString text = tr("Stopped at %1.\nThe device answered: %2\nWhat to check: %3")
                                   .arg(coreText(out.step), coreText(out.answer), coreText(out.advice));
                if (!out.restored.isEmpty()) text += QStringLiteral("\n") + coreText(out.restored);
                return self->finish(false, text);
            }
            if (part == 0 && self->plan_->reconnect) return self->reconnect();
            const auto& r = self->plan_->request;
            if (r.change == Change::NodeId)
                self->finish(true,
                             tr("Done: the device that was %1 now answers at node-ID %2 (it reported on the bus).")
                                 .arg(r.node == 0xFF ? tr("without node-ID") : tr("node %1").arg(r.node))
                                 .arg(r.newNodeId));
            else
                self->finish(true, tr("Done: node %1 now runs at %2 and CoScope is connected at %2. Nodes still at %3 "
                                      "cannot be reached at this rate: "
                                      "change them too, or reconnect at %3.")
                                       .arg(r.node)
                                       .arg(bitRateText(r.newBitRate), bitRateText(r.bitRate)));
        });
}

void NodeIdWizard::reconnect() {
    CanBus* bus = workspace_->bus();
    if (!bus) return finish(false, tr("The connection is gone before reconnecting."));
    const QString url = sim::urlAtBitRate(*bus, plan_->reconnectBitRate, &keepNetwork_);
    emit progress(tr("Reconnecting at %1 (%2)…").arg(bitRateText(plan_->reconnectBitRate), url));
    const int reconnectStep = static_cast<int>(plan_->beforeReconnect.steps.size());
    preview()->markRunning(reconnectStep);
    reconnecting_ = true;
    changer_.reset();  // it belongs to the old connection's services
    changerFor_ = nullptr;
    workspace_->disconnectBus();
    QString error;
    if (!workspace_->connectBus(url, &error)) {
        reconnecting_ = false;
        return finish(
            false,
            tr("Could not reconnect at %1: %2\n%3").arg(bitRateText(plan_->reconnectBitRate), error, plan_->recovery));
    }
    auto* timer = new QTimer(this);
    auto waited = std::make_shared<int>(0);
    timer->setInterval(50);
    connect(timer, &QTimer::timeout, this, [this, timer, waited] {
        *waited += 50;
        if (workspace_->canTransmit()) {
            timer->deleteLater();
            reconnecting_ = false;
            preview()->markStep(static_cast<int>(plan_->beforeReconnect.steps.size()), true,
                                tr("connected at %1").arg(bitRateText(plan_->reconnectBitRate)));
            runPart(1);
        } else if (*waited > 10000) {
            timer->deleteLater();
            reconnecting_ = false;
            finish(false,
                   tr("The bus did not open at %1.\n%2").arg(bitRateText(plan_->reconnectBitRate), plan_->recovery));
        }
    });
    timer->start();
}

void NodeIdWizard::followChange(int from, int to) {
    canopen::NodeTable& nodes = workspace_->nodes();
    if (from >= 1 && from <= 127 && from != to) {
        nodes.moveNode(from, to);
        workspace_->events().forgetNode(from);  // its heartbeats come from `to` now
        workspace_->events().add(renderedEvent(TraceEvent::Kind::Info, nowNs(), kNoFrame, to, [from, to] {
            return tr("Node %1 now answers at node-ID %2 (Baud rate and node-ID wizard)").arg(from).arg(to);
        }));
        workspace_->syncDictionaries();
    }
    // Ask the device at its new ID (or rate) who it is (1018h): confirms the entry, and gives a
    // device that had no node-ID its dictionary.
    if (!workspace_->sdo() || !workspace_->canTransmit()) return;
    auto* identify = new NodeScanner(workspace_->sdo(), workspace_);
    connect(workspace_, &Workspace::sourceChanged, identify, &QObject::deleteLater);
    connect(identify, &NodeScanner::finished, workspace_, [ws = workspace_, identify] {
        ws->syncDictionaries();
        identify->deleteLater();
    });
    identify->scan(to, to, 1000);
}

void NodeIdWizard::finish(bool ok, const QString& text) {
    running_ = false;
    outcome_ = ok ? Outcome::Succeeded : Outcome::Failed;
    outcomeText_ = text;
    if (ok && plan_) {
        followChange(plan_->request.change == Change::NodeId ? plan_->request.node : plan_->finalNodeId,
                     plan_->finalNodeId);
        if (plan_->request.change == Change::NodeId) {
            request_.node = plan_->finalNodeId;
            plan_->request.node = plan_->finalNodeId;
        }
    }
    emit progress(text);
    emit finished(ok);
}

}  // namespace coscope::gui
