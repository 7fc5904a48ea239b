// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/logio/LogReader.h"

#include "core/logio/CaptureGapText.h"

#include <QFile>
#include <QFileInfo>

#include <cstring>

namespace coscope::logio {

LogReader::~LogReader() = default;

bool LogReader::open(const QString& path) {
    auto file = std::make_unique<QFile>(path);
    if (!file->open(QIODevice::ReadOnly)) {
        fail(QStringLiteral("cannot open %1: %2").arg(path, file->errorString()));
        done_ = true;
        return false;
    }
    owned_ = std::move(file);
    return open(owned_.get(), path);
}

bool LogReader::open(QIODevice* device, const QString& sourceName) {
    device_ = device;
    sourceName_ = sourceName;
    if (!device_ || !device_->isReadable()) {
        fail(QStringLiteral("input is not readable"));
        done_ = true;
        return false;
    }
    size_ = device_->isSequential() ? 0 : device_->size();
    started_ = true;
    if (!readHeader()) {
        if (error_.isEmpty()) fail(QStringLiteral("not a %1 file").arg(formatName()));
        done_ = true;
        return false;
    }
    return true;
}

size_t LogReader::read(CanFrame* out, size_t max) {
    if (!started_ || done_ || max == 0) return 0;
    if (isCancelled()) {
        done_ = true;
        return 0;
    }
    size_t n = 0;
    // A batch may be empty (a stretch of comments): keep going until frames or the end.
    while (n == 0 && !done_ && !isCancelled()) n = readFrames(out, max);
    framesRead_ += n;
    updateProgress();
    if (done_) progress_.store(1.0, std::memory_order_relaxed);
    return n;
}

std::vector<CanFrame> LogReader::readAll() {
    std::vector<CanFrame> all;
    CanFrame batch[256];
    while (size_t n = read(batch, 256)) all.insert(all.end(), batch, batch + n);
    return all;
}

void LogReader::warn(int64_t where, const QString& message) {
    ++diagnosticCount_;
    if (diagnostics_.size() < kMaxStoredDiagnostics) diagnostics_.push_back({where, message});
}

void LogReader::fail(const QString& message) {
    if (error_.isEmpty()) error_ = message;
    done_ = true;
}

void LogReader::updateProgress() {
    if (size_ > 0 && device_)
        progress_.store(std::min(1.0, double(device_->pos()) / double(size_)), std::memory_order_relaxed);
}

uint8_t LogReader::busIndex(std::string_view name) {
    for (size_t i = 0; i < busKeys_.size(); ++i)
        if (busKeys_[i].size() == qsizetype(name.size()) &&
            std::memcmp(busKeys_[i].constData(), name.data(), name.size()) == 0)
            return static_cast<uint8_t>(i);
    if (busKeys_.size() >= 255) return 255;
    busKeys_.emplace_back(name.data(), qsizetype(name.size()));
    busNames_ << QString::fromLatin1(name.data(), qsizetype(name.size()));
    return static_cast<uint8_t>(busKeys_.size() - 1);
}

uint8_t LogReader::busChannel(uint32_t channel) {
    const uint32_t bus = channel == 0 ? 0 : std::min<uint32_t>(channel - 1, 255);
    while (busNames_.size() <= qsizetype(bus)) {
        const QByteArray name = "can" + QByteArray::number(busNames_.size());
        busKeys_.push_back(name);
        busNames_ << QString::fromLatin1(name);
    }
    return static_cast<uint8_t>(bus);
}

// ---- LineLogReader

namespace {
constexpr qsizetype kChunk = 1 << 20;       // read 1 MiB at a time
constexpr qsizetype kMaxLine = 4 * kChunk;  // longer "lines" are cut (binary junk)
}  // namespace

bool LineLogReader::nextLine(std::string_view& line) {
    if (unread_) {
        unread_ = false;
        line = last_;
        return true;
    }
    for (;;) {
        const char* base = buffer_.constData();
        const void* nl = pos_ < end_ ? std::memchr(base + pos_, '\n', size_t(end_ - pos_)) : nullptr;
        if (nl || (eof_ && pos_ < end_) || (end_ - pos_) >= kMaxLine) {
            const qsizetype stop = nl ? qsizetype(static_cast<const char*>(nl) - base) : end_;
            qsizetype len = stop - pos_;
            if (len > 0 && base[pos_ + len - 1] == '\r') --len;
            line = std::string_view(base + pos_, size_t(len));
            pos_ = nl ? stop + 1 : stop;
            if (++lineNumber_ == 1 && line.substr(0, 3) == "\xEF\xBB\xBF") line.remove_prefix(3);  // UTF-8 BOM
            last_ = line;
            return true;
        }
        if (eof_) return false;
        // Move the partial line to the front and read more behind it.
        const qsizetype keep = end_ - pos_;
        if (buffer_.size() < keep + kChunk) buffer_.resize(keep + kChunk);
        if (keep && pos_) std::memmove(buffer_.data(), buffer_.constData() + pos_, size_t(keep));
        pos_ = 0;
        end_ = keep;
        const qint64 got = device()->read(buffer_.data() + end_, kChunk);
        if (got <= 0) {
            // Sequential devices may just not have data yet; for logs, treat as the end.
            eof_ = true;
        } else {
            end_ += got;
        }
    }
}

void LineLogReader::noteGapComment(std::string_view text) {
    int64_t lost = 0, back = 0;
    if (parseCaptureGapText(text, &lost, &back)) pendingGaps_.push_back({0, lost, back});
}

size_t LineLogReader::readFrames(CanFrame* out, size_t max) {
    size_t n = 0;
    std::string_view line;
    unsigned lines = 0;
    while (n < max) {
        if ((++lines & 0xFFF) == 0 && isCancelled()) return n;
        if (!nextLine(line)) {
            finish();
            break;
        }
        CanFrame& f = out[n];
        f = CanFrame{};
        if (parseLine(line, f) == LineResult::Frame) {
            for (CaptureGap& g : pendingGaps_) {
                g.frame = framesRead() + n;
                addGap(g);
            }
            pendingGaps_.clear();
            ++n;
        }
    }
    return n;
}

}  // namespace coscope::logio
