// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/can/CanFrame.h"

#include <QByteArray>
#include <QString>
#include <QStringList>

#include <atomic>
#include <cstdint>
#include <memory>
#include <string_view>
#include <vector>

class QIODevice;

namespace coscope::logio {

// A problem in the input that did not stop reading: `where` is the 1-based line number of a
// text log, or the record/object number of a binary one.
struct LogDiagnostic {
    int64_t where = 0;
    QString message;
};

// A gap in a live capture recorded in the log (issue 16 "Lost adapter"): the adapter was lost
// at lostNs and back at backNs; `frame` (0-based, counting the frames read) is the first frame
// after it. Only formats that can say so carry gaps (CaptureGapText.h: a comment on that
// frame's pcapng block, a comment line in ASC and TRC, a "gap" row in CSV).
struct CaptureGap {
    uint64_t frame = 0;
    int64_t lostNs = 0;
    int64_t backNs = 0;
};

// Reads one log format incrementally (DESIGN.md "Reliability": a bad line is reported with its
// line number and the rest is read; nothing here throws or aborts on bad input).
// Typical use: open(), then read() batches until it returns 0; then check errorString().
// cancel() may be called from any thread; progress() is safe to poll from any thread.
class LogReader {
public:
    virtual ~LogReader();

    virtual QString formatName() const = 0;

    bool open(const QString& path);
    // Reads from `device` (opened for reading; the caller keeps it alive until done).
    bool open(QIODevice* device, const QString& sourceName = {});

    // Reads up to `max` frames; 0 means the end (or a fatal error, or cancel()).
    size_t read(CanFrame* out, size_t max);
    // Reads everything that is left (small files, tests).
    std::vector<CanFrame> readAll();

    bool atEnd() const { return done_; }
    double progress() const { return progress_.load(std::memory_order_relaxed); }  // 0..1 by bytes
    void cancel() { cancelled_.store(true, std::memory_order_relaxed); }
    bool isCancelled() const { return cancelled_.load(std::memory_order_relaxed); }

    // Fatal problem (unreadable file, not this format); empty when reading worked.
    bool hasError() const { return !error_.isEmpty(); }
    QString errorString() const { return error_; }

    const std::vector<LogDiagnostic>& diagnostics() const { return diagnostics_; }
    // Gaps of the capture found so far, in frame order (see CaptureGap).
    const std::vector<CaptureGap>& gaps() const { return gaps_; }
    uint64_t diagnosticCount() const { return diagnosticCount_; }  // including unstored ones
    uint64_t framesRead() const { return framesRead_; }
    // Lines read so far for text formats; 0 for binary ones.
    virtual int64_t linesRead() const { return 0; }
    QString sourceName() const { return sourceName_; }
    // Names of the buses seen (CanFrame::bus indexes this list): "can0", "1", ...
    const QStringList& busNames() const { return busNames_; }

    static constexpr size_t kMaxStoredDiagnostics = 1000;

protected:
    // Called once after open(): reads the header. Return false after fail() if unusable.
    virtual bool readHeader() { return true; }
    // Reads up to max frames; call finish() at the end of input.
    virtual size_t readFrames(CanFrame* out, size_t max) = 0;

    QIODevice* device() const { return device_; }
    void warn(int64_t where, const QString& message);
    void fail(const QString& message);
    void finish() { done_ = true; }
    void addGap(const CaptureGap& gap) { gaps_.push_back(gap); }
    void updateProgress();
    // Index of a bus by name, added on first sight (at most 256 buses; later ones share 255).
    uint8_t busIndex(std::string_view name);
    // Index of a bus numbered from 1 (Vector, PEAK, BLF channels): channel N is bus N-1, named
    // "canN-1" so a converted log replays on can0.. .
    uint8_t busChannel(uint32_t channel);

private:
    std::unique_ptr<QIODevice> owned_;
    QIODevice* device_ = nullptr;
    QString sourceName_;
    QString error_;
    std::vector<LogDiagnostic> diagnostics_;
    std::vector<CaptureGap> gaps_;
    uint64_t diagnosticCount_ = 0;
    uint64_t framesRead_ = 0;
    QStringList busNames_;
    std::vector<QByteArray> busKeys_;
    int64_t size_ = 0;
    bool done_ = false;
    bool started_ = false;
    std::atomic<bool> cancelled_{false};
    std::atomic<double> progress_{0.0};
};

// Base of the line-oriented formats: buffered line splitting straight from the device
// (never the whole file in memory), 1-based line numbers, CR LF tolerated.
class LineLogReader : public LogReader {
protected:
    enum class LineResult { Frame, Skip, Bad };
    // Parses one line (without the line end). Bad lines call warn(lineNumber(), ...) themselves.
    virtual LineResult parseLine(std::string_view line, CanFrame& frame) = 0;

    size_t readFrames(CanFrame* out, size_t max) override;
    // For readHeader(): the next line, or false at the end.
    bool nextLine(std::string_view& line);
    // A comment's text (after "//", ";", ...): when it is a gap in CaptureGapText.h's wording,
    // the next frame returned is the first after that gap (gaps()).
    void noteGapComment(std::string_view text);
    // Puts the last line back so readFrames() sees it again.
    void unreadLine() { unread_ = true; }
    int64_t lineNumber() const { return lineNumber_; }

public:
    int64_t linesRead() const override { return lineNumber_; }

private:
    QByteArray buffer_;
    qsizetype pos_ = 0;
    qsizetype end_ = 0;
    bool eof_ = false;
    bool unread_ = false;
    std::string_view last_;
    int64_t lineNumber_ = 0;
    std::vector<CaptureGap> pendingGaps_;  // before the next frame
};

}  // namespace coscope::logio
