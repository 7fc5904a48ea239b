// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "app/gui/trace/FrameDecoder.h"
#include "core/can/CanFrame.h"

#include <QWidget>

#include <memory>
#include <optional>
#include <vector>

class QTextEdit;
class QTreeWidget;

namespace coscope::gui {

// Details of the selected frame: the decoder's field tree (with byte/bit positions) and a hex
// dump of the payload; selecting a field highlights its bytes in the dump.
class FrameDetailsView : public QWidget {
    Q_OBJECT
public:
    explicit FrameDetailsView(QWidget* parent = nullptr);

    void setDecoder(std::shared_ptr<const FrameDecoder> decoder) { decoder_ = std::move(decoder); }
    void showFrame(const CanFrame& frame, uint64_t number);  // decoded on its own
    // Frame n of the store, decoded in the context of the frames before it; shown as n + 1.
    void showFrame(const TraceStore& store, FrameNo n);
    // A reassembled SDO transfer (a grouped row): the record's fields; the dump shows its data.
    // `frames` are its frame numbers (0-based).
    void showTransfer(const dissect::SdoTransferRecord& t, const std::vector<FrameNo>& frames);
    void clear();
    // The frame or transfer shown next is being read back from the capture journal.
    void showLoading();

    QTreeWidget* tree() const { return tree_; }
    // The bytes highlighted now: [first, first + count).
    std::pair<int, int> highlighted() const { return highlight_; }

private:
    void renderHex();
    void showDecoded(const CanFrame& frame, uint64_t number, const dissect::Dissection& d);

    std::shared_ptr<const FrameDecoder> decoder_ = defaultFrameDecoder();
    QTreeWidget* tree_ = nullptr;
    QTextEdit* hex_ = nullptr;
    std::optional<CanFrame> frame_;
    QByteArray transferData_;  // shown in the dump when no frame is
    std::pair<int, int> highlight_{0, 0};
};

}  // namespace coscope::gui
