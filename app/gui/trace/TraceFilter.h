// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "app/gui/session/Job.h"
#include "app/gui/trace/FrameDecoder.h"
#include "app/gui/trace/SdoGroups.h"
#include "core/canopen/CobId.h"
#include "core/trace/TraceStore.h"

#include <QString>

#include <memory>
#include <optional>
#include <utility>
#include <vector>

namespace coscope::gui {

// Which frames the trace shows. Written by the user as words, all optional, combined with AND:
//   node:5,6   svc:sdo,emcy,tpdo1,nmt_ec   id:580-5FF,700   any other words = text in the summary
// Service words are the decode JSON names (NMT SYNC TIME EMCY TPDO1.. SDO_REQ SDO_RESP NMT_EC
// LSS_REQ LSS_RESP UNKNOWN), case-insensitive, plus "sdo", "pdo" and "tpdo"/"rpdo" as groups.
struct TraceFilter {
    std::vector<int> nodes;
    std::vector<canopen::Service> services;
    std::vector<std::pair<uint32_t, uint32_t>> idRanges;  // inclusive
    QString text;                                         // case-insensitive, in the summary

    bool isEmpty() const { return nodes.empty() && services.empty() && idRanges.empty() && text.isEmpty(); }
    bool needsDecoding() const { return !text.isEmpty(); }

    // A parse error names the word that is wrong.
    static std::optional<TraceFilter> parse(const QString& query, QString* error);

    // `scratch` is reused between calls; the decoder is only asked when text is set.
    bool matches(const TraceStore& store, FrameNo n, const FrameDecoder& decoder, dissect::Dissection& scratch) const;
};

// Frame numbers in [from, to) that match, or nullopt when cancelled.
std::optional<std::vector<FrameNo>> runFilter(const TraceStore& store, const TraceFilter& filter,
                                              const FrameDecoder& decoder, FrameNo from, FrameNo to,
                                              const std::function<bool(double)>& progress = {});

// A filter over a whole trace on a worker thread; result() once isDone() and not cancelled.
// With `groupSdo`, it also finds the SDO transfers and builds the grouped rows (TraceModel::setView).
class FilterJob : public Job {
public:
    FilterJob(std::shared_ptr<const TraceStore> store, TraceFilter filter, std::shared_ptr<const FrameDecoder> decoder,
              bool groupSdo = false);
    ~FilterJob() override;

    const TraceFilter& filter() const { return filter_; }
    // Frames scanned: [0, scannedUpTo()).
    FrameNo scannedUpTo() const { return upTo_; }
    std::vector<FrameNo> takeResult() { return std::move(result_); }
    bool groupsSdo() const { return groupSdo_; }
    std::shared_ptr<SdoGroupIndex> takeGroups() { return std::move(groups_); }
    GroupedRows takeGroupedRows() { return std::move(grouped_); }

protected:
    void run() override;

private:
    std::shared_ptr<const TraceStore> store_;
    TraceFilter filter_;
    std::shared_ptr<const FrameDecoder> decoder_;
    bool groupSdo_ = false;
    FrameNo upTo_ = 0;
    std::vector<FrameNo> result_;
    std::shared_ptr<SdoGroupIndex> groups_;
    GroupedRows grouped_;
};

}  // namespace coscope::gui
