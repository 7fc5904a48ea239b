// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/master/ProcessDataDock.h"
#include "core/canopen/RpdoMotion.h"
#include "core/od/NumberNotation.h"

#include "app/gui/session/Workspace.h"
#include "app/gui/wizards/ds402/Ds402Units.h"
#include "core/canopen/BusMaster.h"
#include "core/canopen/SdoClient.h"
#include "dissectors/SignalCatalog.h"

#include <QCheckBox>
#include <QComboBox>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QPointer>
#include <QPushButton>
#include <QScrollArea>
#include <QSpinBox>
#include <QTimer>
#include <QVBoxLayout>

#include <cmath>

namespace coscope::gui {

namespace {
// Controlword bits a technician sets by hand (CiA 402-2 §6.3.1 Table 26; bits 4-6 and 8 are
// mode specific: new set-point, change set immediately, absolute/relative in profile position).
struct CwBit {
    int bit;
    const char* name;
};
const CwBit kCwBits[] = {{0, QT_TRANSLATE_NOOP("coscope::gui::ProcessDataDock", "Switch on")},
                         {1, QT_TRANSLATE_NOOP("coscope::gui::ProcessDataDock", "Enable voltage")},
                         {2, QT_TRANSLATE_NOOP("coscope::gui::ProcessDataDock", "Quick stop (0 = active)")},
                         {3, QT_TRANSLATE_NOOP("coscope::gui::ProcessDataDock", "Enable operation")},
                         {4, QT_TRANSLATE_NOOP("coscope::gui::ProcessDataDock", "New set-point")},
                         {5, QT_TRANSLATE_NOOP("coscope::gui::ProcessDataDock", "Change set immediately")},
                         {6, QT_TRANSLATE_NOOP("coscope::gui::ProcessDataDock", "Relative")},
                         {7, QT_TRANSLATE_NOOP("coscope::gui::ProcessDataDock", "Fault reset")},
                         {8, QT_TRANSLATE_NOOP("coscope::gui::ProcessDataDock", "Halt")}};

bool isControlword(uint16_t index) { return index >= 0x6000 && index < 0xA000 && (index - 0x6000) % 0x800 == 0x40; }
}  // namespace

struct ProcessDataDock::Row {
    canopen::ProcessDataObject object;
    od::Unit unit;  // the dictionary's (factor 1 and no text: raw)
    QLineEdit* edit = nullptr;
    std::vector<QCheckBox*> bits;  // controlword
};

ProcessDataDock::ProcessDataDock(Workspace* workspace, QWidget* parent)
    : QDockWidget(tr("Process data"), parent), workspace_(workspace) {
    setObjectName(QStringLiteral("processDataDock"));
    auto* w = new QWidget(this);
    auto* v = new QVBoxLayout(w);
    reason_ = new QLabel(w);
    reason_->setWordWrap(true);
    reason_->setObjectName(QStringLiteral("processDataReason"));
    v->addWidget(reason_);
    auto* top = new QHBoxLayout;
    top->addWidget(new QLabel(tr("Node:"), w));
    node_ = new QComboBox(w);
    node_->setObjectName(QStringLiteral("processDataNode"));
    top->addWidget(node_);
    mode_ = new QComboBox(w);
    mode_->setObjectName(QStringLiteral("processDataMode"));
    mode_->addItem(tr("Send once"), int(canopen::ProcessData::Mode::Once));
    mode_->addItem(tr("On change"), int(canopen::ProcessData::Mode::OnChange));
    mode_->addItem(tr("Every N ms"), int(canopen::ProcessData::Mode::Every));
    mode_->addItem(tr("With each SYNC"), int(canopen::ProcessData::Mode::WithSync));
    top->addWidget(mode_);
    period_ = new QSpinBox(w);
    period_->setRange(1, 60000);
    period_->setValue(100);
    period_->setSuffix(tr(" ms"));
    top->addWidget(period_);
    start_ = new QPushButton(tr("Start"), w);
    start_->setObjectName(QStringLiteral("processDataStart"));
    start_->setCheckable(true);
    top->addWidget(start_);
    send_ = new QPushButton(tr("Send"), w);
    send_->setObjectName(QStringLiteral("processDataSend"));
    top->addWidget(send_);
    top->addStretch();
    v->addLayout(top);
    auto* scroll = new QScrollArea(w);
    scroll->setWidgetResizable(true);
    pdoArea_ = new QWidget(scroll);
    pdoLayout_ = new QVBoxLayout(pdoArea_);
    scroll->setWidget(pdoArea_);
    v->addWidget(scroll, 1);
    live_ = new QLabel(w);
    live_->setObjectName(QStringLiteral("processDataLive"));
    live_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    v->addWidget(live_);
    status_ = new QLabel(w);
    status_->setWordWrap(true);
    v->addWidget(status_);
    auto* buttons = new QHBoxLayout;
    arm_ = new QPushButton(tr("Arm motion…"), w);
    arm_->setObjectName(QStringLiteral("processDataArm"));
    hold_ = new QPushButton(tr("Hold to run"), w);
    hold_->setObjectName(QStringLiteral("processDataHold"));
    hold_->setMinimumHeight(40);
    hold_->setToolTip(
        tr("RPDOs with motion objects are sent only while this button is held down; releasing it sends halt and "
           "velocity 0."));
    buttons->addWidget(arm_);
    buttons->addWidget(hold_, 1);
    v->addLayout(buttons);
    setWidget(w);

    feed_ = new QTimer(this);
    feed_->setInterval(100);
    connect(feed_, &QTimer::timeout, this, [this] {
        if (data_ && hold_->isDown()) data_->feedHold();
    });
    poll_ = new QTimer(this);
    poll_->setInterval(200);
    connect(poll_, &QTimer::timeout, this, [this] {
        refreshNodes();
        refreshLive();
        updateEnabled();
    });
    poll_->start();
    connect(node_, &QComboBox::activated, this, [this] { showNode(); });
    connect(mode_, &QComboBox::activated, this, [this] {
        if (data_) data_->setMode(canopen::ProcessData::Mode(mode_->currentData().toInt()), period_->value());
        updateEnabled();
    });
    connect(period_, &QSpinBox::editingFinished, this, [this] {
        if (data_) data_->setMode(data_->mode(), period_->value());
    });
    connect(start_, &QPushButton::clicked, this, &ProcessDataDock::startStop);
    connect(send_, &QPushButton::clicked, this, &ProcessDataDock::sendOnce);
    connect(arm_, &QPushButton::clicked, this, &ProcessDataDock::arm);
    connect(hold_, &QPushButton::pressed, this, [this] {
        if (!data_ || !armed_) return;
        data_->feedHold();
        feed_->start();
    });
    connect(hold_, &QPushButton::released, this, [this] {
        feed_->stop();
        if (data_) data_->releaseHold();
    });
    updateEnabled();
}

ProcessDataDock::~ProcessDataDock() { setMaster(nullptr); }

void ProcessDataDock::setMaster(canopen::BusMaster* master) {
    if (master == master_) return;
    feed_->stop();
    data_.reset();  // sends the stopped values of what it sent
    disarm();
    master_ = master;
    if (master_) {
        data_ = std::make_unique<canopen::ProcessData>(master_->context(), master_->sync());
        connect(data_.get(), &canopen::ProcessData::sendFailed, this, &ProcessDataDock::showError);
        connect(data_.get(), &canopen::ProcessData::holdExpired, this,
                [this] { status_->setText(tr("Hold to run was not fed: the drive was sent halt and velocity 0.")); });
    }
    showNode();
}

void ProcessDataDock::refreshNodes() {
    QList<int> ids;
    for (const canopen::NodeInfo& n : workspace_->nodes().snapshot())
        if (!n.dictionary.isEmpty()) ids << n.node;
    QList<int> shown;
    for (int i = 0; i < node_->count(); ++i) shown << node_->itemData(i).toInt();
    if (ids == shown) return;
    const int current = node_->currentData().toInt();
    node_->clear();
    for (int id : ids) node_->addItem(tr("Node %1").arg(id), id);
    int at = node_->findData(current);
    // No choice yet: the first node whose dictionary maps an RPDO (a Delta maps none by default).
    for (int i = 0; at < 0 && i < node_->count(); ++i) {
        const auto info = workspace_->nodes().node(node_->itemData(i).toInt());
        const eds::DictionaryPtr d = info ? eds::DictionaryLibrary::shared().loadShared(info->dictionary) : nullptr;
        for (int n = 1; d && at < 0 && n <= 4; ++n)
            if (const auto l = canopen::rpdoLayout(*d, static_cast<uint8_t>(info->node), n);
                l && l->valid() && !l->entries.empty())
                at = i;
    }
    node_->setCurrentIndex(at >= 0 ? at : 0);
    if (node_->currentData().toInt() != current || !current) showNode();
}

void ProcessDataDock::showNode() {
    disarm();
    dictionary_.reset();
    const int node = node_->currentData().toInt();
    if (node > 0) {
        if (const auto info = workspace_->nodes().node(node)) dictionaryName_ = info->dictionary;
        QString error;
        dictionary_ = eds::DictionaryLibrary::shared().loadShared(dictionaryName_, nullptr, &error);
        if (!dictionary_)
            showError(tr("Node %1: its dictionary %2 could not be loaded: %3").arg(node).arg(dictionaryName_, error));
    }
    if (data_ && dictionary_) {
        QString error;
        if (!data_->setNode(static_cast<uint8_t>(node), *dictionary_, &error)) showError(error);
        data_->setMode(canopen::ProcessData::Mode(mode_->currentData().toInt()), period_->value());
        if (workspace_->sdo() && workspace_->canTransmit())
            data_->readValues(*workspace_->sdo(),
                              [this, self = QPointer<ProcessDataDock>(this)](const QStringList& failed) {
                                  if (!self) return;
                                  showValues();
                                  if (!failed.isEmpty())
                                      showError(tr("Could not read: %1").arg(failed.join(QStringLiteral("; "))));
                              });
    }
    rebuildRows();
    updateEnabled();
}

void ProcessDataDock::rebuildRows() {
    rows_.clear();
    for (QGroupBox* g : groups_) delete g;
    groups_.clear();
    if (!data_ || data_->pdos().empty() || !dictionary_) return;
    for (const canopen::ProcessDataPdo& pdo : data_->pdos()) {
        auto* box = new QGroupBox(tr("RPDO%1 (%2h)")
                                      .arg(pdo.layout.number)
                                      .arg(pdo.layout.canId(), 3, 16, QChar(u'0'))
                                      .toUpper()
                                      .replace(QStringLiteral("H)"), QStringLiteral("h)")),
                                  pdoArea_);
        box->setCheckable(true);
        box->setChecked(data_->isEnabled(pdo.layout.number));
        const int number = pdo.layout.number;
        connect(box, &QGroupBox::toggled, this, [this, number](bool on) {
            if (data_) data_->setEnabled(number, on);
        });
        auto* grid = new QGridLayout(box);
        int r = 0;
        for (const canopen::ProcessDataObject& o : pdo.objects) {
            if (o.dummy) continue;
            auto row = std::make_unique<Row>();
            row->object = o;
            if (const od::SubObject* s = dictionary_->entry(o.entry.index, o.entry.sub);
                s && s->unit && s->unit->factor > 0)
                row->unit = *s->unit;
            grid->addWidget(new QLabel(QStringLiteral("%1h %2")
                                           .arg(o.entry.index, 4, 16, QChar(u'0'))
                                           .toUpper()
                                           .replace(QStringLiteral("H "), QStringLiteral("h "))
                                           .arg(o.name),
                                       box),
                            r, 0);
            Row* raw = row.get();
            if (isControlword(o.entry.index)) {
                auto* bits = new QWidget(box);
                auto* bl = new QGridLayout(bits);
                bl->setContentsMargins(0, 0, 0, 0);
                int k = 0;
                for (const CwBit& b : kCwBits) {
                    auto* c = new QCheckBox(tr("%1 (bit %2)").arg(tr(b.name)).arg(b.bit), bits);
                    c->setObjectName(QStringLiteral("controlwordBit%1").arg(b.bit));
                    c->setProperty("bit", b.bit);
                    connect(c, &QCheckBox::clicked, this, [this, raw] { commitControlword(*raw); });
                    bl->addWidget(c, k / 3, k % 3);
                    row->bits.push_back(c);
                    ++k;
                }
                grid->addWidget(bits, r, 1);
            } else {
                row->edit = new QLineEdit(box);
                row->edit->setObjectName(
                    QStringLiteral("pdValue%1_%2").arg(o.entry.index, 4, 16, QChar(u'0')).arg(o.entry.sub));
                row->edit->setToolTip(row->unit.text.isEmpty() ? tr("Decimal, 0x1F or 1Fh")
                                                               : tr("In %1").arg(row->unit.text));
                connect(row->edit, &QLineEdit::editingFinished, this, [this, raw] { commit(*raw); });
                grid->addWidget(row->edit, r, 1);
                grid->addWidget(new QLabel(row->unit.text, box), r, 2);
            }
            rows_.push_back(std::move(row));
            ++r;
        }
        pdoLayout_->insertWidget(static_cast<int>(groups_.size()), box);
        groups_.push_back(box);
    }
    showValues();
}

void ProcessDataDock::showValues() {
    if (!data_) return;
    for (auto& row : rows_) {
        const auto v = data_->value(row->object.entry.index, row->object.entry.sub);
        if (!v) continue;
        if (row->edit) {
            if (row->unit.factor != 1.0 && !row->unit.text.isEmpty())
                row->edit->setText(QString::number(double(*v) * row->unit.factor, 'f', unitDecimals(row->unit)));
            else row->edit->setText(QString::number(*v));
        }
        for (QCheckBox* c : row->bits) c->setChecked((*v >> c->property("bit").toInt()) & 1);
    }
}

void ProcessDataDock::commit(Row& row) {
    if (!data_) return;
    const QString text = row.edit->text().trimmed();
    QString error;
    bool ok = false;
    const double shown = text.toDouble(&ok);
    bool set = false;
    if (ok && row.unit.factor != 1.0 && !row.unit.text.isEmpty())  // in the drive's unit: raw = shown / factor
        set = data_->setValue(row.object.entry.index, row.object.entry.sub, std::llround(shown / row.unit.factor),
                              &error);
    else set = data_->setValueText(row.object.entry.index, row.object.entry.sub, text, &error);
    if (!set) showError(error);
    else status_->clear();
}

void ProcessDataDock::commitControlword(Row& row) {
    if (!data_) return;
    int64_t v = data_->value(row.object.entry.index, row.object.entry.sub).value_or(0);
    for (QCheckBox* c : row.bits) {
        const int64_t bit = int64_t{1} << c->property("bit").toInt();
        v = c->isChecked() ? (v | bit) : (v & ~bit);
    }
    QString error;
    if (!data_->setValue(row.object.entry.index, row.object.entry.sub, v, &error)) showError(error);
}

void ProcessDataDock::refreshLive() {
    const int node = node_->currentData().toInt();
    const auto& rec = workspace_->signalRecorder();
    if (!rec || node <= 0) {
        live_->clear();
        return;
    }
    QStringList parts;
    for (const dissect::SignalInfo& s : rec->catalog()) {
        if (s.key.node != node || s.key.bit >= 0 || !s.pdo.startsWith(QStringLiteral("TPDO"))) continue;
        const auto buf = rec->buffer(s.key);
        const auto last = buf ? buf->last() : std::nullopt;
        if (!last) continue;
        const double raw = last->value;
        const od::Unit unit{s.rawUnit, s.rawFactor};
        // Statusword, error codes and other bit patterns in hex as CiA 301 writes them (README "Numbers").
        const QString hex =
            raw >= 0 ? od::hexValueText(s.key.index, s.key.sub, static_cast<uint64_t>(raw), 16) : QString();
        parts << QStringLiteral("%1: %2").arg(s.name, !hex.isEmpty()        ? hex
                                                      : s.rawUnit.isEmpty() ? QString::number(raw, 'g', 10)
                                                                            : inUnit(raw, unit));
    }
    live_->setText(parts.isEmpty() ? tr("TPDOs: no values seen yet (are they sent on SYNC?)")
                                   : tr("TPDOs: %1").arg(parts.join(QStringLiteral(" · "))));
}

void ProcessDataDock::updateEnabled() {
    QString why;
    if (!workspace_->isLive()) why = tr("No bus is connected.");
    else if (!workspace_->canTransmit()) why = tr("The bus is listen-only or not open: nothing can be sent.");
    else if (!data_) why = tr("The bus's master services are not available.");
    else if (node_->count() == 0)
        why = tr("No node with a dictionary is known yet: scan the network or assign a dictionary.");
    else if (!data_ || data_->pdos().empty()) why = tr("This node's dictionary maps no RPDO.");
    reason_->setText(why);
    reason_->setVisible(!why.isEmpty());
    const bool can = why.isEmpty();
    const auto mode = canopen::ProcessData::Mode(mode_->currentData().toInt());
    for (QGroupBox* g : groups_) g->setEnabled(can);
    mode_->setEnabled(can);
    period_->setEnabled(can && mode == canopen::ProcessData::Mode::Every);
    start_->setEnabled(can && mode != canopen::ProcessData::Mode::Once);
    start_->setChecked(data_ && data_->isRunning());
    start_->setText(data_ && data_->isRunning() ? tr("Stop") : tr("Start"));
    send_->setEnabled(can);
    bool motion = false;
    if (data_)
        for (const canopen::ProcessDataPdo& p : data_->pdos()) motion |= p.carriesMotion();
    arm_->setEnabled(can && motion && !armed_);
    hold_->setEnabled(can && armed_);
    if (!can && armed_) disarm();
}

void ProcessDataDock::startStop() {
    if (!data_) return;
    if (data_->isRunning()) {
        data_->stop();
    } else {
        data_->setMode(canopen::ProcessData::Mode(mode_->currentData().toInt()), period_->value());
        QString error;
        if (!data_->start(&error)) showError(error);
        else if (data_->mode() == canopen::ProcessData::Mode::WithSync && master_ && !master_->sync().isRunning())
            status_->setText(tr("Sent with each SYNC: start the SYNC producer (Bus menu) for frames to go out."));
    }
    updateEnabled();
}

void ProcessDataDock::sendOnce() {
    if (!data_) return;
    const auto mode = data_->mode();
    const bool running = data_->isRunning();
    data_->setMode(canopen::ProcessData::Mode::Once);
    QString error;
    if (!data_->start(&error)) showError(error);
    else status_->setText(tr("Sent."));
    data_->setMode(mode, period_->value());
    if (running) data_->start();
}

void ProcessDataDock::arm() {
    if (!data_) return;
    const int answer =
        QMessageBox::question(this, tr("Arm motion"),
                              tr("The RPDOs of node %1 carry motion objects (controlword, mode, targets). While \"Hold "
                                 "to run\" is held, they are sent with the values shown and "
                                 "the motor can move. Releasing the button sends halt and velocity 0.\n\nMake sure the "
                                 "axis is free to move. Arm?")
                                  .arg(data_->node()),
                              QMessageBox::Yes | QMessageBox::No, QMessageBox::No);
    armed_ = answer == QMessageBox::Yes;
    updateEnabled();
}

void ProcessDataDock::disarm() {
    armed_ = false;
    if (feed_) feed_->stop();
    if (data_) data_->releaseHold();
}

void ProcessDataDock::showError(const QString& message) {
    status_->setText(QStringLiteral("<span style='color:#b00020'>%1</span>").arg(message.toHtmlEscaped()));
}

QLineEdit* ProcessDataDock::editor(uint16_t index, uint8_t sub) const {
    for (const auto& r : rows_)
        if (r->object.entry.index == index && r->object.entry.sub == sub) return r->edit;
    return nullptr;
}

QCheckBox* ProcessDataDock::controlwordBit(int bit) const {
    for (const auto& r : rows_)
        for (QCheckBox* c : r->bits)
            if (c->property("bit").toInt() == bit) return c;
    return nullptr;
}

}  // namespace coscope::gui
