// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/trace/FrameDetailsView.h"

#include "app/gui/language/CoreText.h"
#include "app/gui/language/ObjectNameText.h"

#include "core/canopen/CobId.h"

#include <QFontDatabase>

#include <QHBoxLayout>
#include <QHeaderView>
#include <QSplitter>
#include <QTextEdit>
#include <QTreeWidget>
#include <algorithm>

namespace coscope::gui {

namespace {
constexpr int kOffsetRole = Qt::UserRole + 1;
constexpr int kLengthRole = Qt::UserRole + 2;
}  // namespace

FrameDetailsView::FrameDetailsView(QWidget* parent) : QWidget(parent) {
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    auto* split = new QSplitter(Qt::Horizontal, this);
    tree_ = new QTreeWidget(split);
    tree_->setObjectName(QStringLiteral("frameFields"));
    tree_->setColumnCount(3);
    tree_->setHeaderLabels({tr("Field"), tr("Value"), tr("Bytes")});
    tree_->header()->setSectionResizeMode(0, QHeaderView::ResizeToContents);
    tree_->header()->setSectionResizeMode(1, QHeaderView::Stretch);
    tree_->header()->setStretchLastSection(false);
    tree_->setAlternatingRowColors(true);
    hex_ = new QTextEdit(split);
    hex_->setObjectName(QStringLiteral("frameHex"));
    hex_->setReadOnly(true);
    hex_->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    split->addWidget(tree_);
    split->addWidget(hex_);
    split->setStretchFactor(0, 3);
    split->setStretchFactor(1, 1);
    layout->addWidget(split);
    connect(tree_, &QTreeWidget::currentItemChanged, this, [this](QTreeWidgetItem* item) {
        highlight_ =
            item ? std::pair{item->data(0, kOffsetRole).toInt(), item->data(0, kLengthRole).toInt()} : std::pair{0, 0};
        renderHex();
    });
}

void FrameDetailsView::clear() {
    frame_.reset();
    transferData_.clear();
    tree_->clear();
    hex_->clear();
    highlight_ = {0, 0};
}

void FrameDetailsView::showLoading() {
    clear();
    //: Details pane while the selected frame is read back from the capture journal on disk
    tree_->addTopLevelItem(new QTreeWidgetItem(QStringList{tr("Loading the frame back from the capture journal…")}));
}

void FrameDetailsView::showFrame(const CanFrame& f, uint64_t number) {
    dissect::Dissection d;
    d.reset(dissect::Dissection::Level::Tree);
    decoder_->decode(f, d);
    showDecoded(f, number, d);
}

void FrameDetailsView::showFrame(const TraceStore& store, FrameNo n) {
    dissect::Dissection d;
    d.reset(dissect::Dissection::Level::Tree);
    decoder_->decodeAt(store, n, d);
    showDecoded(store.frame(n), static_cast<uint64_t>(n) + 1, d);
}

void FrameDetailsView::showTransfer(const dissect::SdoTransferRecord& t, const std::vector<FrameNo>& frames) {
    frame_.reset();
    transferData_ = t.data;
    highlight_ = {0, 0};
    tree_->clear();
    const QString object =
        QStringLiteral("%1:%2").arg(t.index, 4, 16, QLatin1Char('0')).arg(t.sub, 2, 16, QLatin1Char('0')).toUpper();
    const QString name = localObjectName(t);
    auto* top = new QTreeWidgetItem(tree_, {tr("SDO transfer"), QStringLiteral("%1 %2").arg(object, name)});
    auto add = [top](const QString& label, const QString& value) { return new QTreeWidgetItem(top, {label, value}); };
    add(tr("Node"), QString::number(t.node));
    add(tr("Object"), name.isEmpty() ? object : QStringLiteral("%1 %2").arg(object, name));
    add(tr("Direction"), t.upload ? tr("upload (read from the server)") : tr("download (write to the server)"));
    add(tr("Mode"), t.block ? tr("block") : t.segmented ? tr("segmented") : tr("expedited"));
    add(tr("Size"), tr("%n byte(s)", nullptr, static_cast<int>(t.size)));
    if (!t.data.isEmpty()) {
        add(tr("Data"), QString::fromLatin1(t.data.left(64).toHex(' ').toUpper()) +
                            (t.data.size() > 64 ? QStringLiteral(" …") : QString()))
            ->setData(0, kLengthRole, static_cast<int>(t.data.size()));
    }
    if (!t.valueText.isEmpty()) add(tr("Value"), coreText(t.valueText));
    auto* status = add(tr("Status"), coreText(t.status));
    if (t.status != QLatin1String("ok")) status->setForeground(1, QColor(176, 0, 32));
    if (t.status == QLatin1String("aborted")) {
        add(tr("Abort code"), QStringLiteral("0x%1")
                                  .arg(t.abortCode, 8, 16, QLatin1Char('0'))
                                  .toUpper()
                                  .replace(QLatin1String("0X"), QLatin1String("0x")));
        add(tr("Abort reason"), coreText(t.abortText));
    }
    if (!frames.empty())
        add(tr("Frames"),
            frames.size() == 1
                ? tr("1 (frame %1)").arg(frames.front() + 1)
                : tr("%1 (frames %2–%3)").arg(frames.size()).arg(frames.front() + 1).arg(frames.back() + 1));
    add(tr("Duration"), QStringLiteral("%1 ms").arg(static_cast<double>(t.endNs - t.startNs) / 1e6, 0, 'f', 3));
    top->setExpanded(true);
    renderHex();
}

void FrameDetailsView::showDecoded(const CanFrame& f, uint64_t number, const dissect::Dissection& d) {
    frame_ = f;
    transferData_.clear();
    highlight_ = {0, 0};
    tree_->clear();

    // The dissectors write in English (shared with the CLI): shown in the UI language (CoreText.h).
    // Object names of a bundled dictionary in the UI language too (ObjectNameText.h).
    auto* top = new QTreeWidgetItem(tree_, {tr("Frame %1").arg(number), coreLines(localObjectNames(d, d.summary))});
    const QString id = f.isExtended() ? QStringLiteral("%1").arg(f.id, 8, 16, QLatin1Char('0')).toUpper()
                                      : QStringLiteral("%1").arg(f.id, 3, 16, QLatin1Char('0')).toUpper();
    new QTreeWidgetItem(top, {tr("Identifier"), tr("%1h (%2-bit)").arg(id).arg(f.isExtended() ? 29 : 11)});
    new QTreeWidgetItem(top, {tr("Service"), canopen::serviceName(d.service) +
                                                 (d.node >= 0 ? tr(", node %1").arg(d.node) : QString())});
    new QTreeWidgetItem(top,
                        {tr("Length"), QString::number(f.len) + (f.isRemote() ? tr(" (remote request)") : QString())});
    QStringList flags;
    if (f.isTx()) flags << tr("transmitted");
    if (f.isFd()) flags << QStringLiteral("CAN FD");
    if (f.flags & CanFrame::BitRateSwitch) flags << QStringLiteral("BRS");
    if (f.flags & CanFrame::ErrorState) flags << QStringLiteral("ESI");
    if (f.isError()) flags << tr("error frame");
    if (!flags.isEmpty()) new QTreeWidgetItem(top, {tr("Flags"), flags.join(QStringLiteral(", "))});
    for (const QString& w : d.warnings) {
        auto* item = new QTreeWidgetItem(top, {tr("Warning"), coreText(localObjectNames(d, w))});
        item->setForeground(1, QColor(176, 0, 32));
    }
    top->setExpanded(true);

    // The field tree: pre-order list with depths.
    std::vector<QTreeWidgetItem*> parents;
    for (const auto& t : d.tree) {
        parents.resize(static_cast<size_t>(t.depth));
        QTreeWidgetItem* item = parents.empty() ? new QTreeWidgetItem(tree_) : new QTreeWidgetItem(parents.back());
        item->setText(0, coreText(localObjectNames(d, t.label)));
        item->setText(1, coreLines(localObjectNames(d, t.value)));
        if (t.byteLength > 0) {
            QString where = t.byteLength == 1
                                ? tr("byte %1").arg(t.byteOffset)
                                : tr("bytes %1–%2").arg(t.byteOffset).arg(t.byteOffset + t.byteLength - 1);
            if (t.bitOffset >= 0)
                where += t.bitLength == 1 ? tr(", bit %1").arg(t.bitOffset)
                                          : tr(", bits %1–%2").arg(t.bitOffset).arg(t.bitOffset + t.bitLength - 1);
            item->setText(2, where);
        }
        item->setData(0, kOffsetRole, t.byteOffset);
        item->setData(0, kLengthRole, t.byteLength);
        item->setExpanded(true);
        parents.push_back(item);
    }
    renderHex();
}

void FrameDetailsView::renderHex() {
    if (!frame_ && transferData_.isEmpty()) {
        hex_->clear();
        return;
    }
    const auto* bytes = frame_ ? frame_->data.data() : reinterpret_cast<const uint8_t*>(transferData_.constData());
    const int len = frame_ ? frame_->payloadSize() : static_cast<int>(std::min<qsizetype>(transferData_.size(), 4096));
    QString html = QStringLiteral("<pre style='margin:0'>");
    for (int i = 0; i < len; ++i) {
        if (i % 8 == 0) html += QStringLiteral("%1  ").arg(i, frame_ ? 2 : 4, 16, QLatin1Char('0'));
        const bool hot = i >= highlight_.first && i < highlight_.first + highlight_.second;
        const QString byte = QStringLiteral("%1").arg(bytes[i], 2, 16, QLatin1Char('0')).toUpper();
        html += hot ? QStringLiteral("<span style='background:#ffd54f'>%1</span> ").arg(byte) : byte + QLatin1Char(' ');
        if (i % 8 == 7) html += QLatin1Char('\n');
    }
    if (len == 0) html += tr("(no payload)");
    html += QStringLiteral("</pre>");
    hex_->setHtml(html);
}

}  // namespace coscope::gui
