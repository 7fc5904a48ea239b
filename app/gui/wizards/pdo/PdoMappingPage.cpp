// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/wizards/pdo/PdoMappingPage.h"
#include "app/gui/language/CoreText.h"

#include "app/gui/wizards/pdo/PdoFrameLayout.h"
#include "app/gui/wizards/pdo/PdoWizard.h"
#include "dissectors/ObjectNames.h"
#include "dissectors/VendorTable.h"

#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPushButton>
#include <QTimer>
#include <QVBoxLayout>

namespace coscope::gui {

namespace {
constexpr int kEntryRole = Qt::UserRole + 1;  // PdoMapEntry::encode()
}

PdoMappingPage::PdoMappingPage(PdoWizard* wizard) : wizard_(wizard) {
    setTitle(tr("What the message carries"));
    setSubTitle(
        tr("Pick the values to put in the message, in the order they appear in the frame (the PDO mapping). "
           "Double-click or drag an object to the right; drag or use Up/Down to reorder. A frame holds at most 8 bytes "
           "(64 bits)."));
    search_ = new QLineEdit(this);
    search_->setObjectName(QStringLiteral("pdoSearch"));
    search_->setPlaceholderText(tr("Search by name or index, e.g. velocity or 606C"));
    search_->setClearButtonEnabled(true);
    available_ = new QListWidget(this);
    available_->setObjectName(QStringLiteral("pdoAvailable"));
    available_->setDragEnabled(true);
    available_->setDragDropMode(QAbstractItemView::DragOnly);
    available_->setDefaultDropAction(Qt::CopyAction);
    available_->setSelectionMode(QAbstractItemView::ExtendedSelection);
    mapped_ = new QListWidget(this);
    mapped_->setObjectName(QStringLiteral("pdoMapped"));
    mapped_->setDragDropMode(QAbstractItemView::DragDrop);
    mapped_->setDefaultDropAction(Qt::MoveAction);
    mapped_->setAcceptDrops(true);
    layout_ = new PdoFrameLayout(this);
    layout_->setObjectName(QStringLiteral("pdoFrameLayout"));
    summary_ = new QLabel(this);
    summary_->setWordWrap(true);

    auto* add = new QPushButton(tr("Add →"), this);
    auto* remove = new QPushButton(tr("← Remove"), this);
    auto* up = new QPushButton(tr("Up"), this);
    auto* down = new QPushButton(tr("Down"), this);
    auto* clear = new QPushButton(tr("Clear"), this);
    auto* restore = new QPushButton(tr("As in the drive"), this);
    restore->setToolTip(tr("Start again from the mapping read from the drive"));
    auto* buttons = new QVBoxLayout;
    buttons->addStretch();
    for (QPushButton* b : {add, remove, up, down, clear, restore}) buttons->addWidget(b);
    buttons->addStretch();

    auto* left = new QVBoxLayout;
    left->addWidget(new QLabel(tr("Objects this drive allows in the message:"), this));
    left->addWidget(search_);
    left->addWidget(available_);
    auto* right = new QVBoxLayout;
    right->addWidget(new QLabel(tr("In the message, in frame order:"), this));
    right->addWidget(mapped_);
    auto* lists = new QHBoxLayout;
    lists->addLayout(left, 3);
    lists->addLayout(buttons);
    lists->addLayout(right, 2);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(lists, 2);
    layout->addWidget(new QLabel(tr("The frame, byte by byte:"), this));
    layout->addWidget(layout_);
    layout->addWidget(summary_);
    auto* slot = new QVBoxLayout;
    slot->setObjectName(QStringLiteral("framesSlot"));
    layout->addLayout(slot, 1);

    connect(search_, &QLineEdit::textChanged, this, &PdoMappingPage::setFilter);
    connect(available_, &QListWidget::itemDoubleClicked, this, [this](QListWidgetItem* item) {
        const auto e = canopen::PdoMapEntry::decode(item->data(kEntryRole).toUInt());
        addObject(e.index, e.sub);
    });
    connect(add, &QPushButton::clicked, this, [this] {
        for (QListWidgetItem* item : available_->selectedItems()) {
            const auto e = canopen::PdoMapEntry::decode(item->data(kEntryRole).toUInt());
            addObject(e.index, e.sub);
        }
    });
    connect(remove, &QPushButton::clicked, this, [this] { removeAt(mapped_->currentRow()); });
    connect(up, &QPushButton::clicked, this, [this] { moveUp(mapped_->currentRow()); });
    connect(down, &QPushButton::clicked, this, [this] { moveDown(mapped_->currentRow()); });
    connect(clear, &QPushButton::clicked, this, &PdoMappingPage::clearMapping);
    connect(restore, &QPushButton::clicked, this, &PdoMappingPage::restoreCurrent);
    // A drop (from the left, or a move inside) changes the list's rows: read them back once
    // the drag has finished (a move inserts, then removes).
    auto queueSync = [this] {
        if (showing_ || syncQueued_) return;
        syncQueued_ = true;
        QTimer::singleShot(0, this, [this] {
            syncQueued_ = false;
            syncFromList();
        });
    };
    connect(mapped_->model(), &QAbstractItemModel::rowsInserted, this, queueSync);
    connect(mapped_->model(), &QAbstractItemModel::rowsRemoved, this, queueSync);
    connect(mapped_->model(), &QAbstractItemModel::rowsMoved, this, queueSync);
}

void PdoMappingPage::initializePage() {
    fillAvailable();
    showMapped();
}

bool PdoMappingPage::isComplete() const { return wizard_->state().wanted.totalBits() <= 64; }

int PdoMappingPage::availableCount() const {
    int n = 0;
    for (int i = 0; i < available_->count(); ++i) n += available_->item(i)->isHidden() ? 0 : 1;
    return n;
}
int PdoMappingPage::mappedCount() const { return mapped_->count(); }

void PdoMappingPage::fillAvailable() {
    available_->clear();
    const PdoWizardState& s = wizard_->state();
    if (!s.dictionary) {
        available_->addItem(tr("(no dictionary for this node: objects cannot be listed)"));
        available_->item(0)->setFlags(Qt::NoItemFlags);
        return;
    }
    for (const auto& [index, object] : s.dictionary->objects()) {
        for (const od::SubObject& sub : object.subs) {
            if (!sub.pdoMappable) continue;
            if (s.pdo.transmit ? !od::isReadable(sub.access) : !od::isWritable(sub.access)) continue;
            const int bits = od::bitSize(sub.dataType);
            if (bits <= 0 || bits > 64) continue;
            auto* item = new QListWidgetItem(
                tr("%1  (%2, %3 bits)").arg(s.objectName(index, sub.sub), od::dataTypeName(sub.dataType)).arg(bits),
                available_);
            item->setData(kEntryRole, canopen::PdoMapEntry{index, sub.sub, static_cast<uint8_t>(bits)}.encode());
            // The EDS's own name in the tooltip when the list shows the manual's (ObjectNames.h).
            const QString eds = s.dictionary->displayName(index, sub.sub);
            const QString shown =
                dissect::localDisplayName(*s.dictionary, index, sub.sub, dissect::vendorTextLanguage());
            item->setToolTip(
                tr("%1h:%2 — %3, access %4")
                    .arg(index, 4, 16, QChar(u'0'))
                    .arg(sub.sub, 2, 16, QChar(u'0'))
                    .arg(shown == eds ? eds : QStringLiteral("%1 (%2)").arg(shown, eds), od::accessName(sub.access)));
        }
    }
    setFilter(search_->text());
}

void PdoMappingPage::setFilter(const QString& text) {
    if (search_->text() != text) search_->setText(text);
    const QString t = text.trimmed();
    for (int i = 0; i < available_->count(); ++i) {
        QListWidgetItem* item = available_->item(i);
        item->setHidden(!t.isEmpty() && !item->text().contains(t, Qt::CaseInsensitive) &&
                        !item->toolTip().contains(t, Qt::CaseInsensitive));
    }
}

bool PdoMappingPage::addObject(uint16_t index, uint8_t sub, QString* why) {
    PdoWizardState& s = wizard_->state();
    std::vector<canopen::PdoMapEntry> one{{index, sub, 0}};
    QString error;
    if (!canopen::validatePdoMapping(one, s.pdo, s.dictionary.get(), &error)) {
        if (why) *why = error;
        summary_->setText(tr("Cannot add: %1").arg(coreText(error)));
        return false;
    }
    s.wanted.entries.push_back(one.front());
    showMapped();
    mapped_->setCurrentRow(mapped_->count() - 1);
    return true;
}

void PdoMappingPage::removeAt(int row) {
    auto& e = wizard_->state().wanted.entries;
    if (row < 0 || row >= static_cast<int>(e.size())) return;
    e.erase(e.begin() + row);
    showMapped();
    mapped_->setCurrentRow(std::min(row, mapped_->count() - 1));
}

void PdoMappingPage::moveUp(int row) {
    auto& e = wizard_->state().wanted.entries;
    if (row <= 0 || row >= static_cast<int>(e.size())) return;
    std::swap(e[static_cast<size_t>(row)], e[static_cast<size_t>(row - 1)]);
    showMapped();
    mapped_->setCurrentRow(row - 1);
}

void PdoMappingPage::moveDown(int row) {
    auto& e = wizard_->state().wanted.entries;
    if (row < 0 || row + 1 >= static_cast<int>(e.size())) return;
    std::swap(e[static_cast<size_t>(row)], e[static_cast<size_t>(row) + 1]);
    showMapped();
    mapped_->setCurrentRow(row + 1);
}

void PdoMappingPage::clearMapping() {
    wizard_->state().wanted.entries.clear();
    showMapped();
}

void PdoMappingPage::restoreCurrent() {
    wizard_->state().wanted.entries = wizard_->state().current.entries;
    showMapped();
}

void PdoMappingPage::showMapped() {
    const PdoWizardState& s = wizard_->state();
    showing_ = true;
    mapped_->clear();
    std::vector<PdoFrameLayout::Field> fields;
    int i = 0;
    for (const auto& e : s.wanted.entries) {
        auto* item = new QListWidgetItem(tr("%1  (%2 bits)").arg(s.objectName(e.index, e.sub)).arg(e.bits), mapped_);
        item->setData(kEntryRole, e.encode());
        item->setData(Qt::DecorationRole, PdoFrameLayout::colorFor(i++));
        QString label = s.objectName(e.index, e.sub);
        fields.push_back({label.replace(QStringLiteral("h:00 "), QStringLiteral("h ")), e.bits});
    }
    showing_ = false;
    layout_->setFields(std::move(fields));
    updateSummary();
}

void PdoMappingPage::syncFromList() {
    std::vector<canopen::PdoMapEntry> entries;
    for (int i = 0; i < mapped_->count(); ++i) {
        const QVariant v = mapped_->item(i)->data(kEntryRole);
        if (v.isValid()) entries.push_back(canopen::PdoMapEntry::decode(v.toUInt()));
    }
    wizard_->state().wanted.entries = std::move(entries);
    showMapped();
}

void PdoMappingPage::updateSummary() {
    const PdoWizardState& s = wizard_->state();
    const int bits = s.wanted.totalBits();
    QString text;
    if (bits > 64) text = tr("Too long: %1 bits. Remove objects until the total is 64 bits or less.").arg(bits);
    else if (s.wanted.entries.empty()) text = tr("Nothing mapped: the message would carry no data.");
    else if (s.wanted.entries == s.current.entries) text = tr("Same as in the drive now.");
    else
        text = tr("Changed: %1 objects, %2 bits (was %3 objects, %4 bits).")
                   .arg(s.wanted.entries.size())
                   .arg(bits)
                   .arg(s.current.entries.size())
                   .arg(s.current.totalBits());
    if (s.wanted.entries.size() > 8) text += tr(" Many drives allow at most 8 objects per PDO.");
    summary_->setText(text);
    emit completeChanged();
}

}  // namespace coscope::gui
