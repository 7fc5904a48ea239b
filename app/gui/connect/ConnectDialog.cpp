// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/connect/ConnectDialog.h"

#include "app/gui/connect/RecentConnections.h"
#include "app/gui/files/LastFolders.h"
#include "core/can/BusUrl.h"
#include "core/sim/Personality.h"
#include "core/sim/SimNetwork.h"

#include <QCanBus>
#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSpinBox>
#include <QStackedWidget>
#include <QTableWidget>
#include <QVBoxLayout>

#include <spdlog/spdlog.h>

namespace coscope::gui {

namespace {
enum Page { PluginPage, SocketcandPage, SimPage, ReplayPage };
const int kBitrates[] = {10000, 20000, 50000, 100000, 125000, 250000, 500000, 800000, 1000000};  // CiA 301 §7.1 table
}  // namespace

ConnectDialog::ConnectDialog(QWidget* parent) : QDialog(parent) {
    setWindowTitle(tr("Connect to a CAN bus"));
    setObjectName(QStringLiteral("ConnectDialog"));
    auto* layout = new QVBoxLayout(this);
    auto* form = new QFormLayout;
    recent_ = new QComboBox(this);
    recent_->setObjectName(QStringLiteral("recent"));
    recent_->addItem(tr("(recent connections)"));
    recent_->addItems(RecentConnections::list());
    connect(recent_, &QComboBox::activated, this, [this](int i) {
        if (i > 0) setUrl(recent_->itemText(i));
    });
    form->addRow(tr("Recent:"), recent_);
    linkJob_ = new SocketCanLinkJob(this);
    connect(linkJob_, &SocketCanLinkJob::listed, this, &ConnectDialog::onLinksListed);
    connect(linkJob_, &SocketCanLinkJob::broughtUp, this, &ConnectDialog::onBroughtUp);
    mayConfigure_ = mayConfigureLinks();
    backend_ = new QComboBox(this);
    backend_->setObjectName(QStringLiteral("backend"));
    backend_->addItem(tr("Virtual drives (sim://)"), QStringLiteral("sim"));
    backend_->addItem(tr("socketcand server (remote CAN)"), QStringLiteral("socketcand"));
    for (const QString& p : qtCanPlugins()) backend_->addItem(tr("Qt CAN plugin: %1").arg(p), p);
    backend_->addItem(tr("Replay a log file"), QStringLiteral("replay"));
    form->addRow(tr("Backend:"), backend_);
    layout->addLayout(form);

    pages_ = new QStackedWidget(this);
    {  // Qt plugin
        auto* w = new QWidget;
        auto* f = new QFormLayout(w);
        device_ = new QComboBox(w);
        device_->setObjectName(QStringLiteral("device"));
        device_->setEditable(true);
        f->addRow(tr("Device:"), device_);
        noDevices_ = new QLabel(w);
        noDevices_->setObjectName(QStringLiteral("noDevices"));
        noDevices_->setWordWrap(true);
        noDevices_->setTextInteractionFlags(Qt::TextSelectableByMouse);
        noDevices_->setText(
            tr("No CAN interfaces found. A virtual one for trying: <tt>sudo modprobe vcan; sudo ip link add dev vcan0 "
               "type vcan; sudo ip link set vcan0 up</tt>. A real adapter: <tt>sudo ip link set can0 up type can "
               "bitrate 500000</tt>. Then choose the backend again."));
        noDevices_->hide();
        f->addRow(noDevices_);
        linkState_ = new QLabel(w);
        linkState_->setObjectName(QStringLiteral("linkState"));
        linkState_->setWordWrap(true);
        linkState_->setTextInteractionFlags(Qt::TextSelectableByMouse);
        linkState_->hide();
        f->addRow(linkState_);
        bringUp_ = new QPushButton(tr("Bring up"), w);
        bringUp_->setObjectName(QStringLiteral("bringUp"));
        bringUp_->hide();
        connect(bringUp_, &QPushButton::clicked, this, &ConnectDialog::onBringUp);
        f->addRow(bringUp_);
        pages_->addWidget(w);
    }
    {  // socketcand
        auto* w = new QWidget;
        auto* f = new QFormLayout(w);
        host_ = new QLineEdit(QStringLiteral("127.0.0.1"), w);
        host_->setObjectName(QStringLiteral("host"));
        port_ = new QSpinBox(w);
        port_->setRange(1, 65535);
        port_->setValue(kSocketcandDefaultPort);
        channel_ = new QLineEdit(QStringLiteral("can0"), w);
        f->addRow(tr("Host:"), host_);
        f->addRow(tr("Port:"), port_);
        f->addRow(tr("Channel:"), channel_);
        pages_->addWidget(w);
    }
    {  // sim
        auto* w = new QWidget;
        auto* v = new QVBoxLayout(w);
        v->setContentsMargins(0, 0, 0, 0);
        v->addWidget(new QLabel(tr("Virtual drives on the in-process bus:"), w));
        drives_ = new QTableWidget(w);
        drives_->setObjectName(QStringLiteral("drives"));
        drives_->setColumnCount(2);
        drives_->setHorizontalHeaderLabels({tr("Drive (dictionary)"), tr("Node-ID")});
        drives_->horizontalHeader()->setSectionResizeMode(0, QHeaderView::Stretch);
        drives_->verticalHeader()->hide();
        const QStringList defaults = sim::SimNetwork::defaultSpec().split(u',');
        const QStringList dicts = sim::simulatableDictionaries();
        drives_->setRowCount(static_cast<int>(dicts.size()));
        for (int i = 0; i < dicts.size(); ++i) {
            auto* item = new QTableWidgetItem(dicts[i]);
            item->setFlags(Qt::ItemIsEnabled | Qt::ItemIsUserCheckable);
            int node = i + 1;
            bool on = false;
            for (const QString& d : defaults)
                if (d.section(u':', 1) == dicts[i]) {
                    on = true;
                    node = d.section(u':', 0, 0).toInt();
                }
            item->setCheckState(on ? Qt::Checked : Qt::Unchecked);
            drives_->setItem(i, 0, item);
            auto* spin = new QSpinBox(drives_);
            spin->setRange(1, 127);
            spin->setValue(node);
            connect(spin, &QSpinBox::valueChanged, this, &ConnectDialog::updatePreview);
            drives_->setCellWidget(i, 1, spin);
        }
        connect(drives_, &QTableWidget::itemChanged, this, &ConnectDialog::updatePreview);
        v->addWidget(drives_);
        pages_->addWidget(w);
    }
    {  // replay
        auto* w = new QWidget;
        auto* f = new QFormLayout(w);
        auto* h = new QHBoxLayout;
        replayPath_ = new QLineEdit(w);
        replayPath_->setObjectName(QStringLiteral("replayPath"));
        auto* browse = new QPushButton(tr("Browse…"), w);
        connect(browse, &QPushButton::clicked, this, [this] {
            const QString f = files::askOpenFile(this, files::kLogs, tr("Log to replay"));
            if (!f.isEmpty()) replayPath_->setText(f);
        });
        h->addWidget(replayPath_, 1);
        h->addWidget(browse);
        f->addRow(tr("Log:"), h);
        // replay://PATH?speed=S&loop=1 (DESIGN.md "Bus URLs"; core/can/ReplayBus.h): 0 = as fast as possible.
        auto* opts = new QHBoxLayout;
        replaySpeed_ = new QComboBox(w);
        replaySpeed_->setObjectName(QStringLiteral("replaySpeed"));
        replaySpeed_->addItem(tr("1×"), 1.0);
        replaySpeed_->addItem(tr("10×"), 10.0);
        replaySpeed_->addItem(tr("100×"), 100.0);
        replaySpeed_->addItem(tr("As fast as possible"), 0.0);
        replayLoop_ = new QCheckBox(tr("Loop"), w);
        replayLoop_->setObjectName(QStringLiteral("replayLoop"));
        opts->addWidget(replaySpeed_);
        opts->addWidget(replayLoop_);
        opts->addStretch(1);
        f->addRow(tr("Speed:"), opts);
        pages_->addWidget(w);
    }
    layout->addWidget(pages_);

    auto* opts = new QFormLayout;
    bitrate_ = new QComboBox(this);
    bitrate_->setObjectName(QStringLiteral("bitrate"));
    bitrate_->addItem(tr("(adapter setting)"), 0);
    for (int b : kBitrates) bitrate_->addItem(tr("%L1 kbit/s").arg(b / 1000), b);
    opts->addRow(tr("Bit rate:"), bitrate_);
    auto* fdRow = new QHBoxLayout;
    fd_ = new QCheckBox(tr("CAN FD"), this);
    dataBitrate_ = new QComboBox(this);
    for (int b : {1000000, 2000000, 4000000, 5000000, 8000000})
        dataBitrate_->addItem(tr("data %L1 Mbit/s").arg(b / 1000000), b);
    dataBitrate_->setCurrentIndex(1);
    dataBitrate_->setEnabled(false);
    fdRow->addWidget(fd_);
    fdRow->addWidget(dataBitrate_, 1);
    opts->addRow(QString(), fdRow);
    listenOnly_ = new QCheckBox(tr("Listen-only (never transmit)"), this);
    listenOnly_->setObjectName(QStringLiteral("listenOnly"));
    opts->addRow(QString(), listenOnly_);
    preview_ = new QLineEdit(this);
    preview_->setObjectName(QStringLiteral("urlPreview"));
    preview_->setToolTip(tr("Type or paste a bus URL, e.g. socketcan://can0?bitrate=500000"));
    connect(preview_, &QLineEdit::textEdited, this, &ConnectDialog::onUrlTyped);
    connect(preview_, &QLineEdit::returnPressed, this, &ConnectDialog::accept);
    opts->addRow(tr("URL:"), preview_);
    layout->addLayout(opts);
    error_ = new QLabel(this);
    error_->setStyleSheet(QStringLiteral("color: #b00020"));
    error_->setWordWrap(true);
    error_->hide();
    layout->addWidget(error_);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    buttons->button(QDialogButtonBox::Ok)->setText(tr("Connect"));
    connect(buttons, &QDialogButtonBox::accepted, this, &ConnectDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &ConnectDialog::reject);
    layout->addWidget(buttons);

    connect(backend_, &QComboBox::currentIndexChanged, this, &ConnectDialog::onBackendChanged);
    for (QComboBox* c : {device_, bitrate_, dataBitrate_, replaySpeed_})
        connect(c, &QComboBox::currentTextChanged, this, &ConnectDialog::updatePreview);
    for (QLineEdit* e : {host_, channel_, replayPath_})
        connect(e, &QLineEdit::textChanged, this, &ConnectDialog::updatePreview);
    connect(port_, &QSpinBox::valueChanged, this, &ConnectDialog::updatePreview);
    connect(fd_, &QCheckBox::toggled, this, [this](bool on) {
        dataBitrate_->setEnabled(on);
        updatePreview();
    });
    connect(listenOnly_, &QCheckBox::toggled, this, &ConnectDialog::updatePreview);
    connect(replayLoop_, &QCheckBox::toggled, this, &ConnectDialog::updatePreview);
    onBackendChanged();
    // Opens on the last connection used (its backend and settings), as the user left it.
    if (const QStringList recent = RecentConnections::list();
        !recent.isEmpty() && BusUrl::parse(recent.first(), nullptr))
        setUrl(recent.first());
    resize(520, 480);
}

void ConnectDialog::onBackendChanged() {
    const QString key = backend_->currentData().toString();
    if (key == u"sim") pages_->setCurrentIndex(SimPage);
    else if (key == u"socketcand") pages_->setCurrentIndex(SocketcandPage);
    else if (key == u"replay") pages_->setCurrentIndex(ReplayPage);
    else {
        pages_->setCurrentIndex(PluginPage);
        device_->clear();
        links_.clear();
        noDevices_->hide();
        QString error;
        for (const auto& info : QCanBus::instance()->availableDevices(key, &error)) device_->addItem(info.name());
        for (int i = 0; i < device_->count(); ++i)
            if (!pluginProbesHardware(key))
                device_->setItemData(i, tr("Listed by the plugin without finding an adapter"), Qt::ToolTipRole);
        if (device_->count() == 0) device_->setEditText(key == u"virtualcan" ? QStringLiteral("can0") : QString());
        // State and bit rate come from `ip`, off the GUI thread (onLinksListed).
        if (key == u"socketcan") linkJob_->list();
    }
    updatePreview();
}

void ConnectDialog::onLinksListed(const QList<SocketCanLink>& links, const QString& error) {
    if (backend_->currentData().toString() != u"socketcan") return;
    if (!error.isEmpty()) spdlog::info("listing CAN interfaces: {}", error.toStdString());
    links_ = links;
    const QString typed = device_->currentText();
    for (const SocketCanLink& l : links_)
        if (device_->findText(l.name) < 0) device_->addItem(l.name);
    for (int i = 0; i < device_->count(); ++i)
        for (const SocketCanLink& l : links_)
            if (l.name == device_->itemText(i)) device_->setItemData(i, linkText(l), Qt::ToolTipRole);
    if (!typed.isEmpty() && device_->findText(typed) >= 0) device_->setCurrentIndex(device_->findText(typed));
    noDevices_->setVisible(device_->count() == 0);
    updatePreview();
}

void ConnectDialog::onBringUp() {
    const QString name = device_->currentText().trimmed();
    for (const SocketCanLink& l : links_) {
        if (l.name != name) continue;
        const int wanted = bitrate_->currentData().toInt();
        bringUp_->setEnabled(false);
        linkJob_->bringUp(l, wanted > 0 ? wanted : (l.bitrate > 0 ? l.bitrate : 500000),
                          fd_->isChecked() ? dataBitrate_->currentData().toInt() : 0);
        return;
    }
}

void ConnectDialog::onBroughtUp(bool ok, const QString& error) {
    bringUp_->setEnabled(true);
    if (!ok) {
        error_->setText(tr("Could not bring the interface up: %1").arg(error));
        error_->show();
    }
    linkJob_->list();  // show the state the kernel reports now
}

QString ConnectDialog::url() const {
    if (!typed_.isEmpty()) return typed_.trimmed();
    const QString key = backend_->currentData().toString();
    QString target;
    QStringList options;
    if (key == u"sim") {
        QStringList nodes;
        for (int i = 0; i < drives_->rowCount(); ++i)
            if (drives_->item(i, 0)->checkState() == Qt::Checked)
                nodes << QStringLiteral("%1:%2")
                             .arg(static_cast<QSpinBox*>(drives_->cellWidget(i, 1))->value())
                             .arg(drives_->item(i, 0)->text());
        if (nodes.join(u',') != sim::SimNetwork::defaultSpec()) options << QStringLiteral("nodes=") + nodes.join(u',');
    } else if (key == u"socketcand") {
        target =
            QStringLiteral("%1:%2/%3").arg(host_->text().trimmed()).arg(port_->value()).arg(channel_->text().trimmed());
    } else if (key == u"replay") {
        target = replayPath_->text().trimmed();
    } else {
        target = device_->currentText().trimmed();
    }
    if (const int b = bitrate_->currentData().toInt(); b > 0 && key != u"replay")
        options << QStringLiteral("bitrate=%1").arg(b);
    if (fd_->isChecked())
        options << QStringLiteral("fd=1") << QStringLiteral("data-bitrate=%1").arg(dataBitrate_->currentData().toInt());
    if (listenOnly_->isChecked()) options << QStringLiteral("listen-only=1");
    if (key == u"replay") {
        if (const double speed = replaySpeed_->currentData().toDouble(); speed != 1.0)
            options << QStringLiteral("speed=%1").arg(speed);
        if (replayLoop_->isChecked()) options << QStringLiteral("loop=1");
    }
    QString s = key + QStringLiteral("://") + target;
    if (!options.isEmpty()) s += u'?' + options.join(u'&');
    return s;
}

void ConnectDialog::setUrl(const QString& text) {
    QString error;
    const auto u = BusUrl::parse(text, &error);
    if (!u) {
        error_->setText(error);
        error_->show();
        return;
    }
    const int i = backend_->findData(u->scheme);
    if (i >= 0) backend_->setCurrentIndex(i);
    if (u->scheme == u"socketcand") {
        host_->setText(u->host);
        port_->setValue(u->port ? u->port : kSocketcandDefaultPort);
        channel_->setText(u->channel);
    } else if (u->scheme == u"replay") {
        replayPath_->setText(u->target);
        const int sp = replaySpeed_->findData(u->speed());
        if (sp >= 0) replaySpeed_->setCurrentIndex(sp);
        replayLoop_->setChecked(u->loop());
    } else if (u->scheme == u"sim") {
        const QString spec = u->option(QStringLiteral("nodes"), sim::SimNetwork::defaultSpec());
        for (int r = 0; r < drives_->rowCount(); ++r) {
            drives_->item(r, 0)->setCheckState(Qt::Unchecked);
            for (const QString& d : spec.split(u','))
                if (d.section(u':', 1) == drives_->item(r, 0)->text()) {
                    drives_->item(r, 0)->setCheckState(Qt::Checked);
                    static_cast<QSpinBox*>(drives_->cellWidget(r, 1))->setValue(d.section(u':', 0, 0).toInt());
                }
        }
    } else {
        device_->setEditText(u->target);
    }
    const int b = bitrate_->findData(u->bitrate());
    bitrate_->setCurrentIndex(b >= 0 ? b : 0);
    fd_->setChecked(u->canFd());
    listenOnly_->setChecked(u->listenOnly());
    updatePreview();
}

void ConnectDialog::updatePreview() {
    updateLinkState();
    if (applyingTyped_) return;
    typed_.clear();
    preview_->setText(url());
    error_->hide();
}

QString ConnectDialog::linkText(const SocketCanLink& l) const {
    if (!l.up) return tr("%1 is down").arg(l.name);
    if (l.isVirtual()) return tr("%1 is up (virtual CAN)").arg(l.name);
    QString text =
        l.bitrate > 0 ? tr("%1 is up at %L2 kbit/s").arg(l.name).arg(l.bitrate / 1000.0) : tr("%1 is up").arg(l.name);
    if (l.dataBitrate > 0) text += tr(", CAN FD data %L1 Mbit/s").arg(l.dataBitrate / 1e6);
    // CiA 301 / ISO 11898-1 fault confinement: error active, warning, passive, bus-off.
    if (l.controllerState == u"ERROR-WARNING")
        text += tr(", controller in error warning (TEC %1, REC %2)").arg(l.txErrors).arg(l.rxErrors);
    else if (l.controllerState == u"ERROR-PASSIVE")
        text += tr(", controller error passive (TEC %1, REC %2)").arg(l.txErrors).arg(l.rxErrors);
    else if (l.controllerState == u"BUS-OFF")
        text += tr(", controller is bus-off: check wiring, termination and bit rate");
    else if (l.controllerState == u"STOPPED") text += tr(", controller stopped");
    return text;
}

void ConnectDialog::updateLinkState() {
    const QString key = backend_->currentData().toString();
    const QString name = device_->currentText().trimmed();
    QString text;
    bool offerBringUp = false;
    if (pages_->currentIndex() == PluginPage && !pluginProbesHardware(key) && device_->findText(name) >= 0) {
        text =
            tr("Unverified: the %1 plugin lists %2 without finding an adapter; connecting shows whether one is there.")
                .arg(key, name);
    } else if (key == u"socketcan") {
        for (const SocketCanLink& l : links_) {
            if (l.name != name) continue;
            const int wanted = bitrate_->currentData().toInt();
            const int wantedData = fd_->isChecked() ? dataBitrate_->currentData().toInt() : 0;
            text = linkText(l);
            const bool rateDiffers = !l.isVirtual() && wanted > 0 && wanted != l.bitrate;
            if (!l.up || rateDiffers) {
                text +=
                    QStringLiteral("<br>") + (l.up ? tr("To change its bit rate, run:") : tr("Bring it up with:")) +
                    QStringLiteral(" <tt>%1</tt>")
                        .arg(bringUpCommand(l, wanted > 0 ? wanted : (l.bitrate > 0 ? l.bitrate : 500000), wantedData)
                                 .toHtmlEscaped());
                offerBringUp = true;
                bringUp_->setText(l.up ? tr("Change bit rate now") : tr("Bring up now"));
            }
        }
    }
    // Runs the same command, without sudo, when this process may (CAP_NET_ADMIN).
    bringUp_->setVisible(offerBringUp);
    bringUp_->setEnabled(offerBringUp && mayConfigure_ && !linkJob_->busy());
    bringUp_->setToolTip(mayConfigure_ ? QString()
                                       : tr("CoScope runs without the right to configure network interfaces: run the "
                                            "command above in a terminal"));
    linkState_->setText(text);
    linkState_->setVisible(!text.isEmpty());
}

void ConnectDialog::onUrlTyped(const QString& text) {
    typed_ = text.trimmed();
    if (typed_.isEmpty()) return updatePreview();
    if (!BusUrl::parse(typed_, nullptr)) return;  // still being typed; accept() names what is wrong
    applyingTyped_ = true;
    setUrl(typed_);
    applyingTyped_ = false;
    error_->hide();
}

void ConnectDialog::accept() {
    QString error;
    if (!BusUrl::parse(url(), &error)) {
        error_->setText(error);
        error_->show();
        return;
    }
    if (backend_->currentData().toString() == u"sim") {
        bool any = false;
        for (int i = 0; i < drives_->rowCount(); ++i) any = any || drives_->item(i, 0)->checkState() == Qt::Checked;
        if (!any) {
            error_->setText(tr("Choose at least one virtual drive"));
            error_->show();
            return;
        }
    }
    QDialog::accept();
}

}  // namespace coscope::gui
