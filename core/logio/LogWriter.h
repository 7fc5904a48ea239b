// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/can/CanFrame.h"

#include <QByteArray>
#include <QString>
#include <QStringList>

#include <cstdint>
#include <functional>
#include <memory>
#include <utility>
#include <vector>

class QIODevice;

namespace coscope::logio {

// Writes one log format. The header goes out with the first frame (formats put the start time
// in it) or at close() for an empty log. Output is buffered and written in large blocks.
class LogWriter {
public:
    virtual ~LogWriter();

    virtual QString formatName() const = 0;

    bool open(const QString& path);
    bool open(QIODevice* device);  // caller keeps the device alive until close()

    // Names of the buses (CanFrame::bus indexes it); missing ones are written as "can<N>".
    void setBusNames(const QStringList& names) { busNames_ = names; }
    // Formats with a summary column (CSV) call this when write() is given no summary.
    void setSummaryProvider(std::function<QString(const CanFrame&)> provider) { summary_ = std::move(provider); }

    bool write(const CanFrame& frame, const QString& summary = {});
    // The next frame written comes after a gap in the capture (issue 16 "Lost adapter": the
    // adapter was lost at lostNs and back at backNs). Formats that can say so (keepsGaps():
    // pcapng, ASC, TRC, CSV; CaptureGapText.h) record it with that frame; the others count it
    // in gapsDropped().
    void markGap(int64_t lostNs, int64_t backNs);
    // Whether this format can hold a gap of the capture (candump and BLF cannot).
    virtual bool keepsGaps() const { return false; }
    // Gaps given to markGap() that this format could not hold.
    uint64_t gapsDropped() const { return gapsDropped_; }
    bool flush();
    // flush(), then to the disk (fdatasync) for a file: what a power loss keeps.
    bool sync();
    bool close();  // writes the footer, flushes; closes a file opened by path

    bool hasError() const { return !error_.isEmpty(); }
    QString errorString() const { return error_; }
    uint64_t framesWritten() const { return written_; }

protected:
    virtual void writeHeader(const CanFrame* first) = 0;  // first == nullptr: empty log
    virtual void writeFrame(const CanFrame& frame, const QString& summary) = 0;
    // Formats that keepsGaps(): records a gap before the frame written next (after the header).
    virtual void writeGap(int64_t lostNs, int64_t backNs) {
        (void)lostNs;
        (void)backNs;
    }
    virtual void writeFooter() {}
    virtual bool wantsSummary() const { return false; }
    // Formats that hold frames back (BLF containers) move them to out() here; called by flush().
    virtual void beforeFlush() {}
    // After the last flush on a seekable device: formats with totals in their header (BLF)
    // write it again. The device is positioned at the end on return.
    virtual void patchHeader(QIODevice& /*device*/) {}

    QByteArray& out() { return buffer_; }
    QString busName(uint8_t bus) const;
    uint64_t frameNumber() const { return written_ + 1; }  // of the frame being written

private:
    bool ensureHeader(const CanFrame* first);

    std::unique_ptr<QIODevice> owned_;
    QIODevice* device_ = nullptr;
    QByteArray buffer_;
    QStringList busNames_;
    std::function<QString(const CanFrame&)> summary_;
    QString error_;
    uint64_t written_ = 0;
    std::vector<std::pair<int64_t, int64_t>> pendingGaps_;  // lost, back
    uint64_t gapsDropped_ = 0;
    bool headerDone_ = false;
    bool closed_ = false;
};

// Appends "AB" for a byte; uppercase like candump and Vector tools.
void appendHex2(QByteArray& out, uint8_t byte);
// Appends `value` as uppercase hex with at least `width` digits.
void appendHex(QByteArray& out, uint32_t value, int width);

}  // namespace coscope::logio
