// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/canopen/ProcessData.h"

#include "core/canopen/SdoClient.h"
#include "core/od/NumberText.h"

#include <QPointer>
#include <QTimer>

#include <chrono>
#include <mutex>
#include <set>

namespace coscope::canopen {

namespace {

int64_t processDataNowNs() {
    return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now().time_since_epoch())
        .count();
}

QString mappedObjectText(uint16_t index, uint8_t sub) {
    return QStringLiteral("%1h:%2")
        .arg(index, 4, 16, QChar(u'0'))
        .arg(sub, 2, 16, QChar(u'0'))
        .toUpper()
        .replace(QStringLiteral("H:"), QStringLiteral("h:"));
}

// The axis-0 object of a CiA 402 object on any axis (CiA 402-2 §5.2).
uint16_t axisBase(uint16_t index) {
    if (index < 0x6000 || index >= 0xA000) return index;
    return static_cast<uint16_t>(0x6000 + ((index - 0x6000) % 0x800));
}

bool fits(const ProcessDataObject& o, int64_t v) {
    const int bits = o.entry.bits;
    if (bits >= 64) return true;
    if (o.isSigned) return v >= -(int64_t{1} << (bits - 1)) && v < (int64_t{1} << (bits - 1));
    return v >= 0 && static_cast<uint64_t>(v) < (uint64_t{1} << bits);
}

// A value read over SDO (little-endian, CiA 301 §7.1.2), sign-extended for signed objects.
int64_t fromBytes(const ProcessDataObject& o, const QByteArray& data) {
    uint64_t raw = 0;
    const int n = std::min<int>(static_cast<int>(data.size()), 8);
    for (int i = 0; i < n; ++i) raw |= uint64_t(uint8_t(data[i])) << (8 * i);
    const int bits = std::min<int>(o.entry.bits, n * 8);
    if (bits < 64) {
        raw &= (uint64_t{1} << bits) - 1;
        if (o.isSigned && bits > 0 && (raw >> (bits - 1)) & 1) raw |= ~uint64_t{0} << bits;
    }
    return static_cast<int64_t>(raw);
}

}  // namespace

bool ProcessDataPdo::carriesMotion() const {
    for (const ProcessDataObject& o : objects)
        if (o.motion) return true;
    return false;
}

int ProcessDataPdo::bytes() const {
    int bits = 0;
    for (const ProcessDataObject& o : objects) bits = std::max(bits, o.bitOffset + o.entry.bits);
    return std::min((bits + 7) / 8, 64);
}

CanFrame composeRpdo(const ProcessDataPdo& pdo, const std::vector<int64_t>& values) {
    CanFrame f;
    f.id = pdo.layout.canId();
    if (pdo.layout.extended()) f.flags |= CanFrame::Extended;
    f.len = static_cast<uint8_t>(std::min(pdo.bytes(), 8));
    for (size_t i = 0; i < pdo.objects.size(); ++i) {
        const ProcessDataObject& o = pdo.objects[i];
        const auto raw = o.dummy || i >= values.size() ? uint64_t{0} : static_cast<uint64_t>(values[i]);
        // LSB first: bit b of the value is bit (offset + b) of the frame, counted from bit 0 of byte 0.
        for (int b = 0; b < o.entry.bits; ++b) {
            const int at = o.bitOffset + b;
            if (at >= f.len * 8) break;
            if ((raw >> b) & 1) f.data[at / 8] |= static_cast<uint8_t>(1u << (at % 8));
        }
    }
    return f;
}

std::vector<int64_t> stoppedValues(const ProcessDataPdo& pdo, const std::vector<int64_t>& values) {
    std::vector<int64_t> out = values;
    for (size_t i = 0; i < pdo.objects.size() && i < out.size(); ++i) {
        switch (axisBase(pdo.objects[i].entry.index)) {
        case 0x6040: out[i] |= 0x100; break;  // controlword bit 8: halt
        case 0x6042:                          // vl target velocity
        case 0x6071:                          // target torque
        case 0x60B1:                          // velocity offset
        case 0x60B2:                          // torque offset
        case 0x60FF: out[i] = 0; break;       // target velocity
        default: break;
        }
    }
    return out;
}

// What the sender thread shares with the owner's thread; everything under `mutex`.
struct ProcessData::Shared {
    std::mutex mutex;
    std::vector<ProcessDataPdo> pdos;           // set while nothing is sending
    std::vector<std::vector<int64_t>> values;   // per pdo, per object
    std::vector<char> enabled;                  // per pdo
    std::vector<char> stopPending;              // per pdo with motion: values went out since the last stop frame
    std::vector<char> removeJob;                // per pdo: its job sent the stop frame and ends
    std::vector<PeriodicSender::JobId> jobIds;  // per pdo, for the job removing itself
    int64_t holdUntilNs = 0;                    // 0 = not held
    bool withSync = false;                      // the SYNC hook sends
    std::atomic<uint64_t> sent{0};
    QString lastError;

    bool held(int64_t now) const { return holdUntilNs != 0 && now < holdUntilNs; }
    // The frame of pdo i as it must go out now (mutex held); nullopt: nothing to send.
    std::optional<CanFrame> next(size_t i, bool held, bool repeatStop) {
        const ProcessDataPdo& p = pdos[i];
        if (!p.carriesMotion()) return composeRpdo(p, values[i]);
        if (held) {
            stopPending[i] = 1;
            return composeRpdo(p, values[i]);
        }
        if (!stopPending[i] && !repeatStop) return std::nullopt;
        stopPending[i] = 0;
        return composeRpdo(p, stoppedValues(p, values[i]));
    }
};

ProcessData::ProcessData(MasterContext& context, SyncProducer& sync, QObject* parent)
    : QObject(parent), context_(context), sync_(sync), shared_(std::make_shared<Shared>()) {
    watchdog_ = new QTimer(this);
    watchdog_->setInterval(50);
    connect(watchdog_, &QTimer::timeout, this, &ProcessData::checkWatchdog);
}

ProcessData::~ProcessData() {
    endHold(false);
    stop();
}

bool ProcessData::setNode(uint8_t node, const od::ObjectDictionary& dictionary, QString* error) {
    endHold(false);
    stop();
    std::vector<ProcessDataPdo> pdos;
    for (int n = 1; n <= 512; ++n) {
        auto layout = rpdoLayout(dictionary, node, n);
        if (!layout) {
            if (n > 4) break;  // RPDOs after the first four are listed only when described
            continue;
        }
        if (!layout->valid() || layout->entries.empty()) continue;
        ProcessDataPdo p;
        p.layout = *layout;
        int offset = 0;
        for (const PdoMapEntry& e : layout->entries) {
            ProcessDataObject o;
            o.entry = e;
            o.bitOffset = offset;
            offset += e.bits;
            o.dummy = e.index >= 1 && e.index <= 7;
            o.motion = isMotionObject(e.index);
            if (const od::SubObject* s = dictionary.entry(e.index, e.sub)) {
                o.name = s->name;
                o.isSigned = od::isSigned(s->dataType);
            } else if (o.dummy) {
                o.isSigned = e.index == 2 || e.index == 3 || e.index == 4;  // INTEGER8/16/32 dummies
            }
            p.objects.push_back(std::move(o));
        }
        if (offset > 64) continue;  // not a classic CAN PDO
        pdos.push_back(std::move(p));
    }
    node_ = node;
    ++generation_;
    pdos_ = std::move(pdos);
    {
        const std::lock_guard lock(shared_->mutex);
        shared_->pdos = pdos_;
        shared_->values.clear();
        for (const ProcessDataPdo& p : pdos_) shared_->values.emplace_back(p.objects.size(), 0);
        shared_->enabled.assign(pdos_.size(), 1);
        shared_->stopPending.assign(pdos_.size(), 0);
        shared_->removeJob.assign(pdos_.size(), 0);
        shared_->jobIds.assign(pdos_.size(), 0);
        shared_->sent = 0;
        shared_->lastError.clear();
    }
    jobs_.assign(pdos_.size(), 0);
    if (pdos_.empty() && error)
        *error = QStringLiteral("node %1's dictionary describes no valid mapped RPDO").arg(node);
    return !pdos_.empty();
}

const ProcessDataPdo* ProcessData::pdo(int number) const {
    for (const ProcessDataPdo& p : pdos_)
        if (p.layout.number == number) return &p;
    return nullptr;
}

void ProcessData::setEnabled(int number, bool enabled) {
    const std::lock_guard lock(shared_->mutex);
    for (size_t i = 0; i < pdos_.size(); ++i)
        if (pdos_[i].layout.number == number) shared_->enabled[i] = enabled;
}

bool ProcessData::isEnabled(int number) const {
    const std::lock_guard lock(shared_->mutex);
    for (size_t i = 0; i < pdos_.size(); ++i)
        if (pdos_[i].layout.number == number) return shared_->enabled[i];
    return false;
}

bool ProcessData::setValue(uint16_t index, uint8_t sub, int64_t value, QString* error) {
    std::vector<size_t> changed;
    bool mapped = false;
    {
        const std::lock_guard lock(shared_->mutex);
        for (size_t i = 0; i < pdos_.size(); ++i) {
            for (size_t k = 0; k < pdos_[i].objects.size(); ++k) {
                const ProcessDataObject& o = pdos_[i].objects[k];
                if (o.dummy || o.entry.index != index || o.entry.sub != sub) continue;
                mapped = true;
                if (!fits(o, value)) {
                    if (error)
                        *error = QStringLiteral("%1 = %2 does not fit its %3 mapped bits (%4)")
                                     .arg(mappedObjectText(index, sub))
                                     .arg(value)
                                     .arg(o.entry.bits)
                                     .arg(o.isSigned ? QStringLiteral("signed") : QStringLiteral("unsigned"));
                    return false;
                }
                if (shared_->values[i][k] != value) changed.push_back(i);
                shared_->values[i][k] = value;
            }
        }
    }
    if (const ProcessDataObject* o = mapped ? object(index, sub) : nullptr) noteIfEnabling(*o, value);
    if (mapped) setByUser_.insert(uint32_t(index) << 8 | sub);
    if (!mapped) {
        if (error)
            *error =
                QStringLiteral("%1 is not mapped in an RPDO of node %2").arg(mappedObjectText(index, sub)).arg(node_);
        return false;
    }
    if (running_ && mode_ == Mode::OnChange) {
        const bool held = isHeld();
        for (size_t i : changed)
            if (isEnabled(pdos_[i].layout.number) && (held || !pdos_[i].carriesMotion())) sendNow(i, nullptr);
    }
    return true;
}

std::optional<int64_t> ProcessData::value(uint16_t index, uint8_t sub) const {
    const std::lock_guard lock(shared_->mutex);
    for (size_t i = 0; i < pdos_.size(); ++i)
        for (size_t k = 0; k < pdos_[i].objects.size(); ++k)
            if (!pdos_[i].objects[k].dummy && pdos_[i].objects[k].entry.index == index &&
                pdos_[i].objects[k].entry.sub == sub)
                return shared_->values[i][k];
    return std::nullopt;
}

const ProcessDataObject* ProcessData::object(uint16_t index, uint8_t sub) const {
    for (const ProcessDataPdo& p : pdos_)
        for (const ProcessDataObject& o : p.objects)
            if (!o.dummy && o.entry.index == index && o.entry.sub == sub) return &o;
    return nullptr;
}

std::optional<int64_t> ProcessData::parseValue(const ProcessDataObject& o, const QString& text, QString* error) {
    QString t = text.trimmed();
    bool hexSuffix = false;
    if (t.size() > 1 && (t.endsWith(u'h') || t.endsWith(u'H'))) {  // "1Fh", as the manuals write hex
        t.chop(1);
        hexSuffix = true;
    }
    std::optional<od::ParsedInteger> p;
    if (hexSuffix) {
        bool ok = false;
        const uint64_t v = t.toULongLong(&ok, 16);
        if (ok) p = od::ParsedInteger{v, false, true};
    } else {
        p = od::parseIntegerText(t, od::TextStyle::Person);
    }
    if (!p) {
        if (error) *error = QStringLiteral("'%1' is not a number (decimal, 0x1F or 1Fh)").arg(text);
        return std::nullopt;
    }
    int64_t v = 0;
    const int bits = o.entry.bits;
    if (p->hex && o.isSigned && bits < 64 && !p->negative && p->magnitude < (uint64_t{1} << bits)) {
        uint64_t raw = p->magnitude;
        if ((raw >> (bits - 1)) & 1) raw |= ~uint64_t{0} << bits;  // the bit pattern of a negative value
        v = static_cast<int64_t>(raw);
    } else {
        v = p->negative ? -static_cast<int64_t>(p->magnitude) : static_cast<int64_t>(p->magnitude);
    }
    if (!fits(o, v)) {
        if (error)
            *error = QStringLiteral("%1 does not fit %2's %3 mapped bits")
                         .arg(text, mappedObjectText(o.entry.index, o.entry.sub))
                         .arg(bits);
        return std::nullopt;
    }
    return v;
}

bool ProcessData::setValueText(uint16_t index, uint8_t sub, const QString& text, QString* error) {
    const ProcessDataObject* o = object(index, sub);
    if (!o) {
        if (error)
            *error =
                QStringLiteral("%1 is not mapped in an RPDO of node %2").arg(mappedObjectText(index, sub)).arg(node_);
        return false;
    }
    const auto v = parseValue(*o, text, error);
    return v && setValue(index, sub, *v, error);
}

void ProcessData::readValues(SdoClient& sdo, std::function<void(const QStringList&)> done) {
    auto todo = std::make_shared<std::vector<ProcessDataObject>>();
    std::set<uint32_t> seen;
    for (const ProcessDataPdo& p : pdos_)
        for (const ProcessDataObject& o : p.objects)
            if (!o.dummy && seen.insert(o.entry.encode() & 0xFFFFFF00u).second) todo->push_back(o);
    auto failures = std::make_shared<QStringList>();
    setByUser_.clear();
    auto step = std::make_shared<std::function<void(size_t)>>();
    const QPointer<ProcessData> self(this);
    const uint8_t node = node_;
    const uint64_t generation = generation_;
    // The chain holds itself only through the pending upload's callback: an SDO client that drops
    // its callbacks (bus closed) frees the chain instead of leaking a step -> lambda -> step cycle.
    *step = [self, &sdo, node, todo, failures, weakStep = std::weak_ptr(step), done, generation](size_t i) {
        if (self && self->generation_ != generation && i < todo->size()) {
            *failures << QStringLiteral("node %1 was replaced while reading").arg(node);
            i = todo->size();
        }
        if (!self || i >= todo->size()) {
            if (self && done) done(*failures);  // nobody waits for a ProcessData that is gone
            return;
        }
        const ProcessDataObject o = (*todo)[i];
        sdo.upload(
            node, o.entry.index, o.entry.sub, [self, o, failures, step = weakStep.lock(), i](const SdoResult& r) {
                if (!self) return;
                if (!r.ok)
                    *failures << QStringLiteral("%1: %2").arg(mappedObjectText(o.entry.index, o.entry.sub), r.error);
                else if (!self->setByUser_.count(uint32_t(o.entry.index) << 8 | o.entry.sub))
                    self->setValueQuietly(o, fromBytes(o, r.data));
                (*step)(i + 1);
            });
    };
    (*step)(0);
}

void ProcessData::noteIfEnabling(const ProcessDataObject& object, int64_t value) {
    // A controlword that switches voltage on goes into the bus's record of drives CoScope enabled
    // before it can be sent, so whatever closes the bus disables the drive first (EnabledDrives).
    // A disabling one is not taken as proof: an RPDO is not confirmed by the drive.
    const uint16_t index = object.entry.index;
    if (index >= 0x6000 && index < 0xA000 && (index - 0x6000) % 0x800 == 0x40 && object.entry.sub == 0 &&
        EnabledDrives::enablesVoltage(static_cast<uint16_t>(value)))
        context_.enabledDrives().noteControlword(node_, (index - 0x6000) / 0x800, static_cast<uint16_t>(value));
}

void ProcessData::setValueQuietly(const ProcessDataObject& object, int64_t value) {
    if (!fits(object, value)) return;
    noteIfEnabling(object, value);
    const std::lock_guard lock(shared_->mutex);
    for (size_t i = 0; i < pdos_.size(); ++i)
        for (size_t k = 0; k < pdos_[i].objects.size(); ++k)
            if (!pdos_[i].objects[k].dummy && pdos_[i].objects[k].entry.index == object.entry.index &&
                pdos_[i].objects[k].entry.sub == object.entry.sub)
                shared_->values[i][k] = value;
}

CanFrame ProcessData::frame(int number, bool held) const {
    const std::lock_guard lock(shared_->mutex);
    for (size_t i = 0; i < pdos_.size(); ++i) {
        if (pdos_[i].layout.number != number) continue;
        return composeRpdo(pdos_[i], held || !pdos_[i].carriesMotion() ? shared_->values[i]
                                                                       : stoppedValues(pdos_[i], shared_->values[i]));
    }
    return {};
}

void ProcessData::setMode(Mode mode, int periodMs) {
    const bool wasRunning = running_;
    if (wasRunning) stop();
    mode_ = mode;
    if (periodMs > 0) periodMs_ = periodMs;
    if (wasRunning && mode != Mode::Once) start();
}

bool ProcessData::sendNow(size_t i, QString* error) {
    QString why;
    bool ok = true;
    {
        const std::lock_guard lock(shared_->mutex);
        const auto f = shared_->next(i, shared_->held(processDataNowNs()), false);
        if (!f) return true;
        ok = context_.send(*f, &why);
        if (ok) ++shared_->sent;
        else shared_->lastError = why;
    }
    if (!ok) {
        if (error) *error = why;
        emit sendFailed(why);
    }
    return ok;
}

void ProcessData::startJob(size_t i) {
    if (jobs_[i] && context_.periodic().status(jobs_[i]).running) return;
    if (jobs_[i]) context_.periodic().remove(jobs_[i]);
    PeriodicSender::Job job;
    job.periodNs = int64_t{periodMs_} * 1000000;
    const std::shared_ptr<Shared> s = shared_;
    PeriodicSender* periodic = &context_.periodic();
    job.maker = [s, i] {
        const std::lock_guard lock(s->mutex);
        const bool held = s->held(processDataNowNs());
        const bool motion = s->pdos[i].carriesMotion();
        // Not held any more (the owner's thread may be stalled): one frame with the stopped
        // values, then the job ends.
        if (motion && !held) s->removeJob[i] = 1;
        return *s->next(i, held, true);
    };
    job.afterSend = [s, i, periodic](const CanFrame&, uint64_t) {
        ++s->sent;
        PeriodicSender::JobId end = 0;
        {
            const std::lock_guard lock(s->mutex);
            if (s->removeJob[i]) end = s->jobIds[i];
            s->removeJob[i] = 0;
        }
        if (end) periodic->remove(end);
    };
    job.onStopped = [this, s](const QString& why) {
        if (why.isEmpty()) return;
        {
            const std::lock_guard lock(s->mutex);
            s->lastError = why;
        }
        QMetaObject::invokeMethod(
            this, [this, why] { emit sendFailed(why); }, Qt::QueuedConnection);
    };
    QString error;
    {
        const std::lock_guard lock(shared_->mutex);
        shared_->removeJob[i] = 0;
    }
    jobs_[i] = context_.periodic().add(std::move(job), &error);
    const std::lock_guard lock(shared_->mutex);
    shared_->jobIds[i] = jobs_[i];
    if (!jobs_[i]) {
        shared_->lastError = error;
        QMetaObject::invokeMethod(
            this, [this, error] { emit sendFailed(error); }, Qt::QueuedConnection);
    }
}

void ProcessData::stopJobs(bool motionOnly) {
    for (size_t i = 0; i < jobs_.size(); ++i) {
        if (!jobs_[i] || (motionOnly && !pdos_[i].carriesMotion())) continue;
        context_.periodic().remove(jobs_[i]);
        jobs_[i] = 0;
    }
}

bool ProcessData::start(QString* error) {
    if (pdos_.empty()) {
        if (error) *error = QStringLiteral("no node with RPDOs chosen");
        return false;
    }
    if (running_) stop();
    const bool held = isHeld();
    bool any = false;
    switch (mode_) {
    case Mode::Once:
    case Mode::OnChange:
        for (size_t i = 0; i < pdos_.size(); ++i) {
            if (!isEnabled(pdos_[i].layout.number) || (pdos_[i].carriesMotion() && !held)) continue;
            if (!sendNow(i, error)) return false;
            any = true;
        }
        if (mode_ == Mode::Once && !any) {
            if (error)
                *error = QStringLiteral(
                    "the RPDOs chosen carry motion objects: they are sent only while hold to run is held");
            return false;
        }
        running_ = mode_ == Mode::OnChange;
        return true;
    case Mode::Every:
        if (!context_.bus() || context_.bus()->isListenOnly()) {
            if (error) *error = QStringLiteral("the bus is listen-only or not open");
            return false;
        }
        running_ = true;
        for (size_t i = 0; i < pdos_.size(); ++i) {
            if (!isEnabled(pdos_[i].layout.number) || (pdos_[i].carriesMotion() && !held)) continue;
            startJob(i);
            if (!jobs_[i]) {
                if (error) *error = lastError();
                stop();
                return false;
            }
        }
        return true;
    case Mode::WithSync: {
        if (!context_.bus() || context_.bus()->isListenOnly()) {
            if (error) *error = QStringLiteral("the bus is listen-only or not open");
            return false;
        }
        running_ = true;
        const std::shared_ptr<Shared> s = shared_;
        MasterContext* context = &context_;
        {
            const std::lock_guard lock(s->mutex);
            s->withSync = true;
        }
        sync_.setOnEachSync([s, context](const CanFrame&, uint64_t) {
            const std::lock_guard lock(s->mutex);
            if (!s->withSync) return;  // stopped while this SYNC went out
            const bool held = s->held(processDataNowNs());
            for (size_t i = 0; i < s->pdos.size(); ++i) {
                if (!s->enabled[i]) continue;
                const auto f = s->next(i, held, false);
                if (!f) continue;
                QString why;
                if (context->send(*f, &why)) ++s->sent;
                else s->lastError = why;
            }
        });
        return true;
    }
    }
    return false;
}

void ProcessData::stop() {
    if (mode_ == Mode::WithSync && running_) sync_.setOnEachSync({});
    {
        const std::lock_guard lock(shared_->mutex);
        shared_->withSync = false;
    }
    stopJobs(false);
    running_ = false;
    // Whatever sent motion values last, they end with the stopped values.
    for (size_t i = 0; i < pdos_.size(); ++i) {
        const std::lock_guard lock(shared_->mutex);
        if (!shared_->stopPending[i]) continue;
        shared_->stopPending[i] = 0;
        QString why;
        if (context_.send(composeRpdo(pdos_[i], stoppedValues(pdos_[i], shared_->values[i])), &why)) ++shared_->sent;
        else shared_->lastError = why;
    }
}

void ProcessData::feedHold() {
    bool began = false;
    {
        const std::lock_guard lock(shared_->mutex);
        const int64_t now = processDataNowNs();
        began = !shared_->held(now);
        shared_->holdUntilNs = now + int64_t{kHoldWatchdogMs} * 1000000;
    }
    if (!began) return;
    watchdog_->start();
    for (size_t i = 0; i < pdos_.size(); ++i) {
        if (!pdos_[i].carriesMotion() || !isEnabled(pdos_[i].layout.number)) continue;
        if (mode_ == Mode::Once || (mode_ == Mode::OnChange && running_)) sendNow(i, nullptr);
        else if (mode_ == Mode::Every && running_) startJob(i);
    }
}

void ProcessData::releaseHold() { endHold(false); }

bool ProcessData::isHeld() const {
    const std::lock_guard lock(shared_->mutex);
    return shared_->held(processDataNowNs());
}

void ProcessData::endHold(bool expired) {
    watchdog_->stop();
    {
        const std::lock_guard lock(shared_->mutex);
        shared_->holdUntilNs = 0;
    }
    stopJobs(true);
    for (size_t i = 0; i < pdos_.size(); ++i)
        if (pdos_[i].carriesMotion()) sendNow(i, nullptr);  // the stopped values, when values went out
    if (expired) emit holdExpired();
}

void ProcessData::checkWatchdog() {
    bool expired = false;
    {
        const std::lock_guard lock(shared_->mutex);
        expired = shared_->holdUntilNs != 0 && !shared_->held(processDataNowNs());
    }
    if (expired) endHold(true);
}

uint64_t ProcessData::sent() const { return shared_->sent.load(); }

QString ProcessData::lastError() const {
    const std::lock_guard lock(shared_->mutex);
    return shared_->lastError;
}

}  // namespace coscope::canopen
