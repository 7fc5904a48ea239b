// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/canopen/MasterContext.h"
#include "core/canopen/PeriodicSender.h"
#include "core/canopen/RpdoMotion.h"
#include "core/canopen/SyncProducer.h"

#include <QObject>
#include <QString>

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <set>
#include <vector>

class QTimer;

namespace coscope::canopen {

class SdoClient;

// One mapped object of an RPDO: where it sits in the frame and how its value is read.
struct ProcessDataObject {
    PdoMapEntry entry;
    int bitOffset = 0;      // from bit 0 of byte 0 (CiA 301 §7.5.2.36: entries in mapping order)
    bool isSigned = false;  // from the dictionary's data type
    bool dummy = false;     // 0001h..0007h: a gap, always 0 (CiA 301 §7.4.7.1)
    bool motion = false;    // isMotionObject (RpdoMotion.h)
    QString name;           // from the dictionary ("" = not described)
};

// One RPDO of the node with the values to send in it.
struct ProcessDataPdo {
    RpdoLayout layout;
    std::vector<ProcessDataObject> objects;
    bool carriesMotion() const;
    int bytes() const;  // frame length: the mapped bits rounded up to bytes
};

// Packs `values` (one raw value per object, two's complement for signed ones) into the RPDO's
// frame: each value LSB first at its bit offset, in its mapped length (CiA 301 §7.2.2 and
// §7.5.2.36). The frame's id is the RPDO's COB-ID.
CanFrame composeRpdo(const ProcessDataPdo& pdo, const std::vector<int64_t>& values);

// The values an RPDO carries while "hold to run" is not held: the targets that make a drive move
// go to 0 (60FFh, 6071h, 6042h, 60B1h, 60B2h) and the controlword gets Halt (bit 8, CiA 402-2
// §6.3.1), so the drive brakes to a stop; positions (607Ah, 60B0h, 60C1h) are kept, since a new
// position of 0 would be a move of its own; everything else is kept as set.
std::vector<int64_t> stoppedValues(const ProcessDataPdo& pdo, const std::vector<int64_t>& values);

// Process data (issue 35): the RPDOs of one node by name, with a value per mapped object, sent
// once, on change, every N ms (a job of the bus's PeriodicSender) or right after each SYNC the
// bus's SyncProducer sends (its one setOnEachSync hook). One per bus, beside the other master services.
//
// Hold to run: an RPDO that carries a motion object (isMotionObject) goes out with its values
// only while feedHold() is called at least every kHoldWatchdogMs; when it is not (released, the
// GUI thread stalled, the CLI ended) the RPDO is sent once more with stoppedValues() and its
// periodic sending stops until the hold is fed again. The watchdog is checked on the owner's
// thread and on the sender thread, so neither can keep a motor running alone.
//
// Thread-safety: use from one thread (the owner's); the sends run on the PeriodicSender's thread.
class ProcessData : public QObject {
    Q_OBJECT
public:
    enum class Mode : uint8_t { Once, OnChange, Every, WithSync };
    static constexpr int kHoldWatchdogMs = 400;

    ProcessData(MasterContext& context, SyncProducer& sync, QObject* parent = nullptr);
    ~ProcessData() override;  // stop()

    // The node whose RPDOs are sent, laid out from its dictionary's 140xh/160xh (rpdoLayout);
    // values start at 0. Stops what was being sent first. False with *error when the dictionary
    // describes no valid mapped RPDO.
    bool setNode(uint8_t node, const od::ObjectDictionary& dictionary, QString* error = nullptr);
    uint8_t node() const { return node_; }
    const std::vector<ProcessDataPdo>& pdos() const { return pdos_; }
    const ProcessDataPdo* pdo(int number) const;

    // Which RPDOs are sent (all after setNode).
    void setEnabled(int number, bool enabled);
    bool isEnabled(int number) const;

    // The value of a mapped object (in every RPDO that maps it), raw in the object's units.
    // False with *error when no RPDO maps it or the value does not fit its mapped length. In
    // OnChange mode while running, the RPDOs that carry it go out at once.
    bool setValue(uint16_t index, uint8_t sub, int64_t value, QString* error = nullptr);
    std::optional<int64_t> value(uint16_t index, uint8_t sub) const;
    // setValue() from text as people write it: decimal, "0x1F" or "1Fh" (hex of a signed object
    // is its bit pattern in the mapped length: 0xFFFFFFFE is -2 for an INTEGER32).
    bool setValueText(uint16_t index, uint8_t sub, const QString& text, QString* error = nullptr);
    // The same reading without setting: the raw value for `object`, nullopt with *error.
    static std::optional<int64_t> parseValue(const ProcessDataObject& object, const QString& text,
                                             QString* error = nullptr);
    // The mapped object index:sub (non-dummy), null when no RPDO of the node maps it.
    const ProcessDataObject* object(uint16_t index, uint8_t sub) const;
    // Reads every mapped object's value from the node over SDO (so that a first send repeats what
    // the drive has); `done` gets the objects that could not be read ("6060h:00: ..."), once
    // (not at all when this ProcessData is destroyed first; a read for a node replaced by setNode
    // stops and reports it as not read).
    void readValues(SdoClient& sdo, std::function<void(const QStringList& failures)> done);

    // The frame of RPDO `number` with the values set (held = true) or as sent while not held.
    CanFrame frame(int number, bool held = true) const;

    void setMode(Mode mode, int periodMs = 0);  // while running: restarts in the new mode
    Mode mode() const { return mode_; }
    int periodMs() const { return periodMs_; }
    // Sends in the mode set: Once sends each enabled RPDO now; the others keep sending until
    // stop(). RPDOs with motion go out only while held (feedHold). False with *error when nothing
    // can be sent (no node, listen-only or closed bus).
    bool start(QString* error = nullptr);
    // Stops sending; an RPDO with motion whose values went out is sent once with stoppedValues().
    void stop();
    bool isRunning() const { return running_; }

    // The hold-to-run control is held: feeds the watchdog. The first feed of a hold sends the
    // enabled RPDOs with motion at once (Once, OnChange) or starts their periodic job (Every).
    void feedHold();
    // Released: the RPDOs with motion are sent once with stoppedValues().
    void releaseHold();
    bool isHeld() const;

    // Frames that went out since setNode (all RPDOs), and the last send error.
    uint64_t sent() const;
    QString lastError() const;

signals:
    // The watchdog ended a hold that was not released (not fed for kHoldWatchdogMs).
    void holdExpired();
    // A send failed (on the owner's thread).
    void sendFailed(const QString& message);

private:
    struct Shared;
    void stopJobs(bool motionOnly);
    void startJob(size_t i);
    bool sendNow(size_t i, QString* error);
    // Notes a controlword value that enables voltage in the bus's EnabledDrives.
    void noteIfEnabling(const ProcessDataObject& object, int64_t value);
    void setValueQuietly(const ProcessDataObject& object, int64_t value);
    void endHold(bool expired);
    void checkWatchdog();

    MasterContext& context_;
    SyncProducer& sync_;
    std::shared_ptr<Shared> shared_;
    uint8_t node_ = 0;
    uint64_t generation_ = 0;  // setNode() count: a read for another node stops
    // Objects the user set (setValue) since the last readValues() began: the drive's value read
    // after that does not overwrite what the user chose (a bit ticked while the read runs).
    std::set<uint32_t> setByUser_;
    std::vector<ProcessDataPdo> pdos_;
    Mode mode_ = Mode::Once;
    int periodMs_ = 100;
    bool running_ = false;
    std::vector<PeriodicSender::JobId> jobs_;  // per pdo, 0 = none
    QTimer* watchdog_ = nullptr;
};

}  // namespace coscope::canopen
