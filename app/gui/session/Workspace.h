// SPDX-License-Identifier: GPL-3.0-or-later
// Folder app/gui/session/ owns what the window works on: the Workspace (bus or log, trace store,
// node table, master services), background jobs and the simulation demo. No widgets.
#pragma once

#include "app/gui/events/EventLog.h"
#include "app/gui/health/HealthMonitor.h"
#include "app/gui/plot/SignalReplayJob.h"
#include "app/gui/trace/FrameDecoder.h"
#include "app/gui/trace/LogLoadJob.h"
#include "app/gui/trace/TraceDecoder.h"
#include "core/can/CanBus.h"
#include "core/canopen/DriveDisable.h"
#include "core/canopen/NodeTable.h"
#include "core/trace/CaptureJournal.h"
#include "core/trace/CaptureSession.h"
#include "core/trace/TimeBase.h"
#include "dissectors/SignalRecorder.h"

#include <QObject>
#include <QStringList>

#include <memory>

namespace coscope::canopen {
class BusMaster;
class GuardedDrives;
class HeartbeatMonitor;
class HeartbeatProducer;
class MasterContext;
class SdoClient;
class SyncProducer;
}  // namespace coscope::canopen

namespace coscope::gui {

// What the window is looking at: one trace store, filled either live from a bus (through a
// CaptureSession whose ingest thread also feeds the node table, the event log and the master
// services' dispatcher) or from a log file (through a LogLoadJob). No widgets: the docks read
// it. It signals only when the source changes (views rebind) and for bus state and errors.
class Workspace : public QObject {
    Q_OBJECT
public:
    explicit Workspace(QObject* parent = nullptr);
    ~Workspace() override;

    // Creates and opens the bus; false with a one-line reason when the URL is unusable.
    // Opening itself is asynchronous: see busStateChanged / errorOccurred.
    bool connectBus(const QString& url, QString* error);
    void disconnectBus();
    // Starts loading a log file; progress via loadJob(). A file that cannot be read as a log
    // (unknown format, bad header, no frame but bad lines in its first part) is refused with the
    // reason, naming the file and the lines, and what is shown stays (logio::probeLog).
    bool openLog(const QString& path, QString* error);
    // Empty trace, no source.
    void clear();

    const std::shared_ptr<TraceStore>& store() const { return store_; }
    canopen::NodeTable& nodes() { return nodes_; }
    EventLog& events() { return events_; }
    const HealthMonitor& health() const { return health_; }
    const std::shared_ptr<const FrameDecoder>& decoder() const { return decoder_; }
    TraceDecoder& traceDecoder() { return *traceDecoder_; }
    // The plot's signal buffers, fed on the ingest thread (live or log loading); replaced with
    // the store when the source changes, and for a log once it was recorded again with the
    // dictionaries assigned after it was read (SignalReplayJob).
    const std::shared_ptr<dissect::SignalRecorder>& signalRecorder() const { return signals_; }

    CanBus* bus() const { return bus_.get(); }
    bool isLive() const { return bus_ != nullptr; }
    bool canTransmit() const;  // a bus is open and not listen-only
    canopen::MasterContext* master() const { return master_.get(); }
    canopen::SdoClient* sdo() const { return sdo_.get(); }
    // The master services of the open bus (SYNC, CoScope's heartbeat, the transmit list), or
    // null: they stop before the bus closes.
    canopen::BusMaster* busMaster() const { return busMaster_.get(); }
    canopen::SyncProducer* syncProducer() const;
    canopen::HeartbeatProducer* heartbeatProducer() const;
    // The drives CoScope enabled on the open bus, each watching CoScope's heartbeat with the
    // user's consent (1016h/6007h), or null. When the bus closes, whatever closes it: the drives
    // are disabled, then their old 1016h/6007h put back, then the heartbeat stops, then the bus
    // closes (closeMaster()).
    canopen::GuardedDrives* guardedDrives() const { return guards_.get(); }
    // CoScope's heartbeat consumer and node guarding of the open bus (the times the user set
    // per node in the Nodes dock), writing into nodes(); its losses go to the Events. Null
    // without a bus.
    canopen::HeartbeatMonitor* heartbeatMonitor() const { return monitor_.get(); }
    LogLoadJob* loadJob() const { return loadJob_.get(); }

    // The capture journal of the live capture (DESIGN.md "Reliability"): every frame of a bus
    // connection is written to a pcapng file in journalFolder() as it arrives. Null when no bus
    // is connected or the journal could not be made (then the capture runs without one, and
    // errorOccurred said so). A write error stops the capture; the trace keeps its frames.
    const CaptureJournal* journal() const { return journal_.get(); }
    QString journalPath() const { return journalPath_; }  // the last capture's, kept after disconnect
    QString journalFolder() const;
    // The trace memory budget setting (MemoryBudget.h) changed: applied at once to a trace paged
    // from its journal (a live capture, or one just ended); the next capture uses it anyway.
    void applyMemoryBudget();

    QString sourceName() const { return sourceName_; }
    // How every view shows a time (TimeBase): seconds since the first frame, or the wall clock.
    // The Trace dock's time mode chooses it; the Events, Health and Plot docks follow.
    TimeBase::Mode timeMode() const { return timeMode_; }
    void setTimeMode(TimeBase::Mode mode);
    QStringList busNames() const;

    // The user's raw signals (RawSignal.h), kept with the workspace (settings "plot/rawSignals",
    // their command-line specs) and recorded for every source; a log already read is recorded
    // again. Signal n has SignalKey::raw n + 1.
    const std::vector<dissect::RawSignal>& rawSignals() const { return raw_; }
    dissect::SignalKey addRawSignal(const dissect::RawSignal& signal);

    // Hands the node table's dictionaries (matched or assigned) to the trace decoder.
    void syncDictionaries();
    // Called by the window's refresh timer: heartbeat timeouts, dropped-frame and error counts,
    // dictionaries for the decoder.
    void poll();

signals:
    void timeModeChanged();
    // Emitted while the bus and the SDO client still work, just before they are closed
    // (disconnect, another connection, opening a log, the workspace going away). Then the
    // drives CoScope left enabled are sent Disable voltage, seen going out before the bus closes.
    void aboutToDisconnect();
    void sourceChanged();
    void busStateChanged(coscope::CanBus::State state);
    void errorOccurred(const QString& message);
    // The capture ended on its own (the journal could not be written); the trace is kept.
    void captureStopped(const QString& message);

private:
    void reset();
    // Before the bus closes, whatever closes it: the last word to each drive CoScope enabled
    // (canopen::disableEnabledDrives), after the SDO client is gone; said in the log, the Events
    // and, when a Disable was not seen on the bus, as an error.
    canopen::DriveDisableOutcome disableEnabledDrives();
    // The master services' end, in this order: no more guarding, SYNC and periodic transmits
    // stop, the SDO client goes, the drives CoScope enabled are disabled, the guards' old values
    // are put back (a drive whose Disable was not confirmed keeps watching, and stops by itself
    // when the heartbeat stops), then CoScope's heartbeat stops. The bus is still open.
    void closeMaster();
    void watchErrorControl();
    void openJournal();
    void closeJournal();
    void noteLostAdapter(CanBus::State state);
    void replaySignals(const std::map<int, QString>& names);
    std::vector<CaptureSession::Consumer> analysisConsumers(bool healthLater);

    std::shared_ptr<TraceDecoder> traceDecoder_;
    std::shared_ptr<const FrameDecoder> decoder_;
    std::shared_ptr<TraceStore> store_;
    std::shared_ptr<dissect::SignalRecorder> signals_;
    canopen::NodeTable nodes_;
    EventLog events_;
    HealthMonitor health_;
    std::unique_ptr<CanBus> bus_;
    std::unique_ptr<CaptureJournal> journal_;  // outlives session_ (its consumer)
    std::unique_ptr<CaptureSession> session_;
    std::unique_ptr<canopen::MasterContext> master_;
    std::unique_ptr<canopen::SdoClient> sdo_;
    std::unique_ptr<canopen::BusMaster> busMaster_;
    std::unique_ptr<canopen::GuardedDrives> guards_;
    std::unique_ptr<canopen::HeartbeatMonitor> monitor_;
    std::unique_ptr<LogLoadJob> loadJob_;
    QString sourceName_;
    TimeBase::Mode timeMode_ = TimeBase::Mode::Relative;
    QString journalPath_;
    uint64_t reportedDropped_ = 0;
    uint64_t reportedErrors_ = 0;
    int64_t lostSinceNs_ = 0;  // the bus is Lost since (0 = not lost)
    uint64_t syncedNodesRevision_ = 0;
    std::map<int, QString> recordedNames_;  // the dictionaries a finished trace's signals were recorded with
    bool logRecorded_ = false;              // a log read in full or a capture ended: recordedNames_ holds
    std::unique_ptr<SignalReplayJob> replay_;
    std::vector<dissect::RawSignal> raw_;
    bool rawAddedWhileLoading_ = false;  // the frames read before it need recording again
};

}  // namespace coscope::gui
