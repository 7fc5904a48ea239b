// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/logio/LogWriter.h"

#include <QFile>

#include <cerrno>
#include <cstring>

#include <unistd.h>

namespace coscope::logio {

namespace {
constexpr qsizetype kFlushAt = 256 * 1024;
const char kUpperHexDigits[] = "0123456789ABCDEF";
}  // namespace

void appendHex2(QByteArray& out, uint8_t byte) {
    out.append(kUpperHexDigits[byte >> 4]);
    out.append(kUpperHexDigits[byte & 0xF]);
}

void appendHex(QByteArray& out, uint32_t value, int width) {
    char tmp[8];
    int n = 0;
    do {
        tmp[n++] = kUpperHexDigits[value & 0xF];
        value >>= 4;
    } while (value && n < 8);
    for (int i = n; i < width; ++i) out.append('0');
    while (n) out.append(tmp[--n]);
}

LogWriter::~LogWriter() {
    if (device_ && !closed_) close();
}

bool LogWriter::open(const QString& path) {
    auto file = std::make_unique<QFile>(path);
    if (!file->open(QIODevice::WriteOnly | QIODevice::Truncate)) {
        error_ = QStringLiteral("cannot write %1: %2").arg(path, file->errorString());
        return false;
    }
    owned_ = std::move(file);
    return open(owned_.get());
}

bool LogWriter::open(QIODevice* device) {
    device_ = device;
    if (!device_ || !device_->isWritable()) {
        error_ = QStringLiteral("output is not writable");
        device_ = nullptr;
        return false;
    }
    buffer_.reserve(kFlushAt + 4096);
    return true;
}

bool LogWriter::ensureHeader(const CanFrame* first) {
    if (!headerDone_) {
        headerDone_ = true;
        writeHeader(first);
    }
    return true;
}

bool LogWriter::write(const CanFrame& frame, const QString& summary) {
    if (!device_ || closed_ || hasError()) return false;
    ensureHeader(&frame);
    for (const auto& [lost, back] : pendingGaps_) writeGap(lost, back);
    pendingGaps_.clear();
    if (summary.isEmpty() && summary_ && wantsSummary()) writeFrame(frame, summary_(frame));
    else writeFrame(frame, summary);
    ++written_;
    if (buffer_.size() >= kFlushAt) return flush();
    return true;
}

void LogWriter::markGap(int64_t lostNs, int64_t backNs) {
    if (keepsGaps()) pendingGaps_.emplace_back(lostNs, backNs);
    else ++gapsDropped_;
}

bool LogWriter::flush() {
    if (!device_) return false;
    beforeFlush();
    if (!buffer_.isEmpty()) {
        if (device_->write(buffer_) != buffer_.size()) {
            if (error_.isEmpty()) error_ = QStringLiteral("write failed: %1").arg(device_->errorString());
            buffer_.clear();
            return false;
        }
        buffer_.clear();
    }
    // A buffered file hands its data to the kernel here: a full disk shows up now, not at close.
    if (auto* file = qobject_cast<QFileDevice*>(device_); file && !file->flush() && error_.isEmpty())
        error_ = QStringLiteral("write failed: %1").arg(file->errorString());
    return !hasError();
}

bool LogWriter::sync() {
    if (!flush()) return false;
    auto* file = qobject_cast<QFileDevice*>(device_);
    const int fd = file ? file->handle() : -1;
    // A device without it (a pipe, /dev/null) is no failure.
    if (fd >= 0 && ::fdatasync(fd) != 0 && errno != EINVAL && errno != EROFS && errno != ENOTSUP) {
        error_ = QStringLiteral("write failed: %1").arg(QString::fromLocal8Bit(std::strerror(errno)));
        return false;
    }
    return true;
}

bool LogWriter::close() {
    if (!device_ || closed_) return !hasError();
    ensureHeader(nullptr);
    writeFooter();
    bool ok = flush();
    if (ok && !device_->isSequential()) {
        patchHeader(*device_);
        if (auto* file = qobject_cast<QFileDevice*>(device_)) ok = file->flush();
    }
    closed_ = true;
    if (owned_) owned_->close();
    return ok;
}

QString LogWriter::busName(uint8_t bus) const {
    if (bus < busNames_.size() && !busNames_[bus].isEmpty()) return busNames_[bus];
    return QStringLiteral("can%1").arg(bus);
}

}  // namespace coscope::logio
