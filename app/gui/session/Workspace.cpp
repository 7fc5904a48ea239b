// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/session/Workspace.h"
#include "app/gui/language/CoreText.h"

#include "app/gui/session/MemoryBudget.h"
#include "core/can/BusInterfaceName.h"
#include "core/canopen/BusMaster.h"
#include "core/canopen/DriveDisable.h"
#include "core/canopen/GuardedDrives.h"
#include "core/canopen/HeartbeatMonitor.h"
#include "core/canopen/MasterContext.h"
#include "core/canopen/SdoClient.h"
#include "core/logio/LogProbe.h"
#include "core/trace/JournalFolder.h"

#include <QFileInfo>
#include <QSettings>

#include <map>

#include <spdlog/spdlog.h>

namespace coscope::gui {

namespace {
const QString kRawKey = QStringLiteral("plot/rawSignals");
constexpr int kDisableWaitMs = 500;  // for the Disable frames' copies before a bus closes
}  // namespace

Workspace::Workspace(QObject* parent)
    : QObject(parent), traceDecoder_(std::make_shared<TraceDecoder>()), decoder_(traceDecoder_),
      store_(std::make_shared<TraceStore>()), signals_(std::make_shared<dissect::SignalRecorder>()), events_(decoder_) {
    traceDecoder_->setStore(store_);
    for (const QString& spec : QSettings().value(kRawKey).toStringList())
        if (const auto r = dissect::RawSignal::parse(spec)) raw_.push_back(*r);
    signals_->setRawSignals(raw_);
}

Workspace::~Workspace() { reset(); }

void Workspace::reset() {
    replay_.reset();  // cancels and joins
    recordedNames_.clear();
    logRecorded_ = false;
    rawAddedWhileLoading_ = false;
    if (loadJob_) {
        loadJob_->cancel();
        loadJob_->wait();
    }
    loadJob_.reset();
    if (bus_) emit aboutToDisconnect();
    closeMaster();
    if (bus_) bus_->close();
    if (session_) session_->stop();
    session_.reset();
    closeJournal();
    journalPath_.clear();
    master_.reset();
    if (bus_) bus_->disconnect(this);
    bus_.reset();
    nodes_.clear();
    events_.clear();
    health_.clear();
    store_ = std::make_shared<TraceStore>();
    signals_ = std::make_shared<dissect::SignalRecorder>();
    signals_->setRawSignals(raw_);
    traceDecoder_->setStore(store_);
    syncedNodesRevision_ = ~uint64_t{0};
    reportedDropped_ = reportedErrors_ = 0;
    lostSinceNs_ = 0;
    sourceName_.clear();
}

// The plot feed holds its own reference to the recorder of this source: a consumer never
// outlives its session or load job, and reset() replaces the recorder only after stopping them.
// A log being opened hands its frames to the Health monitor's low-priority thread (issue 19:
// the trace's index, filters and plots first); a live capture analyses them as they come.
std::vector<CaptureSession::Consumer> Workspace::analysisConsumers(bool healthLater) {
    std::vector<CaptureSession::Consumer> out{
        [this](const TraceStore& s, FrameNo first, size_t count) { nodes_.consume(s, first, count); },
        [this](const TraceStore& s, FrameNo first, size_t count) { events_.consume(s, first, count); },
        [rec = signals_](const TraceStore& s, FrameNo first, size_t count) { rec->consume(s, first, count); }};
    if (healthLater)
        out.push_back(
            [this, store = std::shared_ptr<const TraceStore>(store_)](const TraceStore&, FrameNo first, size_t count) {
                health_.consumeLater(store, first, count);
            });
    else out.push_back([this](const TraceStore& s, FrameNo first, size_t count) { health_.consume(s, first, count); });
    return out;
}

bool Workspace::connectBus(const QString& url, QString* error) {
    QString why;
    auto bus = createBus(url, &why);
    if (!bus) {
        if (error) *error = why;
        return false;
    }
    reset();
    bus_ = std::move(bus);
    sourceName_ = bus_->url().toString();
    connect(bus_.get(), &CanBus::stateChanged, this, [this](CanBus::State s) {
        if (s == CanBus::State::Error && bus_)
            events_.add(renderedEvent(TraceEvent::Kind::BusError, nowNs(), kNoFrame, -1,
                                      [why = bus_->errorString()] { return coreText(why); }));
        if (bus_) noteLostAdapter(s);
        emit busStateChanged(s);
    });
    connect(bus_.get(), &CanBus::errorOccurred, this, &Workspace::errorOccurred);
    session_ = std::make_unique<CaptureSession>(store_);
    openJournal();
    if (journal_) {
        // Bounded memory: frames beyond the budget are paged back from the journal.
        store_->setPager(journal_->pager());
        store_->setMemoryBudget(traceMemoryBudget());
        session_->addConsumer([j = journal_.get()](const TraceStore& s, FrameNo first, size_t count) {
            j->appendFromStore(s, first, count);
        });
    }
    master_ = std::make_unique<canopen::MasterContext>(bus_.get(), &nodes_);
    for (auto& c : analysisConsumers(false)) session_->addConsumer(std::move(c));
    session_->addConsumer(master_->dispatcher().consumer());
    sdo_ = std::make_unique<canopen::SdoClient>(*master_);
    busMaster_ = std::make_unique<canopen::BusMaster>(*master_);
    guards_ = std::make_unique<canopen::GuardedDrives>(*master_, *sdo_, busMaster_->heartbeat());
    watchErrorControl();
    session_->start(bus_.get());
    spdlog::info("connecting to {}", sourceName_.toStdString());
    bus_->open();
    emit sourceChanged();
    return true;
}

// Issue 16 "Lost adapter": the trace keeps everything; the gap goes into the store (marked on the
// first frame after it, never dispatched as a frame), the Events and the node table.
void Workspace::noteLostAdapter(CanBus::State s) {
    if (s == CanBus::State::Lost && lostSinceNs_ == 0) {
        lostSinceNs_ = bus_->lostSinceNs() ? bus_->lostSinceNs() : nowNs();
        const FrameNo from = static_cast<FrameNo>(store_->size());
        nodes_.markGap(from);
        events_.add(renderedEvent(TraceEvent::Kind::BusError, lostSinceNs_, kNoFrame, -1, [why = bus_->errorString()] {
            return tr("Bus lost: %1. Retrying with back-off; node states are unknown until their next heartbeat.")
                .arg(coreText(why));
        }));
        spdlog::warn("bus {} lost: {}", sourceName_.toStdString(), bus_->errorString().toStdString());
    } else if (s == CanBus::State::Open && lostSinceNs_ != 0) {
        const int64_t back = nowNs();
        const FrameNo first = static_cast<FrameNo>(store_->size());
        store_->addGap({first, lostSinceNs_, back});
        if (journal_) journal_->addGap({first, lostSinceNs_, back});  // a reopened journal shows it again
        events_.restartHeartbeatWaits(back);
        events_.add(renderedEvent(TraceEvent::Kind::Info, back, first, -1, [s = double(back - lostSinceNs_) / 1e9] {
            return tr("Bus back after %1 s: frames between are missing from the trace").arg(s, 0, 'f', 1);
        }));
        spdlog::info("bus {} back after {:.1f} s", sourceName_.toStdString(), double(back - lostSinceNs_) / 1e9);
        lostSinceNs_ = 0;
    }
}

void Workspace::disconnectBus() {
    if (!bus_) return;
    // Last chance for whoever drives a device (the CiA 402 wizard disables its drive): the
    // bus and the SDO client are still there.
    emit aboutToDisconnect();
    // Keep the trace: stop the bus and the ingest thread, leave the store for review.
    closeMaster();
    bus_->close();
    lostSinceNs_ = 0;
    if (session_) session_->stop();
    session_.reset();
    closeJournal();
    master_.reset();
    bus_->disconnect(this);
    bus_.reset();
    // The capture is complete: a dictionary assigned from now on records its signals again.
    logRecorded_ = true;
    recordedNames_.clear();
    for (const canopen::NodeInfo& n : nodes_.snapshot())
        if (!n.dictionary.isEmpty()) recordedNames_.emplace(n.node, n.dictionary);
    sourceName_ += QStringLiteral(" (disconnected)");
    emit busStateChanged(CanBus::State::Closed);
    emit sourceChanged();
}

// The heartbeat consumer / node guarding the user sets per node (Nodes dock): its findings in
// the node table, its losses and returns in the Events.
void Workspace::watchErrorControl() {
    monitor_ = std::make_unique<canopen::HeartbeatMonitor>(*master_);
    monitor_->setTableFedByTrace(true);
    canopen::HeartbeatMonitor* m = monitor_.get();
    connect(m, &canopen::HeartbeatMonitor::nodeChanged, this, [this, m](int node) {
        events_.setWatched(node,
                           m->watch(static_cast<uint8_t>(node)).status != canopen::ErrorControlWatch::Status::Off);
    });
    connect(m, &canopen::HeartbeatMonitor::nodeLost, this, [this, m](int node) {
        const canopen::ErrorControlWatch w = m->watch(static_cast<uint8_t>(node));
        events_.add(renderedEvent(TraceEvent::Kind::HeartbeatTimeout, nowNs(), kNoFrame, node, [w] {
            return w.guarding()
                       ? tr("Node guarding lost: no answer within the node life time of %1 ms (guard time %2 ms × %3)")
                             .arg(w.guardTimeMs * w.lifeTimeFactor)
                             .arg(w.guardTimeMs)
                             .arg(w.lifeTimeFactor)
                       : tr("Heartbeat lost: none within the consumer time of %1 ms").arg(w.consumerTimeMs);
        }));
    });
    connect(m, &canopen::HeartbeatMonitor::nodeBack, this, [this, m](int node) {
        const bool guarding = m->watch(static_cast<uint8_t>(node)).guarding();
        events_.add(renderedEvent(TraceEvent::Kind::Info, nowNs(), kNoFrame, node, [guarding] {
            return guarding ? tr("Node guarding answers again") : tr("Heartbeat back");
        }));
    });
    connect(m, &canopen::HeartbeatMonitor::guardingError, this, [this](int node, const QString& what) {
        events_.add(renderedEvent(TraceEvent::Kind::HeartbeatTimeout, nowNs(), kNoFrame, node,
                                  [what] { return coreText(what); }));
    });
}

void Workspace::closeMaster() {
    monitor_.reset();  // its guarding requests stop
    std::vector<canopen::GuardedDrives::PutBack> putBack =
        guards_ ? guards_->takePutBack() : std::vector<canopen::GuardedDrives::PutBack>{};
    guards_.reset();
    // Nothing periodic may counter the Disable (a transmit row with a controlword, process data
    // with each SYNC); CoScope's heartbeat goes on while drives watch it.
    if (busMaster_) {
        busMaster_->sync().stop();
        busMaster_->transmit().stopAll();
    }
    sdo_.reset();
    const canopen::DriveDisableOutcome disabled = disableEnabledDrives();
    if (master_ && !putBack.empty()) {
        for (const canopen::PutBackOutcome& o :
             canopen::putBackDirect(*master_, std::move(putBack), disabled, kDisableWaitMs)) {
            const int node = o.node;
            const bool ok = o.putBack;
            events_.add(renderedEvent(ok ? TraceEvent::Kind::Info : TraceEvent::Kind::BusError, nowNs(), kNoFrame, node,
                                      [text = o.text] { return coreText(text); }));
            if (!ok) emit errorOccurred(coreText(o.text));
        }
    }
    busMaster_.reset();  // CoScope's heartbeat stops last, before the bus closes
}

// The frames go straight on the bus and the wait is bounded (500 ms): nothing of the window's
// (no SDO client, no event loop) is needed, so it also runs from the destructor.
canopen::DriveDisableOutcome Workspace::disableEnabledDrives() {
    if (!master_ || master_->enabledDrives().isEmpty()) return {};
    canopen::DriveDisableOutcome outcome = canopen::disableEnabledDrives(*master_, kDisableWaitMs);
    for (const auto& d : outcome.drives) {
        const int node = d.drive.node, axis = d.drive.axis;
        auto name = [node, axis] { return axis ? tr("node %1 axis %2").arg(node).arg(axis) : tr("node %1").arg(node); };
        if (d.seen) {
            events_.add(renderedEvent(TraceEvent::Kind::Info, nowNs(), kNoFrame, node, [name] {
                return tr("Disable voltage (6040h = 0000h) sent to %1 before the bus closed, and seen on the bus")
                    .arg(name());
            }));
            continue;
        }
        auto text = [name, why = d.error] {
            return tr("%1 may still be enabled: its Disable voltage (6040h = 0000h) was not seen on the bus before it "
                      "closed (%2). Check the drive.")
                .arg(name(), coreText(why));
        };
        events_.add(renderedEvent(TraceEvent::Kind::BusError, nowNs(), kNoFrame, node, text));
        emit errorOccurred(text());
    }
    return outcome;
}

QString Workspace::journalFolder() const { return journals::defaultFolder(); }

void Workspace::setTimeMode(TimeBase::Mode mode) {
    if (mode == timeMode_) return;
    timeMode_ = mode;
    emit timeModeChanged();
}

void Workspace::applyMemoryBudget() {
    if (store_->memoryBudget() != 0) store_->setMemoryBudget(traceMemoryBudget());
}

void Workspace::openJournal() {
    journalPath_ = journals::newJournalPath(journalFolder(), sourceName_);
    auto journal = std::make_unique<CaptureJournal>();
    if (journalPath_.isEmpty() || !journal->open(journalPath_, {busInterfaceName(bus_->url())})) {
        const QString why =
            journalPath_.isEmpty() ? tr("cannot create the folder %1").arg(journalFolder()) : journal->errorString();
        spdlog::warn("no capture journal: {}", why.toStdString());
        journalPath_.clear();
        emit errorOccurred(tr("The capture is not journaled to disk (%1); it is kept in memory only").arg(why));
        return;
    }
    journal_ = std::move(journal);
}

void Workspace::closeJournal() {
    if (!journal_) return;
    journal_->close();
    journal_.reset();
}

namespace {
// Why a file was not opened, naming it and where it failed (line or record numbers).
QString probeErrorText(const QString& path, const logio::LogProbe& probe) {
    if (!probe.error.isEmpty()) return probe.error;
    // Recognised by no format, only guessed by the file's name: say so rather than blame the
    // guessed format's syntax (issue 37).
    QStringList lines{
        probe.formatByName
            ? Workspace::tr("%1: not a format CoScope reads (tried candump, Vector ASC and BLF, PEAK TRC, pcap/pcapng, "
                            "CoScope CSV, "
                            "SavvyCAN GVRET, BUSMASTER, IXXAT, Kvaser and ASAM MDF4); read as %2 by its name, no CAN "
                            "frame was found")
                  .arg(QFileInfo(path).fileName(), probe.format)
            : Workspace::tr("%1: no CAN frame found (read as %2)").arg(QFileInfo(path).fileName(), probe.format)};
    for (const auto& d : probe.problems) lines << Workspace::tr("line %1: %2").arg(d.where).arg(d.message);
    return lines.join(u'\n');
}
}  // namespace

bool Workspace::openLog(const QString& path, QString* error) {
    if (!QFileInfo(path).isReadable()) {
        if (error) *error = tr("%1: cannot read the file").arg(path);
        return false;
    }
    // Nothing is thrown away for a file that cannot be read as a log at all: the trace, nodes
    // and signals shown stay until the new file's format, header and first frames are known good.
    const logio::LogProbe probe = logio::probeLog(path);
    if (!probe.usable) {
        if (error) *error = probeErrorText(path, probe);
        return false;
    }
    reset();
    sourceName_ = QFileInfo(path).fileName();
    // A gap recorded in the log (a journal of a capture whose adapter was lost): the node states
    // become unknown from there, as they did live, and the Events say so.
    auto onGap = [this](const TraceStore::Gap& g) {
        nodes_.markGap(g.firstFrame);
        events_.add(
            renderedEvent(TraceEvent::Kind::Info, g.backNs, g.firstFrame, -1, [s = double(g.backNs - g.lostNs) / 1e9] {
                return tr("Bus back after %1 s: frames between are missing from the trace").arg(s, 0, 'f', 1);
            }));
    };
    loadJob_ = std::make_unique<LogLoadJob>(path, store_, analysisConsumers(true), onGap);
    // Bounded memory: a large log pages from a spill journal beside the capture journals.
    loadJob_->setSpill(journalFolder() + QStringLiteral("/opened"), traceMemoryBudget());
    loadJob_->start();
    emit sourceChanged();
    return true;
}

void Workspace::clear() {
    reset();
    emit sourceChanged();
}

canopen::SyncProducer* Workspace::syncProducer() const { return busMaster_ ? &busMaster_->sync() : nullptr; }
canopen::HeartbeatProducer* Workspace::heartbeatProducer() const {
    return busMaster_ ? &busMaster_->heartbeat() : nullptr;
}

bool Workspace::canTransmit() const { return bus_ && bus_->state() == CanBus::State::Open && !bus_->isListenOnly(); }

QStringList Workspace::busNames() const {
    if (loadJob_) return loadJob_->busNames();
    if (bus_) return {bus_->url().target.isEmpty() ? bus_->url().scheme : bus_->url().target};
    return {};
}

void Workspace::syncDictionaries() {
    const uint64_t rev = nodes_.revision();
    if (rev == syncedNodesRevision_) return;
    syncedNodesRevision_ = rev;
    std::map<int, QString> names;
    for (const canopen::NodeInfo& n : nodes_.snapshot())
        if (!n.dictionary.isEmpty()) names.emplace(n.node, n.dictionary);
    traceDecoder_->setDictionaries(names);
    signals_->setDictionaries(names);
    // A log already read: its PDOs are decoded again with the dictionaries assigned since.
    if (!bus_ && logRecorded_ && names != recordedNames_) replaySignals(names);
}

void Workspace::replaySignals(const std::map<int, QString>& names) {
    recordedNames_ = names;
    replay_ = std::make_unique<SignalReplayJob>(store_, names, raw_);
    replay_->start();
}

dissect::SignalKey Workspace::addRawSignal(const dissect::RawSignal& signal) {
    raw_.push_back(signal);
    QStringList specs;
    for (const dissect::RawSignal& r : raw_) specs << r.spec();
    QSettings().setValue(kRawKey, specs);
    signals_->setRawSignals(raw_);
    // A trace already recorded (a log read, a capture ended): record it again with the signal.
    if (!bus_ && logRecorded_) replaySignals(recordedNames_);
    else if (!bus_ && loadJob_) rawAddedWhileLoading_ = true;
    dissect::SignalKey key;
    key.raw = static_cast<uint16_t>(raw_.size());
    return key;
}

void Workspace::poll() {
    if (loadJob_ && loadJob_->isDone() && !logRecorded_) {
        // The names the loader's recorder used (it applies them before each batch).
        logRecorded_ = true;
        syncDictionaries();
        std::map<int, QString> names;
        for (const canopen::NodeInfo& n : nodes_.snapshot())
            if (!n.dictionary.isEmpty()) names.emplace(n.node, n.dictionary);
        recordedNames_ = names;
        if (rawAddedWhileLoading_) replaySignals(names);
        rawAddedWhileLoading_ = false;
    }
    if (replay_ && replay_->isDone()) {
        if (!replay_->isCancelled()) signals_ = replay_->recorder();
        replay_.reset();
    }
    syncDictionaries();
    // Bounded memory: re-applying the budget evicts chunks the journal has written since the
    // last new chunk (a capture faster than the journal, or one that just ended).
    if (const size_t budget = store_->memoryBudget()) store_->setMemoryBudget(budget);
    if (!bus_) return;
    if (journal_ && journal_->hasError()) {
        // The disk is full or gone: stop here rather than capture what could not be kept.
        const QString message =
            tr("Capture stopped: cannot write the capture journal %1 (%2). The trace keeps the %L3 frames received.")
                .arg(journal_->path(), journal_->errorString())
                .arg(store_->size());
        events_.add(renderedEvent(TraceEvent::Kind::BusError, nowNs(), kNoFrame, -1,
                                  [path = journal_->path(), why = journal_->errorString(), frames = store_->size()] {
                                      return tr("Capture stopped: cannot write the capture journal %1 (%2). The trace "
                                                "keeps the %L3 frames received.")
                                          .arg(path, coreText(why))
                                          .arg(frames);
                                  }));
        disconnectBus();
        emit captureStopped(message);
        return;
    }
    // While the adapter is lost no heartbeat can arrive: no timeouts then (noise, issue 16).
    if (lostSinceNs_ == 0) events_.checkHeartbeats(nowNs());
    const auto c = bus_->counters();
    if (c.dropped > reportedDropped_) {
        events_.add(renderedEvent(
            TraceEvent::Kind::Dropped, nowNs(), kNoFrame, -1, [now = c.dropped - reportedDropped_, total = c.dropped] {
                return tr("%n frame(s) dropped (receive queue full), %1 in total", nullptr, static_cast<int>(now))
                    .arg(total);
            }));
        reportedDropped_ = c.dropped;
    }
    reportedErrors_ = c.errors;
}

}  // namespace coscope::gui
