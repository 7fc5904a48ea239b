// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/canopen/MasterContext.h"
#include "core/canopen/SdoClient.h"

#include <QByteArray>
#include <QElapsedTimer>
#include <QObject>
#include <QString>

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>

namespace coscope::canopen {

// What a node says about its program (CiA 302-3 objects of one program number, and 100Ah).
// A field is empty when the node did not answer it (not every node has every object).
struct ProgramState {
    std::optional<uint32_t> softwareId;   // 1F56h:NN program software identification
    std::optional<uint32_t> flashStatus;  // 1F57h:NN flash status identification
    std::optional<QString> version;       // 100Ah manufacturer software version
    // "1F56h 0x1A2B3C4D, 100Ah 2.0, flash ok" for logs and the CLI.
    QString summary() const;
};

// Reads what `node` says about program `program`: 1F56h program software identification, 1F57h
// flash status identification (CiA 302-3 §4) and 100Ah manufacturer software version (CiA 301
// 7.5.2.8), queued in order on the node. Never fails: a field the node does not answer stays empty.
void readProgramState(SdoClient& sdo, uint8_t node, uint8_t program, std::function<void(const ProgramState&)> done);

// 1F57h in words: bit 0 "in progress", bits 1-7 the error code (CiA 302-3): "ok",
// "no valid program", "data format unknown", ... "unspecified error".
QString flashStatusText(uint32_t status);

// What to download and how.
struct ProgramDownloadRequest {
    uint8_t node = 0;
    uint8_t program = 1;        // the sub-index of 1F50h/1F51h/1F56h/1F57h (program number)
    QByteArray image;           // 1F50h program data, sent as it is
    bool block = true;          // block SDO (segmented when the node declines); false = segmented
    bool start = true;          // 1F51h = 1 after the download, then wait for the boot-up
    bool clear = true;          // 1F51h = 3 before the download, where the node takes it
    bool readBefore = true;     // 1F56h, 1F57h, 100Ah before (the outcome's `before`)
    int sdoTimeoutMs = 5000;    // per SDO response (flash erase can take a while)
    int bootTimeoutMs = 10000;  // from the start command to the node's boot-up
};

// The steps, in order.
enum class ProgramStep : uint8_t { ReadBefore, DisableDrive, Stop, Clear, Download, Start, BootUp, ReadAfter, Done };
QString programStepName(ProgramStep step, uint8_t program = 1);  // "stop program (1F51h:01 = 0)", ...

// The result. ok only when every step went through; otherwise `step` names where it stopped,
// `error` says what the node answered, and nothing is claimed about the new program.
struct ProgramDownloadOutcome {
    bool ok = false;
    bool cancelled = false;
    ProgramStep step = ProgramStep::ReadBefore;  // the failed step (Done when ok)
    uint32_t abortCode = 0;                      // the SDO abort code of the failed step (0 = none)
    QString error;                               // one line: object, abort code and text
    ProgramState before, after;                  // after: read once the node came back
    bool started = false;                        // the start command was taken
    bool fellBackToSegmented = false;
    bool clearSkipped = false;  // the node does not take 1F51h = 3
    qint64 bytes = 0;           // program data confirmed by the node
    double seconds = 0;         // of the 1F50h transfer
    QString notes;              // what else happened, e.g. "drive on node 3 disabled"
    // One line for the CLI and the log.
    QString summary() const;
};

// Program download (CiA 302-3) to one node through the SDO client: optional reads of 1F56h,
// 1F57h and 100Ah before; a drive CoScope enabled on the node is disabled (6040h = 0, CiA 402-2
// §6.2.1) since stopping its application drops the motor; 1F51h = 0 stop program; 1F51h = 3
// clear program where the node takes it; 1F50h program data as a DOMAIN, by block transfer
// (CiA 301 §7.2.4.3.9) or segmented; 1F51h = 1 start program; the node's boot-up (CiA 301
// §7.2.8.3.3) as it resets into the new program; 1F56h, 1F57h and 100Ah read again.
//
// Never blocks: run() returns at once, progress and the outcome arrive on this thread. Nothing
// is retried on its own; retry() runs the same request again from the start ("resume from the
// start": CiA 302-3 has no way to continue a broken download).
class ProgramDownload : public QObject {
    Q_OBJECT
public:
    using StepCallback = std::function<void(ProgramStep step)>;
    using ProgressCallback = std::function<void(qint64 done, qint64 total, double bytesPerSecond)>;
    using Done = std::function<void(const ProgramDownloadOutcome&)>;

    ProgramDownload(MasterContext& context, SdoClient& sdo, QObject* parent = nullptr);
    ~ProgramDownload() override;

    // Reads what the node says now (1F56h, 1F57h, 100Ah); never fails, fields stay empty.
    void readState(uint8_t node, uint8_t program, std::function<void(const ProgramState&)> done);

    void run(const ProgramDownloadRequest& request, StepCallback step, ProgressCallback progress, Done done);
    void retry();  // the last request again, same callbacks
    // During the download: aborts the SDO transfer (08000000h); before it: stops after the step
    // in progress. After the start command it does nothing (the node is already resetting).
    void cancel();
    bool isRunning() const { return run_ != nullptr; }

private:
    struct Run;
    void next(ProgramStep step);
    void fail(ProgramStep step, const SdoResult& r, const QString& error = {});
    void finish(bool ok);
    void write(ProgramStep step, uint16_t index, uint8_t sub, QByteArray data,
               std::function<void(const SdoResult&)> then);
    void readInto(ProgramState* state, std::function<void()> then);
    void waitBootUp();

    MasterContext& context_;
    SdoClient& sdo_;
    std::shared_ptr<Run> run_;
    ProgramDownloadRequest lastRequest_;
    StepCallback lastStep_;
    ProgressCallback lastProgress_;
    Done lastDone_;
    QElapsedTimer sinceBrokenTransfer_;  // a 1F50h transfer ended by an abort (ours or the node's)
};

}  // namespace coscope::canopen
