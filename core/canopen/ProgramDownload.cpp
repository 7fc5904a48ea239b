// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/canopen/ProgramDownload.h"

#include "core/canopen/SdoAbort.h"

#include <QPointer>
#include <QStringList>
#include <QTimer>
#include <QtEndian>

#include <spdlog/spdlog.h>

#include <algorithm>
#include <chrono>

namespace coscope::canopen {

namespace {
// 1F51h program control values (CiA 302-3 §4): 0 stop, 1 start, 2 reset, 3 clear.
constexpr uint8_t kStop = 0, kStart = 1, kClear = 3;
constexpr int kProgressEveryMs = 100;
constexpr qint64 kSettleMs = 300;  // quiet time after a broken transfer before the next run

QByteArray u8(uint8_t v) { return QByteArray(1, static_cast<char>(v)); }

QString hex32(uint32_t v) {
    return QStringLiteral("0x%1")
        .arg(v, 8, 16, QChar(u'0'))
        .toUpper()
        .replace(QStringLiteral("0X"), QStringLiteral("0x"));
}

// Answers that mean "this node has no clear command" rather than "it failed".
bool clearNotSupported(uint32_t code) {
    return code == sdoabort::InvalidValue || code == sdoabort::ValueTooHigh || code == sdoabort::UnsupportedAccess ||
           code == sdoabort::ParameterIncompatible || code == sdoabort::NoSubIndex;
}
}  // namespace

QString flashStatusText(uint32_t status) {
    // 1F57h flash status identification: bit 0 in progress, bits 1-7 error code (CiA 302-3 §4).
    static const char* const errors[] = {"ok",
                                         "no valid program",
                                         "data format unknown",
                                         "data format error",
                                         "flash not cleared before write",
                                         "flash write error",
                                         "general address error",
                                         "flash secured (write access denied)"};
    const uint32_t code = (status >> 1) & 0x7F;
    QString text = code < 8     ? QString::fromLatin1(errors[code])
                   : code == 63 ? QStringLiteral("unspecified error")
                                : QStringLiteral("error %1").arg(code);
    if (status & 1) text += QStringLiteral(", in progress");
    return text;
}

QString ProgramState::summary() const {
    QStringList parts;
    parts
        << QStringLiteral("100Ah %1").arg(version ? QStringLiteral("\"%1\"").arg(*version) : QStringLiteral("unknown"));
    parts << QStringLiteral("1F56h %1").arg(softwareId ? hex32(*softwareId) : QStringLiteral("unknown"));
    parts << QStringLiteral("flash %1").arg(flashStatus ? flashStatusText(*flashStatus) : QStringLiteral("unknown"));
    return parts.join(QStringLiteral(", "));
}

QString programStepName(ProgramStep step, uint8_t program) {
    const QString sub = QStringLiteral("%1").arg(program, 2, 16, QChar(u'0')).toUpper();
    switch (step) {
    case ProgramStep::ReadBefore: return QStringLiteral("read the program state (1F56h, 1F57h, 100Ah)");
    case ProgramStep::DisableDrive: return QStringLiteral("disable the drive (6040h = 0)");
    case ProgramStep::Stop: return QStringLiteral("stop program (1F51h:%1 = 0)").arg(sub);
    case ProgramStep::Clear: return QStringLiteral("clear program (1F51h:%1 = 3)").arg(sub);
    case ProgramStep::Download: return QStringLiteral("program data (1F50h:%1)").arg(sub);
    case ProgramStep::Start: return QStringLiteral("start program (1F51h:%1 = 1)").arg(sub);
    case ProgramStep::BootUp: return QStringLiteral("wait for the boot-up");
    case ProgramStep::ReadAfter: return QStringLiteral("read the new program state");
    case ProgramStep::Done: return QStringLiteral("done");
    }
    return {};
}

QString ProgramDownloadOutcome::summary() const {
    if (ok) {
        const double rate = seconds > 0 ? double(bytes) / seconds / 1024.0 : 0;
        QString s = QStringLiteral("%1 bytes downloaded in %2 s (%3 KiB/s%4)")
                        .arg(bytes)
                        .arg(seconds, 0, 'f', 2)
                        .arg(rate, 0, 'f', 1)
                        .arg(fellBackToSegmented ? QStringLiteral(", segmented: block declined") : QString());
        if (!started) return s + QStringLiteral("; not started (1F51h not written)");
        return s + QStringLiteral("; started; software version %1 -> %2, 1F56h %3 -> %4")
                       .arg(before.version.value_or(QStringLiteral("?")), after.version.value_or(QStringLiteral("?")),
                            before.softwareId ? hex32(*before.softwareId) : QStringLiteral("?"),
                            after.softwareId ? hex32(*after.softwareId) : QStringLiteral("?"));
    }
    const QString what =
        step <= ProgramStep::Stop
            ? QStringLiteral("the node's program was not touched")
            : QStringLiteral("nothing claimed: the node may hold no valid program; download again from the start");
    return QStringLiteral("%1 at step \"%2\": %3; %4")
        .arg(cancelled ? QStringLiteral("cancelled") : QStringLiteral("failed"), programStepName(step), error, what);
}

struct ProgramDownload::Run {
    ProgramDownloadRequest req;
    StepCallback step;
    ProgressCallback progress;
    Done done;
    ProgramDownloadOutcome out;
    bool cancelRequested = false;
    quint64 transfer = 0;  // the 1F50h download in progress
    QElapsedTimer clock;   // since the 1F50h download began
    qint64 lastProgressMs = -kProgressEveryMs;
    int bootSubscription = 0;
    QTimer* bootTimer = nullptr;
    bool bootSeen = false;
    bool startAnswered = false;
};

ProgramDownload::ProgramDownload(MasterContext& context, SdoClient& sdo, QObject* parent)
    : QObject(parent), context_(context), sdo_(sdo) {}

ProgramDownload::~ProgramDownload() {
    if (!run_) return;
    auto run = std::move(run_);  // no callback reaches us any more
    if (run->transfer) sdo_.cancel(run->transfer);
    if (run->bootSubscription) context_.dispatcher().unsubscribe(run->bootSubscription);
}

void ProgramDownload::readInto(ProgramState* state, std::function<void()> then) {
    const uint8_t node = run_ ? run_->req.node : 0;
    const uint8_t program = run_ ? run_->req.program : 1;
    QPointer<ProgramDownload> self(this);
    auto run = run_;
    readState(node, program, [self, run, state, then](const ProgramState& s) {
        if (!self || self->run_ != run) return;
        *state = s;
        then();
    });
}

void ProgramDownload::readState(uint8_t node, uint8_t program, std::function<void(const ProgramState&)> done) {
    readProgramState(sdo_, node, program, std::move(done));
}

void readProgramState(SdoClient& sdo, uint8_t node, uint8_t program, std::function<void(const ProgramState&)> done) {
    auto state = std::make_shared<ProgramState>();
    SdoOptions options;
    options.timeoutMs = 1000;
    // Three reads queued in order on the node; the last answer hands the state over.
    // 1F56h program software identification, UNSIGNED32 (CiA 302-3 §4).
    sdo.upload(
        node, 0x1F56, program,
        [state](const SdoResult& r) {
            if (r.ok && r.data.size() >= 4) state->softwareId = qFromLittleEndian<uint32_t>(r.data.constData());
        },
        options);
    // 1F57h flash status identification, UNSIGNED32 (CiA 302-3 §4).
    sdo.upload(
        node, 0x1F57, program,
        [state](const SdoResult& r) {
            if (r.ok && r.data.size() >= 4) state->flashStatus = qFromLittleEndian<uint32_t>(r.data.constData());
        },
        options);
    // 100Ah manufacturer software version, VISIBLE_STRING (CiA 301 7.5.2.8).
    sdo.upload(
        node, 0x100A, 0,
        [state, done](const SdoResult& r) {
            if (r.ok) state->version = QString::fromLatin1(r.data).section(QChar(u'\0'), 0, 0).trimmed();
            if (done) done(*state);
        },
        options);
}

void ProgramDownload::run(const ProgramDownloadRequest& request, StepCallback step, ProgressCallback progress,
                          Done done) {
    lastRequest_ = request;
    lastStep_ = step;
    lastProgress_ = progress;
    lastDone_ = done;
    run_ = std::make_shared<Run>();
    run_->req = request;
    run_->step = std::move(step);
    run_->progress = std::move(progress);
    run_->done = std::move(done);
    spdlog::info("program download: node {} program {}, {} bytes", request.node, request.program, request.image.size());
    auto run = run_;
    QPointer<ProgramDownload> self(this);
    // From the event loop: the caller returns from run() before any callback. Right after a
    // broken transfer, answers the node still sends to the rest of it (a sub-block's ack after
    // our abort) are let go by first, so none is taken for the answer to a new request.
    const qint64 settle =
        sinceBrokenTransfer_.isValid() ? std::max<qint64>(0, kSettleMs - sinceBrokenTransfer_.elapsed()) : 0;
    QTimer::singleShot(std::chrono::milliseconds(settle), this, [self, run] {
        if (self && self->run_ == run)
            self->next(run->req.readBefore ? ProgramStep::ReadBefore : ProgramStep::DisableDrive);
    });
}

void ProgramDownload::retry() {
    if (!run_) run(lastRequest_, lastStep_, lastProgress_, lastDone_);
}

void ProgramDownload::cancel() {
    if (!run_) return;
    run_->cancelRequested = true;
    if (run_->transfer) sdo_.cancel(run_->transfer);  // its callback ends the run
}

void ProgramDownload::write(ProgramStep step, uint16_t index, uint8_t sub, QByteArray data,
                            std::function<void(const SdoResult&)> then) {
    QPointer<ProgramDownload> self(this);
    auto run = run_;
    SdoOptions options;
    options.timeoutMs = run->req.sdoTimeoutMs;
    sdo_.download(
        run->req.node, index, sub, std::move(data),
        [self, run, step, then](const SdoResult& r) {
            if (!self || self->run_ != run) return;
            if (!then) return r.ok ? void() : self->fail(step, r);
            then(r);
        },
        options);
}

void ProgramDownload::next(ProgramStep step) {
    Run& run = *run_;
    const uint8_t node = run.req.node, program = run.req.program;
    if (run.cancelRequested && step <= ProgramStep::Start) {
        run.out.cancelled = true;
        return fail(step, {}, QStringLiteral("cancelled before this step; nothing written to 1F50h"));
    }
    if (run.step && step != ProgramStep::DisableDrive) run.step(step);
    switch (step) {
    case ProgramStep::ReadBefore: return readInto(&run.out.before, [this] { next(ProgramStep::DisableDrive); });
    case ProgramStep::DisableDrive: {
        // Stopping the application drops a drive CoScope enabled: Disable voltage first.
        for (const EnabledDrives::Drive& d : context_.enabledDrives().drives()) {
            if (d.node != node) continue;
            if (run.step) run.step(step);
            const auto cw = static_cast<uint16_t>(0x6040 + d.axis * 0x800);
            return write(step, cw, 0, QByteArray(2, '\0'), [this, d](const SdoResult& r) {
                if (!r.ok) return fail(ProgramStep::DisableDrive, r);
                context_.enabledDrives().noteControlword(d.node, d.axis, 0x0000);
                context_.enabledDrives().forget(d.node, d.axis);
                run_->out.notes += QStringLiteral("%1 disabled (6040h = 0); ").arg(d.name());
                next(ProgramStep::DisableDrive);  // the next enabled axis, if any
            });
        }
        return next(ProgramStep::Stop);
    }
    case ProgramStep::Stop:
        return write(step, 0x1F51, program, u8(kStop), [this](const SdoResult& r) {
            if (!r.ok) return fail(ProgramStep::Stop, r);
            next(run_->req.clear ? ProgramStep::Clear : ProgramStep::Download);
        });
    case ProgramStep::Clear:
        return write(step, 0x1F51, program, u8(kClear), [this](const SdoResult& r) {
            if (!r.ok && !(r.serverAborted && clearNotSupported(r.abortCode))) return fail(ProgramStep::Clear, r);
            if (!r.ok) {
                run_->out.clearSkipped = true;
                run_->out.notes += QStringLiteral("the node does not take clear (%1); ").arg(r.error);
            }
            next(ProgramStep::Download);
        });
    case ProgramStep::Download: {
        SdoOptions options;
        options.protocol = run.req.block ? SdoOptions::Protocol::Block : SdoOptions::Protocol::Auto;
        options.timeoutMs = run.req.sdoTimeoutMs;
        QPointer<ProgramDownload> self(this);
        auto r = run_;
        options.progress = [self, r](qint64 done, qint64 total) {
            if (!self || self->run_ != r || !r->progress) return;
            const qint64 ms = r->clock.elapsed();
            if (done < total && ms - r->lastProgressMs < kProgressEveryMs) return;
            r->lastProgressMs = ms;
            r->progress(done, total, ms > 0 ? double(done) * 1000.0 / double(ms) : 0.0);
        };
        run.clock.start();
        if (run.progress) run.progress(0, run.req.image.size(), 0);
        // 1F50h program data, DOMAIN (CiA 302-3 §4).
        run.transfer = sdo_.download(
            node, 0x1F50, program, run.req.image,
            [self, r](const SdoResult& res) {
                if (!self || self->run_ != r) return;
                r->transfer = 0;
                r->out.seconds = double(r->clock.nsecsElapsed()) / 1e9;
                r->out.fellBackToSegmented = res.fellBackToSegmented;
                if (!res.ok) {
                    self->sinceBrokenTransfer_.start();
                    r->out.cancelled = r->cancelRequested;
                    return self->fail(ProgramStep::Download, res);
                }
                r->out.bytes = r->req.image.size();
                self->next(r->req.start ? ProgramStep::Start : ProgramStep::ReadAfter);
            },
            options);
        return;
    }
    case ProgramStep::Start: {
        // Listen for the boot-up before asking: the node may reset before it answers.
        QPointer<ProgramDownload> self(this);
        auto r = run_;
        run.bootSubscription =
            context_.dispatcher().subscribe(this, {0x700u + node}, [self, r](const std::vector<CanFrame>& frames) {
                if (!self || self->run_ != r || r->bootSeen) return;
                for (const CanFrame& f : frames)
                    if (f.len == 1 && f.data[0] == 0x00 && !f.isRemote()) {  // boot-up (CiA 301 §7.2.8.3.3)
                        r->bootSeen = true;
                        if (r->startAnswered) self->next(ProgramStep::ReadAfter);
                        return;
                    }
            });
        run.bootTimer = new QTimer(this);
        run.bootTimer->setSingleShot(true);
        connect(run.bootTimer, &QTimer::timeout, this, [self, r] {
            if (!self || self->run_ != r) return;
            SdoResult none;
            self->fail(ProgramStep::BootUp, none,
                       QStringLiteral("node %1 sent no boot-up within %2 ms of the start command")
                           .arg(r->req.node)
                           .arg(r->req.bootTimeoutMs));
        });
        return write(step, 0x1F51, program, u8(kStart), [this](const SdoResult& res) {
            Run& rr = *run_;
            // A node that resets before answering: its boot-up stands for the answer.
            if (!res.ok && !(res.timedOut || rr.bootSeen)) return fail(ProgramStep::Start, res);
            rr.startAnswered = true;
            rr.out.started = true;
            if (rr.step) rr.step(ProgramStep::BootUp);
            if (rr.bootSeen) return next(ProgramStep::ReadAfter);
            rr.bootTimer->start(rr.req.bootTimeoutMs);
        });
    }
    case ProgramStep::BootUp: return;  // reached through Start
    case ProgramStep::ReadAfter:
        if (run.bootTimer) run.bootTimer->stop();
        return readInto(&run.out.after, [this] {
            const auto& status = run_->out.after.flashStatus;
            if (status && ((*status >> 1) & 0x7F) != 0)
                return fail(
                    ProgramStep::ReadAfter, {},
                    QStringLiteral("1F57h flash status says: %1 (%2)").arg(flashStatusText(*status), hex32(*status)));
            finish(true);
        });
    case ProgramStep::Done: return finish(true);
    }
}

void ProgramDownload::fail(ProgramStep step, const SdoResult& r, const QString& error) {
    if (!run_) return;
    run_->out.step = step;
    run_->out.abortCode = r.abortCode;
    run_->out.error = error.isEmpty() ? r.error : error;
    finish(false);
}

void ProgramDownload::finish(bool ok) {
    auto run = std::move(run_);
    if (!run) return;
    if (run->bootSubscription) context_.dispatcher().unsubscribe(run->bootSubscription);
    if (run->bootTimer) run->bootTimer->deleteLater();
    run->out.ok = ok;
    if (ok) run->out.step = ProgramStep::Done;
    if (ok) spdlog::info("program download: node {}: {}", run->req.node, run->out.summary().toStdString());
    else spdlog::warn("program download: node {}: {}", run->req.node, run->out.summary().toStdString());
    if (run->step && ok) run->step(ProgramStep::Done);
    if (run->done) run->done(run->out);
}

}  // namespace coscope::canopen
