// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/wizards/pdo/PdoChoosePage.h"

#include "app/gui/session/Workspace.h"
#include "app/gui/wizards/common/WizardGuard.h"
#include "app/gui/wizards/pdo/PdoFrameLayout.h"
#include "app/gui/wizards/pdo/PdoVendorNotes.h"
#include "app/gui/wizards/pdo/PdoWizard.h"

#include <QComboBox>
#include <QFormLayout>
#include <QHeaderView>
#include <QLabel>
#include <QTimer>
#include <QTreeWidget>
#include <QVBoxLayout>

namespace coscope::gui {

PdoChoosePage::PdoChoosePage(PdoWizard* wizard) : wizard_(wizard) {
    setTitle(tr("Which drive and which message"));
    setSubTitle(
        tr("A PDO (process data object) is one CAN message that carries up to 8 bytes of live values. "
           "The drive sends its TPDOs (transmit PDOs, e.g. status and position) and receives its RPDOs (receive PDOs, "
           "e.g. commands)."));
    nodeBox_ = new QComboBox(this);
    nodeBox_->setObjectName(QStringLiteral("pdoNode"));
    pdoBox_ = new QComboBox(this);
    pdoBox_->setObjectName(QStringLiteral("pdoNumber"));
    for (int t = 1; t >= 0; --t)
        for (int n = 1; n <= 4; ++n) {
            const canopen::PdoId id{t == 1, n};
            pdoBox_->addItem(t ? tr("%1 — the drive sends (transmit PDO %2)").arg(id.name()).arg(n)
                               : tr("%1 — the drive receives (receive PDO %2)").arg(id.name()).arg(n),
                             (t ? 0 : 4) + n - 1);
        }
    status_ = new QLabel(this);
    status_->setObjectName(QStringLiteral("pdoReadStatus"));
    status_->setWordWrap(true);
    current_ = new QTreeWidget(this);
    current_->setObjectName(QStringLiteral("pdoCurrent"));
    current_->setHeaderLabels({tr("Byte"), tr("Object"), tr("Bits")});
    current_->setRootIsDecorated(false);
    current_->header()->setSectionResizeMode(1, QHeaderView::Stretch);
    layout_ = new PdoFrameLayout(this);
    notes_ = new QLabel(this);
    notes_->setObjectName(QStringLiteral("pdoVendorNotes"));
    notes_->setWordWrap(true);
    notes_->setTextFormat(Qt::RichText);

    auto* form = new QFormLayout;
    form->addRow(tr("Drive (node):"), nodeBox_);
    form->addRow(tr("Message (PDO):"), pdoBox_);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(new WizardGuard(wizard_->workspace(), this));
    layout->addLayout(form);
    layout->addWidget(status_);
    current_->setMinimumHeight(90);
    layout->addWidget(current_, 1);
    layout->addWidget(layout_);
    layout->addWidget(notes_);
    auto* slot = new QVBoxLayout;
    slot->setObjectName(QStringLiteral("framesSlot"));
    layout->addLayout(slot, 1);

    connect(nodeBox_, &QComboBox::currentIndexChanged, this, &PdoChoosePage::onSelectionChanged);
    connect(pdoBox_, &QComboBox::currentIndexChanged, this, &PdoChoosePage::onSelectionChanged);
    connect(wizard_, &PdoWizard::currentRead, this, [this] {
        showTarget();
        emit completeChanged();
    });
    nodesTimer_ = new QTimer(this);
    nodesTimer_->setInterval(500);
    connect(nodesTimer_, &QTimer::timeout, this, &PdoChoosePage::refreshNodes);
    nodesTimer_->start();
}

bool PdoChoosePage::isComplete() const { return wizard_->state().haveCurrent && !wizard_->isReading(); }

int PdoChoosePage::currentRows() const { return current_->topLevelItemCount(); }

void PdoChoosePage::refreshNodes() {
    const auto nodes = wizard_->workspace()->nodes().snapshot();
    const int selected = wizard_->state().node;
    QStringList labels;
    QList<int> ids;
    for (const canopen::NodeInfo& n : nodes) {
        labels << (n.dictionary.isEmpty()
                       ? tr("Node %1 (no dictionary)").arg(n.node)
                       : tr("Node %1 — %2%3")
                             .arg(n.node)
                             .arg(n.deviceName.isEmpty() ? n.dictionary : n.deviceName,
                                  n.deviceName.isEmpty() ? QString() : QStringLiteral(" (%1)").arg(n.dictionary)));
        ids << n.node;
    }
    if (selected > 0 && !ids.contains(selected)) {  // asked for a node the table does not list (yet)
        labels << tr("Node %1").arg(selected);
        ids << selected;
    }
    bool same = labels.size() == nodeBox_->count();
    for (int i = 0; same && i < labels.size(); ++i) same = nodeBox_->itemText(i) == labels[i];
    if (!same) {
        filling_ = true;
        nodeBox_->clear();
        for (int i = 0; i < labels.size(); ++i) nodeBox_->addItem(labels[i], ids[i]);
        nodeBox_->setCurrentIndex(static_cast<int>(ids.indexOf(selected)));
        filling_ = false;
    }
    // The node's dictionary became known (scan finished): take it.
    for (const canopen::NodeInfo& n : nodes)
        if (n.node == selected && !n.dictionary.isEmpty() && n.dictionary != wizard_->state().dictionaryName &&
            !wizard_->isApplying() && !wizard_->isReading()) {
            wizard_->selectTarget(n.node, wizard_->state().pdo);
            return;
        }
    // Preselect the first node with a dictionary when none was asked for.
    if (selected < 0) {
        for (const canopen::NodeInfo& n : nodes)
            if (!n.dictionary.isEmpty()) {
                wizard_->selectTarget(n.node, wizard_->state().pdo);
                return;
            }
    }
}

void PdoChoosePage::onSelectionChanged() {
    if (filling_) return;
    const int node = nodeBox_->currentData().toInt();
    const int p = pdoBox_->currentData().toInt();
    if (node <= 0) return;
    const canopen::PdoId pdo{p < 4, p % 4 + 1};
    if (node == wizard_->state().node && pdo.transmit == wizard_->state().pdo.transmit &&
        pdo.number == wizard_->state().pdo.number)
        return;
    wizard_->stopAutoPick();
    wizard_->selectTarget(node, pdo);
}

void PdoChoosePage::showTarget() {
    const PdoWizardState& s = wizard_->state();
    filling_ = true;
    for (int i = 0; i < nodeBox_->count(); ++i)
        if (nodeBox_->itemData(i).toInt() == s.node) nodeBox_->setCurrentIndex(i);
    pdoBox_->setCurrentIndex((s.pdo.transmit ? 0 : 4) + s.pdo.number - 1);
    filling_ = false;
    current_->clear();
    std::vector<PdoFrameLayout::Field> fields;
    const QString refusal = wizard_->sendRefusal();
    if (!refusal.isEmpty() && !s.haveCurrent) {
        status_->setText(refusal);
    } else if (s.node < 0) {
        status_->setText(tr("Waiting for a drive to appear on the bus…"));
    } else if (wizard_->isReading()) {
        status_->setText(tr("Reading %1 of node %2 from the drive (SDO upload of %3h and %4h)…")
                             .arg(s.pdo.name())
                             .arg(s.node)
                             .arg(s.pdo.communicationIndex(), 4, 16)
                             .arg(s.pdo.mappingIndex(), 4, 16));
    } else if (!s.haveCurrent) {
        status_->setText(
            tr("Could not read %1 of node %2: %3").arg(s.pdo.name()).arg(s.node).arg(wizard_->readError()));
    } else {
        const auto& c = s.current;
        const QString what = tr("CAN-ID %1h%2. %3. %4 of 64 bits used.")
                                 .arg(QString::number(c.cobId & 0x1FFFFFFF, 16).toUpper(),
                                      c.valid() ? QString() : tr(" (switched off: COB-ID bit 31 set)"),
                                      transmissionTypeText(c.transmissionType, s.pdo.transmit))
                                 .arg(c.totalBits());
        status_->setText(s.fromDictionary ? tr("Dry run (the bus is listen-only, nothing is sent): starting from the "
                                               "dictionary's defaults, not read from the drive: %1")
                                                .arg(what)
                                          : tr("Now in the drive: %1").arg(what));
        int bit = 0;
        for (const auto& e : c.entries) {
            auto* item = new QTreeWidgetItem(current_);
            const int first = bit / 8, last = (bit + std::max<int>(e.bits, 1) - 1) / 8;
            item->setText(0, first == last ? QString::number(first) : QStringLiteral("%1–%2").arg(first).arg(last));
            item->setText(1, s.objectName(e.index, e.sub));
            item->setText(2, QString::number(e.bits));
            item->setData(1, Qt::DecorationRole, PdoFrameLayout::colorFor(static_cast<int>(fields.size())));
            fields.push_back(
                {s.objectName(e.index, e.sub).replace(QStringLiteral("h:00 "), QStringLiteral("h ")), e.bits});
            bit += e.bits;
        }
        if (c.entries.empty()) {
            auto* item = new QTreeWidgetItem(current_);
            item->setText(1, tr("(nothing mapped: the message is empty)"));
        }
    }
    layout_->setFields(std::move(fields));
    layout_->setVisible(s.haveCurrent);
    const QStringList notes = pdoVendorNotes(s.dictionaryName, s.pdo);
    QStringList escaped;
    for (const QString& n : notes) escaped << n.toHtmlEscaped();
    notes_->setText(notes.isEmpty()
                        ? QString()
                        : QStringLiteral("<b>%1</b><ul><li>%2</li></ul>")
                              .arg(tr("Good to know about this drive:"), escaped.join(QStringLiteral("</li><li>"))));
    notes_->setVisible(!notes.isEmpty());
}

}  // namespace coscope::gui
