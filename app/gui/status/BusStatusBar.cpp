// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/status/BusStatusBar.h"

#include "app/gui/language/CoreText.h"
#include "app/gui/session/Workspace.h"

#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QStatusBar>

namespace coscope::gui {

double frameBits(int len, bool extended) {
    const double framing = 47 + 8.0 * len + (extended ? 20 : 0);
    const double stuffable = 34 + 8.0 * len + (extended ? 20 : 0);
    return framing + (stuffable - 1) / 4.0;
}

BusStatusBar::BusStatusBar(QStatusBar* bar, Workspace* workspace) : QObject(bar), workspace_(workspace) {
    auto label = [bar](const QString& name, int minWidth) {
        auto* l = new QLabel(bar);
        l->setObjectName(name);
        l->setMinimumWidth(minWidth);
        l->setFrameShape(QFrame::StyledPanel);
        bar->addPermanentWidget(l);
        return l;
    };
    progress_ = new QProgressBar(bar);
    progress_->setRange(0, 1000);
    progress_->setMaximumWidth(180);
    progress_->setTextVisible(true);
    progress_->hide();
    bar->addPermanentWidget(progress_);
    cancel_ = new QPushButton(tr("Cancel"), bar);
    cancel_->setObjectName(QStringLiteral("jobCancel"));
    cancel_->hide();
    bar->addPermanentWidget(cancel_);
    connect(cancel_, &QPushButton::clicked, this, [this] {
        if (job_) job_->cancel();
    });
    source_ = label(QStringLiteral("statusSource"), 160);
    state_ = label(QStringLiteral("statusState"), 80);
    rate_ = label(QStringLiteral("statusRate"), 90);
    load_ = label(QStringLiteral("statusLoad"), 90);
    dropped_ = label(QStringLiteral("statusDropped"), 90);
    errors_ = label(QStringLiteral("statusErrors"), 80);
    controller_ = label(QStringLiteral("statusController"), 0);
    controller_->hide();
    master_ = label(QStringLiteral("statusMaster"), 0);
    master_->hide();
    restart_ = new QPushButton(tr("Restart controller"), bar);
    restart_->setObjectName(QStringLiteral("restartController"));
    restart_->setToolTip(
        tr("The controller went bus-off and sends nothing; restart it (check wiring, termination and bit rate first)"));
    restart_->hide();
    bar->addPermanentWidget(restart_);
    connect(restart_, &QPushButton::clicked, this, &BusStatusBar::restartController);
    refresh(nullptr);
}

void BusStatusBar::setMasterText(const QString& text) {
    if (master_->text() != text) master_->setText(text);
    master_->setVisible(!text.isEmpty());
}

void BusStatusBar::refresh(Job* job) {
    job_ = job && !job->isDone() ? job : nullptr;
    progress_->setVisible(job_ != nullptr);
    cancel_->setVisible(job_ != nullptr);
    if (job_) {
        progress_->setValue(static_cast<int>(job_->progress() * 1000));
        progress_->setFormat(QStringLiteral("%1 %p%").arg(job_->title()));
    }

    const auto& store = workspace_->store();
    const uint64_t frames = store ? store->size() : 0;
    source_->setText(workspace_->sourceName().isEmpty() ? tr("No source") : workspace_->sourceName());
    CanBus* bus = workspace_->bus();
    if (!bus) {
        state_->setText(workspace_->loadJob() ? tr("Offline") : tr("Not connected"));
        rate_->setText(tr("%L1 frames").arg(frames));
        load_->clear();
        dropped_->clear();
        errors_->clear();
        controller_->hide();
        restart_->hide();
        lastFrames_ = frames;
        return;
    }
    // Rate and load over the frames appended since the last tick (≥ 0.5 s windows).
    const int64_t now = nowNs();
    if (lastNs_ == 0 || frames < lastFrames_) {
        lastNs_ = now;
        lastFrames_ = frames;
    } else if (now - lastNs_ >= 500'000'000) {
        // Over the frames in RAM only: a chunk already paged out to the journal (a capture faster
        // than a small budget) is not read back on the GUI thread; its share is estimated.
        double bits = 0;
        uint64_t counted = 0;
        for (uint64_t n = lastFrames_; n < frames;) {
            const uint64_t chunkEnd =
                std::min<uint64_t>(frames, ((n >> TraceStore::kChunkBits) + 1) << TraceStore::kChunkBits);
            if (!store->isResident(static_cast<FrameNo>(n))) {
                n = chunkEnd;
                continue;
            }
            for (; n < chunkEnd; ++n, ++counted) {
                const TraceRecord& r = store->record(static_cast<FrameNo>(n));
                bits +=
                    frameBits((r.flags & CanFrame::Remote) ? 0 : std::min<int>(r.len, 8), r.flags & CanFrame::Extended);
            }
        }
        if (counted > 0) bits *= double(frames - lastFrames_) / double(counted);
        const double secs = double(now - lastNs_) / 1e9;
        rate_fps_ = double(frames - lastFrames_) / secs;
        const int bitrate = bus->url().bitrate() > 0 ? bus->url().bitrate() : 500000;
        load_pct_ = 100.0 * bits / secs / bitrate;
        lastNs_ = now;
        lastFrames_ = frames;
    }
    const auto c = bus->counters();
    QString state;
    switch (bus->state()) {
    case CanBus::State::Closed: state = tr("closed"); break;
    case CanBus::State::Opening: state = tr("opening"); break;
    case CanBus::State::Open: state = tr("open"); break;
    case CanBus::State::Error: state = tr("error"); break;
    case CanBus::State::Lost: {  // issue 16: the adapter went away; the bus reopens by itself
        const int ms = bus->nextRetryInMs();
        state = ms < 0 ? tr("lost, retrying now") : tr("lost, retrying in %1 s").arg((ms + 999) / 1000);
        break;
    }
    }
    if (bus->isListenOnly()) state += tr(" · listen-only");
    state_->setText(state);
    state_->setStyleSheet(bus->state() == CanBus::State::Lost ? QStringLiteral("color: #b00020; font-weight: bold")
                                                              : QString());
    state_->setToolTip(bus->state() == CanBus::State::Lost
                           ? tr("Adapter lost: %1. The trace keeps everything; CoScope reopens the bus when it is back "
                                "(Disconnect stops trying).")
                                 .arg(bus->errorString())
                           : QString());
    rate_->setText(tr("%L1 frames/s").arg(rate_fps_, 0, 'f', 0));
    load_->setText(tr("load %1 %").arg(load_pct_, 0, 'f', 1));
    load_->setToolTip(tr("Estimated from frame lengths with worst-case bit stuffing at %1 bit/s")
                          .arg(bus->url().bitrate() > 0 ? bus->url().bitrate() : 500000));
    dropped_->setText(tr("dropped %L1").arg(c.dropped));
    dropped_->setStyleSheet(c.dropped ? QStringLiteral("color: #b00020; font-weight: bold") : QString());
    errors_->setText(tr("errors %L1").arg(c.errors));
    errors_->setStyleSheet(c.errors ? QStringLiteral("color: #b00020; font-weight: bold") : QString());

    // ISO 11898-1 §12.1.4 fault confinement, as the last error frame reported it.
    using S = CanErrorReport::BusState;
    QString ctl;
    switch (c.controllerState) {
    case S::Unknown: break;
    case S::Active: ctl = tr("error active"); break;
    case S::Warning: ctl = tr("error warning"); break;
    case S::Passive: ctl = tr("error passive"); break;
    case S::BusOff: ctl = tr("bus-off"); break;
    }
    if (!ctl.isEmpty() && c.txErrors >= 0) ctl += tr(" · TEC %1 REC %2").arg(c.txErrors).arg(c.rxErrors);
    controller_->setText(ctl);
    controller_->setVisible(!ctl.isEmpty());
    controller_->setStyleSheet(c.controllerState >= S::Passive   ? QStringLiteral("color: #b00020; font-weight: bold")
                               : c.controllerState == S::Warning ? QStringLiteral("color: #a05a00")
                                                                 : QString());
    controller_->setToolTip(tr("CAN controller state from the last error frame (transmit / receive error counters)"));
    restart_->setVisible(c.controllerState == S::BusOff);
}

void BusStatusBar::restartController() {
    CanBus* bus = workspace_->bus();
    if (!bus) return;
    QString why;
    if (bus->restartController(&why)) {
        workspace_->events().add(renderedEvent(TraceEvent::Kind::Info, nowNs(), kNoFrame, -1,
                                               [] { return tr("Controller restarted after bus-off"); }));
        return;
    }
    // Said where the user looks, and kept in the Events.
    workspace_->events().add(renderedEvent(TraceEvent::Kind::BusError, nowNs(), kNoFrame, -1, [why] {
        return tr("Restart after bus-off failed: %1").arg(coreText(why));
    }));
    if (auto* bar = qobject_cast<QStatusBar*>(parent()))
        bar->showMessage(tr("Restart after bus-off failed: %1").arg(why), 10000);
    restart_->setToolTip(tr("Last restart failed: %1").arg(why));
}

QString BusStatusBar::controllerText() const { return controller_->isVisible() ? controller_->text() : QString(); }

QString BusStatusBar::stateText() const { return state_->text(); }
QString BusStatusBar::rateText() const { return rate_->text(); }
QString BusStatusBar::loadText() const { return load_->text(); }

}  // namespace coscope::gui
