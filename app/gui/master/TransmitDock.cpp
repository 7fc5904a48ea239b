// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/master/TransmitDock.h"

#include "app/gui/language/CoreText.h"
#include "app/gui/master/TransmitModel.h"
#include "app/gui/session/Workspace.h"
#include "core/canopen/BusMaster.h"
#include "core/canopen/MasterContext.h"
#include "core/canopen/RpdoMotion.h"
#include "eds/DictionaryLibrary.h"

#include <QHBoxLayout>
#include <QHeaderView>
#include <QKeyEvent>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QPushButton>
#include <QTableView>
#include <QVBoxLayout>

#include <map>

#include <spdlog/spdlog.h>

namespace coscope::gui {

TransmitDock::TransmitDock(Workspace* workspace, QWidget* parent)
    : QDockWidget(tr("Transmit"), parent), workspace_(workspace) {
    setObjectName(QStringLiteral("TransmitDock"));
    auto* w = new QWidget(this);
    auto* root = new QVBoxLayout(w);
    root->setContentsMargins(4, 4, 4, 4);
    banner_ = new QLabel(w);
    banner_->setObjectName(QStringLiteral("transmitBanner"));
    banner_->setWordWrap(true);
    banner_->setStyleSheet(QStringLiteral("QLabel { background: #fff4ce; padding: 4px; }"));
    root->addWidget(banner_);

    body_ = new QWidget(w);
    auto* body = new QVBoxLayout(body_);
    body->setContentsMargins(0, 0, 0, 0);
    auto* input = new QHBoxLayout;
    frameEdit_ = new QLineEdit(body_);
    frameEdit_->setObjectName(QStringLiteral("transmitFrame"));
    frameEdit_->setPlaceholderText(
        tr("Frame in candump syntax, e.g. 601#4018100100000000, 123#R, 123##1AABB (CAN FD)"));
    frameEdit_->setClearButtonEnabled(true);
    input->addWidget(frameEdit_, 1);
    input->addWidget(new QLabel(tr("every"), body_));
    every_ = new QLineEdit(body_);
    every_->setObjectName(QStringLiteral("transmitEvery"));
    every_->setPlaceholderText(tr("once"));
    every_->setToolTip(tr("Period in ms, to the microsecond (0.5 = 500 µs); empty or 0 = sent once only"));
    every_->setMaximumWidth(80);
    input->addWidget(every_);
    input->addWidget(new QLabel(tr("ms"), body_));
    add_ = new QPushButton(tr("Add"), body_);
    add_->setObjectName(QStringLiteral("transmitAdd"));
    add_->setToolTip(tr("Add the frame to the list without sending it"));
    input->addWidget(add_);
    auto* sendTyped = new QPushButton(tr("Add and send"), body_);
    sendTyped->setObjectName(QStringLiteral("transmitAddSend"));
    sendTyped->setToolTip(tr("Add the frame to the list and send it (Enter)"));
    input->addWidget(sendTyped);
    body->addLayout(input);
    connect(add_, &QPushButton::clicked, this, [this] { addTyped(false); });
    connect(sendTyped, &QPushButton::clicked, this, [this] { addTyped(true); });
    connect(frameEdit_, &QLineEdit::returnPressed, this, [this] { addTyped(true); });
    connect(every_, &QLineEdit::returnPressed, this, [this] { addTyped(true); });

    model_ = new TransmitModel(this);
    view_ = new QTableView(body_);
    view_->setObjectName(QStringLiteral("transmitView"));
    view_->setModel(model_);
    view_->setSelectionBehavior(QAbstractItemView::SelectRows);
    view_->setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed |
                           QAbstractItemView::AnyKeyPressed);
    view_->verticalHeader()->hide();
    view_->horizontalHeader()->setStretchLastSection(true);
    view_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    view_->horizontalHeader()->setSectionResizeMode(TransmitModel::Data, QHeaderView::Interactive);
    view_->setColumnWidth(TransmitModel::Data, 190);
    view_->installEventFilter(this);
    body->addWidget(view_, 1);
    connect(model_, &TransmitModel::runToggled, this, &TransmitDock::setRunning);
    connect(model_, &TransmitModel::editRefused, this, &TransmitDock::showError);

    auto* buttons = new QHBoxLayout;
    send_ = new QPushButton(tr("Send selected"), body_);
    send_->setObjectName(QStringLiteral("transmitSend"));
    send_->setToolTip(tr("Send the selected rows once (Enter in the list)"));
    remove_ = new QPushButton(tr("Remove"), body_);
    remove_->setObjectName(QStringLiteral("transmitRemove"));
    remove_->setToolTip(tr("Remove the selected rows (Delete)"));
    stopAll_ = new QPushButton(tr("Stop all"), body_);
    stopAll_->setObjectName(QStringLiteral("transmitStopAll"));
    stopAll_->setToolTip(tr("Stop every periodic row"));
    status_ = new QLabel(body_);
    status_->setObjectName(QStringLiteral("transmitStatus"));
    buttons->addWidget(send_);
    buttons->addWidget(remove_);
    buttons->addWidget(stopAll_);
    buttons->addWidget(status_, 1);
    body->addLayout(buttons);
    connect(send_, &QPushButton::clicked, this, &TransmitDock::sendRows);
    connect(remove_, &QPushButton::clicked, this, &TransmitDock::removeRows);
    connect(stopAll_, &QPushButton::clicked, this, [this] {
        model_->list()->stopAll();
        emit message(tr("Every periodic frame stopped"));
    });
    root->addWidget(body_, 1);
    setWidget(w);
    // The bus's list goes with the bus: let go of it before (its rows are saved at every edit).
    connect(workspace_, &Workspace::aboutToDisconnect, this, [this] {
        boundList_ = nullptr;
        model_->rebind(nullptr);
    });
    connect(workspace_, &Workspace::sourceChanged, this, &TransmitDock::rebind);
    rebind();
    refresh();
}

void TransmitDock::rebind() {
    canopen::BusMaster* master = workspace_->busMaster();
    canopen::TransmitList* list = master ? &master->transmit() : nullptr;
    if (list == boundList_ && list == (model_->hasBus() ? model_->list() : nullptr)) return;
    boundList_ = list;
    confirmed_.clear();  // another bus: ask again before motion
    model_->rebind(list);
    refresh();
}

void TransmitDock::refresh() {
    canopen::BusMaster* master = workspace_->busMaster();
    if ((master ? &master->transmit() : nullptr) != boundList_) rebind();
    QString why;
    if (!workspace_->bus()) why = tr("Connect to a bus first: the frames below are kept and sent once a bus is open.");
    else if (workspace_->bus()->isListenOnly())
        why = tr("Listen-only connection: CoScope sends nothing, so the transmit list is disabled.");
    else if (!workspace_->canTransmit()) why = tr("The bus is not open: nothing can be sent now.");
    banner_->setText(why);
    banner_->setVisible(!why.isEmpty());
    const bool can = why.isEmpty();
    send_->setEnabled(can);
    stopAll_->setEnabled(model_->list()->runningCount() > 0);
    frameEdit_->setEnabled(!workspace_->bus() || !workspace_->bus()->isListenOnly());
    view_->setEnabled(!workspace_->bus() || !workspace_->bus()->isListenOnly());
    model_->refresh();
    const int running = model_->list()->runningCount();
    status_->setText(running ? tr("%n periodic frame(s) running", nullptr, running) : QString());
}

QList<int> TransmitDock::selectedRows() const {
    QList<int> rows;
    for (const QModelIndex& i : view_->selectionModel()->selectedRows()) rows << i.row();
    if (rows.isEmpty() && view_->currentIndex().isValid()) rows << view_->currentIndex().row();
    std::sort(rows.begin(), rows.end());
    return rows;
}

void TransmitDock::addTyped(bool sendNow) {
    QString error;
    const auto frame = canopen::TransmitList::parseFrame(frameEdit_->text().trimmed(), &error);
    if (!frame) return showError(tr("Cannot read “%1”: %2").arg(frameEdit_->text().trimmed(), coreText(error)));
    const auto period = TransmitModel::parsePeriodMs(every_->text());
    if (!period || (*period != 0 && *period < 100))
        return showError(tr("“%1” is not a period in ms (0 = once only, at least 0.1 ms)").arg(every_->text()));
    canopen::TransmitEntry e;
    e.frame = *frame;
    e.periodUs = *period;
    // The same frame and period already in the list: use that row (its count goes on).
    int row = -1;
    for (int r = 0; r < model_->rowCount(); ++r)
        if (model_->entry(r).frame == e.frame && model_->entry(r).periodUs == e.periodUs) row = r;
    if (row < 0) row = model_->addEntry(e);
    view_->selectRow(row);
    if (!sendNow) return;
    if (e.periodUs > 0) setRunning(row, true);
    else sendRows();
}

void TransmitDock::sendRows() {
    for (int row : selectedRows()) {
        if (!confirmMotion(row)) return;
        QString error;
        if (!model_->list()->sendOnce(row, &error)) return showError(tr("Not sent: %1").arg(coreText(error)));
    }
    model_->refresh();
}

void TransmitDock::setRunning(int row, bool on) {
    if (!on) {
        model_->list()->stop(row);
        model_->refresh();
        return;
    }
    if (model_->entry(row).periodUs == 0)
        return showError(tr("Give the row a period (Every, ms) to send it periodically"));
    if (!confirmMotion(row)) return model_->refresh();
    QString error;
    if (!model_->list()->start(row, &error)) showError(tr("Cannot send periodically: %1").arg(coreText(error)));
    model_->refresh();
}

void TransmitDock::removeRows() {
    const QList<int> rows = selectedRows();
    for (auto it = rows.rbegin(); it != rows.rend(); ++it) model_->removeEntry(*it);
}

bool TransmitDock::confirmMotion(int row) {
    const canopen::TransmitEntry e = model_->entry(row);
    const QString key = canopen::TransmitList::formatFrame(e.frame);
    if (confirmed_.count(key)) return true;
    std::map<int, eds::DictionaryPtr> dictionaries;
    std::map<int, bool> drives;
    for (const canopen::NodeInfo& n : workspace_->nodes().snapshot()) {
        if (!n.dictionary.isEmpty()) dictionaries[n.node] = eds::DictionaryLibrary::shared().loadShared(n.dictionary);
        drives[n.node] = n.deviceType && (*n.deviceType & 0xFFFF) == 402;  // CiA 402 device profile (1000h)
    }
    const auto aimed = canopen::rpdoAddressed(
        e.frame,
        [&](uint8_t node) -> const od::ObjectDictionary* {
            auto it = dictionaries.find(node);
            return it == dictionaries.end() ? nullptr : it->second.get();
        },
        [&](uint8_t node) { return drives.count(node) && drives[node]; });
    if (!aimed || !aimed->carriesMotion()) return true;
    QStringList objects;
    for (const canopen::PdoMapEntry& m : aimed->motion)
        objects << QStringLiteral("%1h").arg(QString::number(m.index, 16).toUpper());
    const QString what =
        aimed->mappingKnown
            ? tr("It is RPDO%1 of node %2, which carries %3: it can make the motor move.")
                  .arg(aimed->number)
                  .arg(aimed->node)
                  .arg(objects.join(QStringLiteral(", ")))
            : tr("It is RPDO%1 of node %2, a drive whose mapping CoScope does not know: it can make the motor move.")
                  .arg(aimed->number)
                  .arg(aimed->node);
    const auto answer = QMessageBox::question(
        this, tr("Send a motion command?"),
        tr("%1\n\nSend %2%3?").arg(what, key, e.periodUs ? tr(" every %1 ms").arg(e.periodUs / 1000.0) : QString()),
        QMessageBox::Yes | QMessageBox::No, QMessageBox::No);
    if (answer != QMessageBox::Yes) {
        emit message(tr("Not sent: %1").arg(key));
        return false;
    }
    spdlog::info("transmit: the user allowed {} (RPDO{} of node {}, motion)", key.toStdString(), aimed->number,
                 aimed->node);
    confirmed_.insert(key);
    noteControlword(e.frame, *aimed, dictionaries.count(aimed->node) ? dictionaries[aimed->node].get() : nullptr);
    return true;
}

// The controlword a frame carries to a drive goes into the bus's record of drives CoScope enabled
// (EnabledDrives), so that whatever closes the bus disables the drive first. With the mapping
// unknown the drive is taken as enabled (it may be).
void TransmitDock::noteControlword(const CanFrame& frame, const canopen::RpdoAddress& aimed,
                                   const od::ObjectDictionary* dictionary) {
    canopen::MasterContext* master = workspace_->master();
    if (!master) return;
    if (!aimed.mappingKnown || !dictionary) return master->enabledDrives().noteControlword(aimed.node, 0, 0x000F);
    const auto layout = canopen::rpdoLayout(*dictionary, aimed.node, aimed.number);
    if (!layout) return;
    int offset = 0;
    for (const canopen::PdoMapEntry& m : layout->entries) {
        const bool controlword = m.index >= 0x6000 && (m.index - 0x6000) % 0x800 == 0x40 && m.sub == 0 && m.bits == 16;
        if (controlword && offset % 8 == 0 && offset / 8 + 2 <= frame.payloadSize()) {
            const auto cw =
                static_cast<uint16_t>(frame.data[size_t(offset) / 8] | (frame.data[size_t(offset) / 8 + 1] << 8));
            if (canopen::EnabledDrives::enablesVoltage(cw))
                master->enabledDrives().noteControlword(aimed.node, (m.index - 0x6000) / 0x800, cw);
        }
        offset += m.bits;
    }
}

void TransmitDock::showError(const QString& text) {
    status_->setText(text);
    emit message(text);
}

bool TransmitDock::eventFilter(QObject* watched, QEvent* event) {
    // Keys typed into a cell editor go to the editor, not here.
    if (watched == view_ && event->type() == QEvent::KeyPress) {
        const int key = static_cast<QKeyEvent*>(event)->key();
        if (key == Qt::Key_Return || key == Qt::Key_Enter) {
            if (workspace_->canTransmit()) sendRows();
            return true;
        }
        if (key == Qt::Key_Delete) {
            removeRows();
            return true;
        }
    }
    return QDockWidget::eventFilter(watched, event);
}

}  // namespace coscope::gui
