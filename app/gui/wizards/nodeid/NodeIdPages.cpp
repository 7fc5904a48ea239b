// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/wizards/nodeid/NodeIdPages.h"

#include "app/gui/od/IntegerSpinBox.h"
#include "app/gui/session/Workspace.h"
#include "app/gui/wizards/common/ScriptPreview.h"
#include "app/gui/wizards/nodeid/NodeIdWizard.h"
#include "core/canopen/Lss.h"
#include "eds/DictionaryLibrary.h"

#include <QButtonGroup>
#include <QComboBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QRadioButton>
#include <QTableWidget>
#include <QTimer>
#include <QVBoxLayout>

namespace coscope::gui {

namespace {
QString stateText(int s) {
    // NMT states as reported by boot-up/heartbeat (CiA 301 Table 51).
    switch (s) {
    case 0: return QObject::tr("booting (boot-up)");
    case 4: return QObject::tr("stopped");
    case 5: return QObject::tr("running (operational)");
    case 127: return QObject::tr("ready (pre-operational)");
    default: return QObject::tr("seen");
    }
}
QVBoxLayout* framesSlot(QWidget* page) {
    auto* slot = new QVBoxLayout;
    slot->setObjectName(QStringLiteral("framesSlot"));
    slot->setContentsMargins(0, 0, 0, 0);
    (void)page;
    return slot;
}
QLabel* wrapped(QWidget* parent, const QString& text = {}) {
    auto* l = new QLabel(text, parent);
    l->setWordWrap(true);
    return l;
}
}  // namespace

// --- page 1 -------------------------------------------------------------------------------

NodeIdFindPage::NodeIdFindPage(NodeIdWizard* wizard) : QWizardPage(wizard), wizard_(wizard) {
    setTitle(tr("Find the device"));
    setSubTitle(tr("Pick the drive whose node-ID or baud rate (bit rate) you want to change."));
    auto* intro = wrapped(
        this,
        tr("These are the devices CoScope has seen on the bus. <b>Scan</b> asks every node-ID 1-127 for its device "
           "type "
           "and identity (SDO reads, changes nothing). A new device without node-ID (LSS-unconfigured) stays silent: "
           "<b>Find device without node-ID</b> finds it with LSS Fastscan (CiA 305)."));
    refusal_ = wrapped(this);
    refusal_->setObjectName(QStringLiteral("refusal"));
    refusal_->setStyleSheet(QStringLiteral("color:#a40000;font-weight:bold"));
    table_ = new QTableWidget(0, 3, this);
    table_->setObjectName(QStringLiteral("nodeList"));
    table_->setHorizontalHeaderLabels({tr("Node-ID"), tr("Device (dictionary)"), tr("State (NMT)")});
    table_->verticalHeader()->hide();
    table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
    table_->setSelectionBehavior(QAbstractItemView::SelectRows);
    table_->setSelectionMode(QAbstractItemView::SingleSelection);
    table_->horizontalHeader()->setStretchLastSection(true);
    table_->setColumnWidth(1, 260);
    table_->setMinimumHeight(120);
    connect(table_, &QTableWidget::itemSelectionChanged, this, [this] {
        const auto rows = table_->selectionModel()->selectedRows();
        if (rows.isEmpty()) return;
        const int node = table_->item(rows.front().row(), 0)->data(Qt::UserRole).toInt();
        if (node == wizard_->node()) return;
        dictionaryChosen_ = false;
        wizard_->selectNode(node);
    });
    scan_ = new QPushButton(tr("Scan the bus"), this);
    scan_->setObjectName(QStringLiteral("scan"));
    fastscan_ = new QPushButton(tr("Find device without node-ID (LSS Fastscan)"), this);
    fastscan_->setObjectName(QStringLiteral("fastscan"));
    status_ = wrapped(this);
    connect(scan_, &QPushButton::clicked, this, [this] {
        status_->setText(tr("Scanning node-IDs 1-127…"));
        wizard_->scan();
        refresh();
    });
    connect(fastscan_, &QPushButton::clicked, this, [this] {
        status_->setText(tr("LSS Fastscan: looking for a device without node-ID…"));
        wizard_->findUnconfigured();
    });
    connect(wizard_, &NodeIdWizard::scanFinished, this, [this] {
        status_->setText(
            tr("Scan finished: %n device(s) known.", nullptr, static_cast<int>(wizard_->knownNodes().size())));
        shownRevision_ = ~uint64_t(0);
        refresh();
    });
    connect(wizard_, &NodeIdWizard::fastscanFinished, this, [this](bool, const QString& message) {
        status_->setText(message);
        refresh();
    });
    dictionary_ = new QComboBox(this);
    dictionary_->setObjectName(QStringLiteral("dictionary"));
    dictionary_->addItem(tr("(unknown — LSS only)"), QString());
    for (const QString& name : eds::DictionaryLibrary().names()) dictionary_->addItem(name, name);
    connect(dictionary_, &QComboBox::activated, this, [this](int) {
        dictionaryChosen_ = true;  // the user's choice, even "(unknown)": a scan does not override it
        wizard_->setDictionary(dictionary_->currentData().toString());
    });
    target_ = wrapped(this);
    target_->setObjectName(QStringLiteral("target"));
    connect(wizard_, &NodeIdWizard::targetChanged, this, &NodeIdFindPage::refresh);

    auto* buttons = new QHBoxLayout;
    buttons->addWidget(scan_);
    buttons->addWidget(fastscan_);
    buttons->addStretch();
    auto* form = new QFormLayout;
    form->addRow(tr("Device type:"), dictionary_);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(intro);
    layout->addWidget(refusal_);
    layout->addWidget(table_, 1);
    layout->addLayout(buttons);
    layout->addWidget(status_);
    layout->addLayout(form);
    layout->addWidget(target_);
    layout->addLayout(framesSlot(this), 2);

    auto* timer = new QTimer(this);
    timer->setInterval(400);
    connect(timer, &QTimer::timeout, this, [this] {
        if (wizard_->currentPage() == this) refresh();  // the later pages hold what the user chose
    });
    timer->start();
}

bool NodeIdFindPage::isComplete() const { return wizard_->node() != 0 && wizard_->sendRefusal().isEmpty(); }

void NodeIdFindPage::refresh() {
    const QString refusal = wizard_->sendRefusal();
    refusal_->setText(refusal);
    refusal_->setVisible(!refusal.isEmpty());
    scan_->setEnabled(refusal.isEmpty() && !wizard_->isScanning() && !wizard_->isRunning());
    fastscan_->setEnabled(refusal.isEmpty() && !wizard_->isRunning());
    // Rebuild the list when the nodes or what is known about them changed.
    const auto nodes = wizard_->workspace()->nodes().snapshot();
    QString signature;
    for (const auto& n : nodes) signature += QStringLiteral("%1/%2/%3;").arg(n.node).arg(n.dictionary).arg(n.nmtState);
    const uint64_t rev = qHash(signature);
    if (rev != shownRevision_) {
        shownRevision_ = rev;
        QSignalBlocker block(table_);
        table_->setRowCount(static_cast<int>(nodes.size()));
        for (int i = 0; i < static_cast<int>(nodes.size()); ++i) {
            const auto& n = nodes[static_cast<size_t>(i)];
            auto* id = new QTableWidgetItem(QString::number(n.node));
            id->setData(Qt::UserRole, n.node);
            table_->setItem(i, 0, id);
            table_->setItem(
                i, 1, new QTableWidgetItem(n.dictionary.isEmpty() ? tr("(not identified — scan)") : n.dictionary));
            table_->setItem(i, 2, new QTableWidgetItem(stateText(n.nmtState)));
        }
    }
    if (wizard_->node() == 0 && !nodes.empty() && wizard_->sendRefusal().isEmpty()) {
        wizard_->selectNode(nodes.front().node);  // preselect the first node found
        return;
    }
    // The device type became known (identified by a scan) after the node was chosen.
    if (wizard_->node() != 0 && wizard_->node() != 0xFF && wizard_->dictionary().isEmpty() && !dictionaryChosen_ &&
        !wizard_->isRunning())
        if (const auto info = wizard_->workspace()->nodes().node(wizard_->node());
            info && !info->dictionary.isEmpty()) {
            wizard_->selectNode(wizard_->node());
            return;
        }
    {
        QSignalBlocker block(table_);
        for (int r = 0; r < table_->rowCount(); ++r)
            if (table_->item(r, 0)->data(Qt::UserRole).toInt() == wizard_->node()) table_->selectRow(r);
    }
    const int idx = dictionary_->findData(wizard_->dictionary());
    dictionary_->setCurrentIndex(idx < 0 ? 0 : idx);
    dictionary_->setEnabled(wizard_->node() != 0 && wizard_->node() != 0xFF);
    if (wizard_->node() == 0xFF) {
        target_->setText(tr("Target: the device without node-ID found by LSS Fastscan."));
    } else if (wizard_->node() != 0) {
        target_->setText(
            tr("Target: node %1%2.")
                .arg(wizard_->node())
                .arg(wizard_->dictionary().isEmpty() ? QString() : QStringLiteral(" (%1)").arg(wizard_->dictionary())));
    } else {
        target_->setText(tr("No device chosen yet."));
    }
    emit completeChanged();
}

// --- page 2 -------------------------------------------------------------------------------

NodeIdChangePage::NodeIdChangePage(NodeIdWizard* wizard) : QWizardPage(wizard), wizard_(wizard) {
    setTitle(tr("What to change"));
    setSubTitle(tr("The node-ID (the device's address on the bus, 1-127) or the baud rate (CAN bit rate)."));
    nodeId_ = new QRadioButton(tr("Node-ID"), this);
    nodeId_->setObjectName(QStringLiteral("changeNodeId"));
    bitRate_ = new QRadioButton(tr("Baud rate (bit rate)"), this);
    bitRate_->setObjectName(QStringLiteral("changeBitRate"));
    auto* what = new QButtonGroup(this);
    what->addButton(nodeId_);
    what->addButton(bitRate_);
    newId_ = new IntegerSpinBox(this);  // decimal, 0x1F or 1Fh (README "Numbers")
    newId_->setObjectName(QStringLiteral("newNodeId"));
    newId_->setRange(1, 127);
    newRate_ = new QComboBox(this);
    newRate_->setObjectName(QStringLiteral("newBitRate"));
    for (int rate : {1000000, 800000, 750000, 500000, 250000, 125000, 100000, 50000, 20000, 10000})
        newRate_->addItem(canopen::bitRateText(rate), rate);
    viaLss_ = new QRadioButton(tr("LSS (layer setting services, CiA 305) — works for any LSS-capable device"), this);
    viaLss_->setObjectName(QStringLiteral("viaLss"));
    viaVendor_ = new QRadioButton(this);
    viaVendor_->setObjectName(QStringLiteral("viaVendor"));
    auto* how = new QButtonGroup(this);
    how->addButton(viaLss_);
    how->addButton(viaVendor_);
    explanation_ = wrapped(this);
    explanation_->setObjectName(QStringLiteral("explanation"));
    explanation_->setTextFormat(Qt::RichText);
    problem_ = wrapped(this);
    problem_->setObjectName(QStringLiteral("problem"));
    problem_->setStyleSheet(QStringLiteral("color:#a40000;font-weight:bold"));

    // Each control sets only its own part of the request: a refresh caused by one of them
    // (targetChanged) must not put back the others' old values before they are read.
    connect(nodeId_, &QRadioButton::toggled, this, [this](bool on) {
        if (!updating_ && on) wizard_->setChange(NodeIdWizard::Change::NodeId);
    });
    connect(bitRate_, &QRadioButton::toggled, this, [this](bool on) {
        if (!updating_ && on) wizard_->setChange(NodeIdWizard::Change::BitRate);
    });
    connect(viaLss_, &QRadioButton::toggled, this, [this](bool on) {
        if (!updating_ && on) wizard_->setMethod(NodeIdWizard::Method::Lss);
    });
    connect(viaVendor_, &QRadioButton::toggled, this, [this](bool on) {
        if (!updating_ && on) wizard_->setMethod(NodeIdWizard::Method::Vendor);
    });
    connect(newId_, &IntegerSpinBox::valueChanged, this, [this](qint64 id) {
        if (!updating_) wizard_->setNewNodeId(static_cast<int>(id));
    });
    connect(newRate_, &QComboBox::currentIndexChanged, this, [this](int) {
        if (!updating_) wizard_->setNewBitRate(newRate_->currentData().toInt());
    });
    connect(wizard_, &NodeIdWizard::targetChanged, this, &NodeIdChangePage::refresh);

    auto* form = new QFormLayout;
    auto* whatRow = new QHBoxLayout;
    whatRow->addWidget(nodeId_);
    whatRow->addWidget(bitRate_);
    whatRow->addStretch();
    form->addRow(tr("Change:"), whatRow);
    form->addRow(tr("New node-ID:"), newId_);
    form->addRow(tr("New baud rate:"), newRate_);
    auto* howCol = new QVBoxLayout;
    howCol->addWidget(viaLss_);
    howCol->addWidget(viaVendor_);
    form->addRow(tr("How:"), howCol);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(explanation_);
    layout->addWidget(problem_);
    layout->addStretch();
    layout->addLayout(framesSlot(this), 1);
}

void NodeIdChangePage::initializePage() {
    // Suggest a free node-ID.
    if (wizard_->request().newNodeId == 0 && wizard_->request().change == NodeIdWizard::Change::NodeId) {
        const auto used = wizard_->knownNodes();
        for (int id = 1; id <= 127; ++id)
            if (std::find(used.begin(), used.end(), id) == used.end() && id != wizard_->node()) {
                wizard_->setNewNodeId(id);
                break;
            }
    }
    refresh();
}

void NodeIdChangePage::refresh() {
    // The controls show the request, which holds what the user chose: a control is set only
    // when the request differs from it (the wizard changed it: another device, a method this
    // device does not have), so what is being typed or scrolled is never put back.
    updating_ = true;
    const auto& r = wizard_->request();
    const bool unconfigured = wizard_->node() == 0xFF;
    if (nodeId_->isChecked() != (r.change == NodeIdWizard::Change::NodeId))
        nodeId_->setChecked(r.change == NodeIdWizard::Change::NodeId);
    if (bitRate_->isChecked() != (r.change == NodeIdWizard::Change::BitRate))
        bitRate_->setChecked(r.change == NodeIdWizard::Change::BitRate);
    bitRate_->setEnabled(!unconfigured);
    newId_->setEnabled(r.change == NodeIdWizard::Change::NodeId);
    if (r.newNodeId >= 1 && newId_->intValue() != r.newNodeId) newId_->setIntValue(r.newNodeId);
    newRate_->setEnabled(r.change == NodeIdWizard::Change::BitRate);
    if (const int i = newRate_->findData(r.newBitRate); i >= 0 && i != newRate_->currentIndex())
        newRate_->setCurrentIndex(i);
    const bool vendor = wizard_->vendorMethodAvailable();
    viaVendor_->setEnabled(vendor);
    viaVendor_->setText(
        vendor
            ? tr("The drive's own parameter %1 over SDO — as its manual describes").arg(wizard_->vendorParameterName())
            : tr("The drive's own parameter — none documented for this device"));
    if (viaLss_->isChecked() != (r.method == NodeIdWizard::Method::Lss))
        viaLss_->setChecked(r.method == NodeIdWizard::Method::Lss);
    if (viaVendor_->isChecked() != (r.method == NodeIdWizard::Method::Vendor))
        viaVendor_->setChecked(r.method == NodeIdWizard::Method::Vendor);
    explanation_->setText(wizard_->explanation());
    const QString problem = wizard_->blockingProblem();
    problem_->setText(problem);
    problem_->setVisible(!problem.isEmpty());
    updating_ = false;
    emit completeChanged();
}

bool NodeIdChangePage::isComplete() const {
    return wizard_->blockingProblem().isEmpty() && wizard_->sendRefusal().isEmpty();
}

// --- page 3 -------------------------------------------------------------------------------

QString NodeIdRunPage::dryRunSubTitle() {
    return tr("Dry run: nothing has been sent yet. This is exactly what CoScope will send, and why.");
}

NodeIdRunPage::NodeIdRunPage(NodeIdWizard* wizard) : QWizardPage(wizard), wizard_(wizard) {
    setTitle(tr("Check and change"));
    setSubTitle(dryRunSubTitle());
    intro_ = wrapped(this);
    preview_ = new ScriptPreview(this);
    preview_->setObjectName(QStringLiteral("nodeIdScript"));
    run_ = new QPushButton(tr("Change it now"), this);
    run_->setObjectName(QStringLiteral("runChange"));
    status_ = wrapped(this);
    status_->setObjectName(QStringLiteral("status"));
    status_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    connect(run_, &QPushButton::clicked, this, [this] {
        QString why;
        if (!wizard_->start(&why)) status_->setText(why);
        else
            setSubTitle(
                tr("Sending: CoScope runs the sequence below; each step turns green when the device has answered."));
        run_->setEnabled(false);
        emit completeChanged();
    });
    connect(wizard_, &NodeIdWizard::dryRunReady, this, [this](bool ok) {
        run_->setEnabled(ok && wizard_->sendRefusal().isEmpty());
        if (ok) {
            intro_->setText(tr("Takes effect: %1").arg(wizard_->plan()->takesEffect));
            status_->setText(wizard_->plan()->reconnect
                                 ? tr("CoScope will reconnect at %1 after the first part.")
                                       .arg(canopen::bitRateText(wizard_->plan()->reconnectBitRate))
                                 : QString());
        } else {
            intro_->clear();
            status_->setText(tr("Cannot prepare the change: %1").arg(wizard_->planError()));
        }
    });
    connect(wizard_, &NodeIdWizard::progress, this, [this](const QString& text) { status_->setText(text); });
    connect(wizard_, &NodeIdWizard::finished, this, [this](bool ok) {
        status_->setStyleSheet(ok ? QStringLiteral("color:#1d6b1d;font-weight:bold")
                                  : QStringLiteral("color:#a40000;font-weight:bold"));
        status_->setText(wizard_->outcomeText());
        setSubTitle(ok ? tr("Sent: the sequence below ran to the end. The device has its new setting.")
                       : tr("Stopped: the green steps below were sent, the red one failed, the rest was not sent."));
        emit completeChanged();
    });
    auto* row = new QHBoxLayout;
    row->addWidget(run_);
    row->addWidget(status_, 1);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(intro_);
    layout->addWidget(preview_, 2);
    layout->addLayout(row);
    layout->addLayout(framesSlot(this), 1);
}

void NodeIdRunPage::initializePage() {
    setSubTitle(dryRunSubTitle());
    status_->setStyleSheet(QString());
    status_->setText(tr("Preparing the sequence…"));
    run_->setEnabled(false);
    wizard_->prepareDryRun();
}

bool NodeIdRunPage::isComplete() const { return !wizard_->isRunning(); }

}  // namespace coscope::gui
