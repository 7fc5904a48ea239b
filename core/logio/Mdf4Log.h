// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/logio/LogReader.h"
#include "core/logio/Mdf4Blocks.h"
#include "core/logio/Mdf4Channels.h"

#include <QDateTime>
#include <QTimeZone>

#include <map>
#include <memory>
#include <vector>

namespace coscope::logio {

// ASAM MDF 4.x bus logging (.mf4: CANedge, Vector, PEAK, Kvaser loggers), read only. The ID
// block ("MDF     ", or "UnFinMF " with unfinalised flags), the HD block's start time (ns
// since 1970, UTC) as the recording's wall clock, then each DG (data group) with its CGs
// (channel groups): the CAN_DataFrame, CAN_RemoteFrame and CAN_ErrorFrame groups of the
// bus-logging standard become frames (Mdf4Channels.h), other groups (LIN, signals) are skipped
// by their record size. Sorted (one CG, no record id) and unsorted (record ids of 1-8 bytes)
// data groups; DT, DL, DZ (deflate, transposition + deflate) and HL data (Mdf4Blocks.h);
// VLSD data bytes in SD blocks or in VLSD channel groups. Unfinalised files (a power loss):
// cycle counts are not trusted, the last DT block's data runs to the end of the file, a cut
// record at the end is reported. Frames come in time order: the data groups merged, then a
// window of 65536 frames sorted by time (a CANedge writes its Tx and Rx groups up to a second
// apart; equal times keep the file's order). Timestamps are the HD start time plus the master time
// channel (converted to seconds). Bus = CAN_DataFrame.BusChannel (1-based, as BLF).
// Diagnostics count records from 1 and name the byte offset of the block.
class Mdf4Reader : public LogReader {
public:
    Mdf4Reader();
    ~Mdf4Reader() override;
    QString formatName() const override { return QStringLiteral("mf4"); }
    // Start of the recording from the HD block (UTC; invalid before open()).
    QDateTime startTime() const { return QDateTime::fromMSecsSinceEpoch(startNs_ / 1000000).toUTC(); }
    int64_t startNs() const { return startNs_; }

protected:
    bool readHeader() override;
    size_t readFrames(CanFrame* out, size_t max) override;

private:
    struct Group;
    struct DataGroup;
    bool readDataGroup(uint64_t at, int number, bool unfinalisedData);
    // Next frame of `dg` into dg.next; false at its end.
    bool advance(DataGroup& dg);
    // Stores the VLSD record at the read position: 0 when done, the bytes it needs when the
    // data ends first, -1 when it cannot be read (the group ends).
    qsizetype storeVlsd(DataGroup& dg, Group& g);
    bool decode(DataGroup& dg, Group& g, const unsigned char* record, CanFrame& f);
    void endGroup(DataGroup& dg, const QString& why);

    struct Pending {
        CanFrame frame;
        uint64_t sequence = 0;
    };
    std::vector<Pending> window_;  // a heap, earliest first
    uint64_t sequence_ = 0;
    std::unique_ptr<mdf4::BlockFile> file_;
    std::vector<std::unique_ptr<DataGroup>> groups_;
    int64_t startNs_ = 0;
    uint64_t record_ = 0;
};

}  // namespace coscope::logio
