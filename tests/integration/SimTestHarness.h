// SPDX-License-Identifier: GPL-3.0-or-later
// Test helper: a sim:// bus endpoint with raw-frame helpers and a minimal SDO client built from
// the core/canopen codecs (for the virtual device tests).
#pragma once

#include "core/can/CanBus.h"
#include "core/canopen/Sdo.h"
#include "core/sim/SimBus.h"
#include "core/sim/VirtualDevice.h"
#include "eds/SimulatorDictionaries.h"

#include <QElapsedTimer>
#include <QThread>

#include <deque>
#include <functional>
#include <optional>

namespace coscope::testing {

struct SdoResult {
    QByteArray data;
    uint32_t abort = 0;  // 0 = success
    QString error;       // protocol problem seen by the test client (timeout, bad frame)
    bool ok() const { return abort == 0 && error.isEmpty(); }
};

class SimHarness {
public:
    bool open(const QString& spec, QString* error) {
        bus_ = createBus(QStringLiteral("sim://?nodes=") + spec, error);
        if (!bus_) return false;
        bus_->open();
        if (!bus_->waitForOpen(2000)) {
            if (error) *error = bus_->errorString();
            return false;
        }
        collect(60);  // boot-ups
        return true;
    }
    ~SimHarness() {
        if (bus_) bus_->close();
    }
    sim::SimNetwork* net() const { return static_cast<SimBus*>(bus_.get())->network(); }
    // Runs fn on the network thread with the device of `node`.
    void withDevice(uint8_t node, const std::function<void(sim::VirtualDevice&)>& fn) {
        net()->runOnNetworkThread([&] {
            if (auto* d = net()->device(node)) fn(*d);
        });
    }
    void send(const CanFrame& f) { bus_->send(f); }

    // Frames others sent (our own echoes skipped), waiting up to ms.
    std::optional<CanFrame> waitFor(const std::function<bool(const CanFrame&)>& pred, int ms) {
        QElapsedTimer t;
        t.start();
        for (;;) {
            for (auto it = pending_.begin(); it != pending_.end(); ++it)
                if (pred(*it)) {
                    CanFrame f = *it;
                    pending_.erase(it);
                    return f;
                }
            if (t.elapsed() > ms) return std::nullopt;
            pull(5);
        }
    }
    std::vector<CanFrame> collect(int ms) {
        QElapsedTimer t;
        t.start();
        while (t.elapsed() < ms) pull(5);
        std::vector<CanFrame> out(pending_.begin(), pending_.end());
        pending_.clear();
        return out;
    }
    void clear() { collect(0); }

    std::optional<CanFrame> sdoRequest(uint8_t node, const CanFrame& req, int ms = 500) {
        send(req);
        return waitFor([node](const CanFrame& f) { return f.id == 0x580u + node; }, ms);
    }

    // --- a minimal SDO client (CiA 301 §7.2.4.3)
    SdoResult upload(uint8_t node, uint16_t index, uint8_t sub) {
        SdoResult r;
        auto resp = sdoRequest(node, canopen::sdo::initiateUpload(node, index, sub));
        if (!resp) return fail(r, "no response to initiate upload");
        auto p = canopen::parseSdo(resp->data.data(), resp->len, false);
        if (p.command == canopen::SdoCommand::Abort) return aborted(r, p.abortCode);
        if (p.command != canopen::SdoCommand::InitiateUploadResponse) return fail(r, "unexpected response");
        if (p.expedited) {
            r.data = p.data;
            return r;
        }
        bool toggle = false;
        for (;;) {
            auto seg = sdoRequest(node, canopen::sdo::uploadSegmentRequest(node, toggle));
            if (!seg) return fail(r, "no segment response");
            auto s = canopen::parseSdo(seg->data.data(), seg->len, false);
            if (s.command == canopen::SdoCommand::Abort) return aborted(r, s.abortCode);
            if (s.command != canopen::SdoCommand::UploadSegmentResponse) return fail(r, "unexpected segment response");
            if (s.toggle != toggle) return fail(r, "toggle bit");
            r.data.append(s.data);
            toggle = !toggle;
            if (s.last) break;
        }
        if (p.sizeIndicated && uint32_t(r.data.size()) != p.size) return fail(r, "size mismatch");
        return r;
    }

    SdoResult download(uint8_t node, uint16_t index, uint8_t sub, const QByteArray& data) {
        SdoResult r;
        auto resp = sdoRequest(node, canopen::sdo::initiateDownload(node, index, sub, data));
        if (!resp) return fail(r, "no response to initiate download");
        auto p = canopen::parseSdo(resp->data.data(), resp->len, false);
        if (p.command == canopen::SdoCommand::Abort) return aborted(r, p.abortCode);
        if (p.command != canopen::SdoCommand::InitiateDownloadResponse) return fail(r, "unexpected response");
        if (data.size() <= 4 && !data.isEmpty()) return r;
        bool toggle = false;
        for (qsizetype off = 0; off < data.size() || data.isEmpty();) {
            const QByteArray chunk = data.mid(off, 7);
            off += chunk.size();
            const bool last = off >= data.size();
            auto seg = sdoRequest(node, canopen::sdo::downloadSegment(node, toggle, chunk, last));
            if (!seg) return fail(r, "no segment response");
            auto s = canopen::parseSdo(seg->data.data(), seg->len, false);
            if (s.command == canopen::SdoCommand::Abort) return aborted(r, s.abortCode);
            if (s.command != canopen::SdoCommand::DownloadSegmentResponse)
                return fail(r, "unexpected segment response");
            if (s.toggle != toggle) return fail(r, "toggle bit");
            toggle = !toggle;
            if (last) break;
        }
        return r;
    }

    // Block upload with CRC; `dropSeq` > 0 pretends that segment of the first sub-block was lost.
    SdoResult blockUpload(uint8_t node, uint16_t index, uint8_t sub, uint8_t blksize = 127, int dropSeq = 0,
                          uint8_t pst = 0) {
        SdoResult r;
        const uint32_t req = 0x600u + node;
        auto resp = sdoRequest(
            node, CanFrame::classic(req, {0xA4, uint8_t(index), uint8_t(index >> 8), sub, blksize, pst, 0, 0}));
        if (!resp) return fail(r, "no response to block upload initiate");
        auto p = canopen::parseSdo(resp->data.data(), resp->len, false);
        if (p.command == canopen::SdoCommand::Abort) return aborted(r, p.abortCode);
        if (p.command == canopen::SdoCommand::InitiateUploadResponse) {  // protocol switch
            r.data = p.expedited ? p.data : QByteArray();
            r.error = p.expedited ? QString() : QStringLiteral("switched to segmented");
            return r;
        }
        if (p.command != canopen::SdoCommand::BlockUploadInitiateResponse) return fail(r, "unexpected response");
        send(CanFrame::classic(req, {0xA3, 0, 0, 0, 0, 0, 0, 0}));
        bool done = false;
        bool dropped = false;
        while (!done) {
            uint8_t good = 0;
            QByteArray sub_;
            for (;;) {
                auto seg = waitFor([node](const CanFrame& f) { return f.id == 0x580u + node; }, 500);
                if (!seg) return fail(r, "sub-block segment missing");
                if (seg->data[0] == 0x80) {
                    auto a = canopen::parseSdo(seg->data.data(), seg->len, false);
                    return aborted(r, a.abortCode);
                }
                const uint8_t seq = seg->data[0] & 0x7F;
                const bool last = seg->data[0] & 0x80;
                if (!dropped && dropSeq > 0 && seq == dropSeq) {
                    dropped = true;
                } else if (seq == good + 1) {
                    ++good;
                    r.data.append(reinterpret_cast<const char*>(seg->data.data() + 1), 7);
                    if (last) done = true;
                }
                if (seq == blksize || last) break;
            }
            send(CanFrame::classic(req, {0xA2, good, blksize, 0, 0, 0, 0, 0}));
        }
        auto end = waitFor([node](const CanFrame& f) { return f.id == 0x580u + node; }, 500);
        if (!end) return fail(r, "no block upload end");
        auto e = canopen::parseSdo(end->data.data(), end->len, false);
        if (e.command == canopen::SdoCommand::Abort) return aborted(r, e.abortCode);
        if (e.command != canopen::SdoCommand::BlockUploadEnd) return fail(r, "unexpected end frame");
        r.data.chop(e.unusedBytes);
        const uint16_t crc =
            canopen::sdoBlockCrc(reinterpret_cast<const uint8_t*>(r.data.constData()), size_t(r.data.size()));
        if (crc != e.crc) {
            send(canopen::sdo::abortFromClient(node, index, sub, 0x05040004));
            return fail(r, "CRC mismatch");
        }
        send(CanFrame::classic(req, {0xA1, 0, 0, 0, 0, 0, 0, 0}));
        return r;
    }

    // Block download with CRC; `badCrc` sends a wrong CRC at the end.
    SdoResult blockDownload(uint8_t node, uint16_t index, uint8_t sub, const QByteArray& data, bool badCrc = false) {
        SdoResult r;
        const uint32_t req = 0x600u + node;
        const auto n = static_cast<uint32_t>(data.size());
        auto resp = sdoRequest(node, CanFrame::classic(req, {0xC6, uint8_t(index), uint8_t(index >> 8), sub, uint8_t(n),
                                                             uint8_t(n >> 8), uint8_t(n >> 16), uint8_t(n >> 24)}));
        if (!resp) return fail(r, "no response to block download initiate");
        auto p = canopen::parseSdo(resp->data.data(), resp->len, false);
        if (p.command == canopen::SdoCommand::Abort) return aborted(r, p.abortCode);
        if (p.command != canopen::SdoCommand::BlockDownloadInitiateResponse) return fail(r, "unexpected response");
        uint8_t blksize = p.blockSize;
        qsizetype off = 0;
        int lastLen = 0;
        bool finished = false;
        while (!finished) {
            const qsizetype start = off;
            uint8_t seq = 0;
            bool last = false;
            while (seq < blksize && !last) {
                ++seq;
                const QByteArray chunk = data.mid(off, 7);
                off += chunk.size();
                last = off >= data.size();
                lastLen = static_cast<int>(chunk.size());
                CanFrame f = CanFrame::classic(req, {uint8_t((last ? 0x80 : 0) | seq), 0, 0, 0, 0, 0, 0, 0});
                for (int i = 0; i < chunk.size(); ++i) f.data[size_t(1 + i)] = uint8_t(chunk[i]);
                send(f);
            }
            auto ack = waitFor([node](const CanFrame& f) { return f.id == 0x580u + node; }, 500);
            if (!ack) return fail(r, "no block ack");
            auto a = canopen::parseSdo(ack->data.data(), ack->len, false);
            if (a.command == canopen::SdoCommand::Abort) return aborted(r, a.abortCode);
            if (a.command != canopen::SdoCommand::BlockDownloadAck) return fail(r, "unexpected ack");
            off = std::min<qsizetype>(start + qsizetype(a.ackSeq) * 7, data.size());
            finished = last && a.ackSeq == seq;
            blksize = a.blockSize;
        }
        uint16_t crc = canopen::sdoBlockCrc(reinterpret_cast<const uint8_t*>(data.constData()), size_t(data.size()));
        if (badCrc) crc ^= 0x1234;
        const auto unused = static_cast<uint8_t>(7 - lastLen);
        auto end = sdoRequest(node, CanFrame::classic(req, {uint8_t(0xC1 | (unused << 2)), uint8_t(crc),
                                                            uint8_t(crc >> 8), 0, 0, 0, 0, 0}));
        if (!end) return fail(r, "no block download end response");
        auto e = canopen::parseSdo(end->data.data(), end->len, false);
        if (e.command == canopen::SdoCommand::Abort) return aborted(r, e.abortCode);
        if (e.command != canopen::SdoCommand::BlockDownloadEndResponse) return fail(r, "unexpected end response");
        return r;
    }

    // Helpers for numbers.
    static QByteArray u8(uint8_t v) { return QByteArray(1, char(v)); }
    static QByteArray u16(uint16_t v) {
        const char b[2] = {char(v), char(v >> 8)};
        return QByteArray(b, 2);
    }
    static QByteArray u32(uint32_t v) {
        const char b[4] = {char(v), char(v >> 8), char(v >> 16), char(v >> 24)};
        return QByteArray(b, 4);
    }
    static uint32_t le(const QByteArray& b) {
        uint32_t v = 0;
        for (int i = 0; i < std::min<int>(4, int(b.size())); ++i) v |= uint32_t(uint8_t(b[i])) << (8 * i);
        return v;
    }
    std::optional<uint32_t> read(uint8_t node, uint16_t index, uint8_t sub) {
        auto r = upload(node, index, sub);
        if (!r.ok()) return std::nullopt;
        return le(r.data);
    }

    CanBus* bus() const { return bus_.get(); }

private:
    void pull(int waitMs) {
        bus_->waitForFrames(waitMs);
        CanFrame buf[256];
        size_t n;
        while ((n = bus_->read(buf, 256)) > 0)
            for (size_t i = 0; i < n; ++i)
                if (!buf[i].isTx()) pending_.push_back(buf[i]);
    }
    static SdoResult fail(SdoResult& r, const char* what) {
        r.error = QString::fromLatin1(what);
        return r;
    }
    static SdoResult aborted(SdoResult& r, uint32_t code) {
        r.abort = code;
        return r;
    }

    std::unique_ptr<CanBus> bus_;
    std::deque<CanFrame> pending_;
};

}  // namespace coscope::testing
