// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/trace/SdoGroups.h"

#include "app/gui/language/CoreText.h"
#include "app/gui/language/ObjectNameText.h"

#include "app/gui/trace/FrameDecoder.h"

#include <QCoreApplication>
#include "core/canopen/CobId.h"
#include "core/canopen/SdoAbort.h"

#include <algorithm>

namespace coscope::gui {

using canopen::SdoCommand;

namespace {

// Commands that start a transfer (CiA 301 §7.2.4.3: the client's initiate requests).
bool startsTransfer(SdoCommand c) {
    return c == SdoCommand::InitiateDownloadRequest || c == SdoCommand::InitiateUploadRequest ||
           c == SdoCommand::BlockDownloadInitiate || c == SdoCommand::BlockUploadInitiate;
}

bool lessFrame(const std::pair<FrameNo, uint32_t>& a, FrameNo n) { return a.first < n; }

}  // namespace

void SdoGroupIndex::addGroup(Channel& c) {
    SdoGroup g;
    g.first = c.frames.front();
    g.last = c.frames.back();
    g.begin = static_cast<uint32_t>(members_.size());
    g.count = static_cast<uint32_t>(c.frames.size());
    const auto id = static_cast<uint32_t>(groups_.size());
    groups_.push_back(g);
    members_.insert(members_.end(), c.frames.begin(), c.frames.end());
    // Transfers of different channels interleave: keep byFrame_ sorted (the new entries are
    // almost always near the end, so this is a short insertion).
    const size_t mid = byFrame_.size();
    for (FrameNo f : c.frames) byFrame_.emplace_back(f, id);
    if (mid > 0 && byFrame_[mid - 1].first > byFrame_[mid].first)
        std::inplace_merge(byFrame_.begin(), byFrame_.begin() + static_cast<std::ptrdiff_t>(mid), byFrame_.end());
    c.frames.clear();
}

bool SdoGroupIndex::scan(const TraceStore& store, FrameNo to, const std::function<bool(double)>& progress) {
    const FrameNo from = scanned_;
    for (FrameNo n = from; n < to; ++n) {
        if (progress && ((n - from) & 0xFFFF) == 0 && !progress(double(n - from) / double(to - from))) return false;
        const TraceRecord& r = store.record(n);
        if (r.flags & (CanFrame::Extended | CanFrame::Error | CanFrame::Remote)) {
            scanned_ = n + 1;
            continue;
        }
        // The pre-defined connection set (CiA 301 §7.3.5): 580h+n server -> client, 600h+n client -> server.
        const uint32_t base = r.id & 0x780;
        const int node = static_cast<int>(r.id & 0x7F);
        if ((base != 0x580 && base != 0x600) || node == 0) {
            scanned_ = n + 1;
            continue;
        }
        const bool fromClient = base == 0x600;
        Channel& c = channels_[uint32_t(r.bus) << 7 | uint32_t(node)];
        const auto payload = store.payload(n);
        const canopen::SdoFrame f =
            dissect::parseSdoFor(c.sdo, payload.data(), static_cast<int>(payload.size()), fromClient);
        if (f.command == SdoCommand::Invalid) {
            scanned_ = n + 1;
            continue;
        }
        if (startsTransfer(f.command)) c.frames.clear();  // an unfinished transfer is abandoned
        const bool idleBefore = c.sdo.phase == dissect::SdoChannel::Phase::Idle;
        c.frames.push_back(n);
        scratch_.reset(dissect::Dissection::Level::Stats);
        dissect::sdoTrack(c.sdo, f, fromClient, node, r.timestampNs, scratch_);
        if (scratch_.hasTransfer) addGroup(c);
        else if (idleBefore && c.sdo.phase == dissect::SdoChannel::Phase::Idle)
            c.frames.clear();  // not part of a transfer
        scanned_ = n + 1;
    }
    scanned_ = std::max(scanned_, to);
    return true;
}

int64_t SdoGroupIndex::groupOf(FrameNo n) const {
    const auto it = std::lower_bound(byFrame_.begin(), byFrame_.end(), n, lessFrame);
    return it != byFrame_.end() && it->first == n ? static_cast<int64_t>(it->second) : -1;
}

dissect::SdoTransferRecord SdoGroupIndex::record(const TraceStore& store, const SdoGroupIndex& index, size_t g,
                                                 const FrameDecoder& decoder) {
    return record(store, index.frames(g), decoder);
}

dissect::SdoTransferRecord SdoGroupIndex::record(const TraceStore& store, std::span<const FrameNo> frames,
                                                 const FrameDecoder& decoder) {
    if (frames.empty()) return {};
    // Reassembled from the group's own frames: always available.
    dissect::SdoChannel ch;
    dissect::Dissection d;
    d.reset(dissect::Dissection::Level::Stats);
    for (FrameNo n : frames) {
        const TraceRecord& r = store.record(n);
        const bool fromClient = (r.id & 0x780) == 0x600;
        const auto payload = store.payload(n);
        const canopen::SdoFrame f =
            dissect::parseSdoFor(ch, payload.data(), static_cast<int>(payload.size()), fromClient);
        d.reset(dissect::Dissection::Level::Stats);
        dissect::sdoTrack(ch, f, fromClient, static_cast<int>(r.id & 0x7F), r.timestampNs, d);
    }
    dissect::SdoTransferRecord own = d.transfer;
    if (own.status == QLatin1String("aborted") && own.abortText.isEmpty())
        own.abortText = coreText(canopen::sdoAbortText(own.abortCode));
    // The decoder's, in the context of the trace: object name and typed value.
    dissect::Dissection full;
    full.reset(dissect::Dissection::Level::Flat);
    decoder.decodeAt(store, frames.back(), full);
    if (full.hasTransfer && full.transfer.index == own.index && full.transfer.sub == own.sub &&
        full.transfer.status == own.status)
        return full.transfer;
    return own;
}

QString SdoGroupIndex::summary(const dissect::SdoTransferRecord& t, size_t frames) {
    const QString object =
        QStringLiteral("%1:%2").arg(t.index, 4, 16, QLatin1Char('0')).arg(t.sub, 2, 16, QLatin1Char('0')).toUpper() +
        (t.name.isEmpty() ? QString() : u' ' + localObjectName(t));
    //: Trace, one row per SDO transfer: %1 = node, %2 = object ("6041:00 Statusword")
    QString s = (t.upload ? QCoreApplication::translate("SdoGroupIndex", "SDO read node %1 %2")
                          : QCoreApplication::translate("SdoGroupIndex", "SDO write node %1 %2"))
                    .arg(t.node)
                    .arg(object);
    const QString mode = t.block       ? QCoreApplication::translate("SdoGroupIndex", "block")
                         : t.segmented ? QCoreApplication::translate("SdoGroupIndex", "segmented")
                                       : QCoreApplication::translate("SdoGroupIndex", "expedited");
    const QString frameText = frames == 1 ? QCoreApplication::translate("SdoGroupIndex", "1 frame")
                                          : QCoreApplication::translate("SdoGroupIndex", "%1 frames").arg(frames);
    if (t.status == QLatin1String("aborted")) {
        //: %1 = abort code in hex, %2 = its meaning, %3 = expedited/segmented/block, %4 = "3 frames"
        s += QCoreApplication::translate("SdoGroupIndex", ": aborted 0x%1 %2 (%3, %4)")
                 .arg(t.abortCode, 8, 16, QLatin1Char('0'))
                 .arg(coreText(t.abortText), mode, frameText);
        return s;
    }
    if (!t.valueText.isEmpty()) s += QStringLiteral(" = ") + coreText(t.valueText);
    else if (!t.data.isEmpty())
        s += QStringLiteral(" = ") + QString::fromLatin1(t.data.left(16).toHex(' ').toUpper()) +
             (t.data.size() > 16 ? QStringLiteral(" …") : QString());
    //: %1 = expedited/segmented/block, %2 = size, %3 = "3 frames"
    s += QCoreApplication::translate("SdoGroupIndex", " (%1, %2 bytes, %3)").arg(mode).arg(t.size).arg(frameText);
    if (t.status != QLatin1String("ok")) s += QStringLiteral(" ⚠ ") + coreText(t.status);
    return s;
}

SdoGroupIndex::RowText SdoGroupIndex::rowText(const dissect::SdoTransferRecord& t, size_t frames) {
    RowText text;
    text.summary = summary(t, frames);
    text.size = t.size;
    text.data = QString::fromLatin1(t.data.left(8).toHex(' ').toUpper()) +
                (t.data.size() > 8 ? QStringLiteral(" …") : QString());
    return text;
}

void GroupedRows::append(const SdoGroupIndex& index, const std::vector<FrameNo>* source, FrameNo from, FrameNo to) {
    if (headerKey.size() < index.size()) headerKey.resize(index.size(), SdoGroupIndex::kNone);
    const auto& byFrame = index.byFrame();
    const size_t count = source ? source->size() : size_t(to - from);
    if (count == 0) return;
    const FrameNo firstFrame = source ? source->front() : from;
    auto it = std::lower_bound(byFrame.begin(), byFrame.end(), firstFrame, lessFrame);
    top.reserve(top.size() + count);
    for (size_t i = 0; i < count; ++i) {
        const FrameNo n = source ? (*source)[i] : from + static_cast<FrameNo>(i);
        while (it != byFrame.end() && it->first < n) ++it;
        if (it == byFrame.end() || it->first != n) {
            top.push_back(plain(n));
            continue;
        }
        const uint32_t g = it->second;
        if (headerKey[g] != SdoGroupIndex::kNone) continue;  // its header is already shown
        headerKey[g] = n;
        top.push_back(header(g, n));
    }
}

}  // namespace coscope::gui
