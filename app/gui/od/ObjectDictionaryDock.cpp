// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/od/ObjectDictionaryDock.h"

#include "app/gui/MenuTitle.h"
#include "app/gui/files/LastFolders.h"
#include "app/gui/od/OdFilterModel.h"
#include "app/gui/od/OdTreeModel.h"
#include "app/gui/od/OdValueDelegate.h"
#include "app/gui/session/Workspace.h"
#include "core/canopen/DeviceConfiguration.h"
#include "core/canopen/MasterContext.h"
#include "core/canopen/SdoClient.h"
#include "dissectors/ObjectNames.h"
#include "dissectors/VendorTable.h"
#include "eds/DictionaryLibrary.h"
#include "eds/EdsReader.h"

#include <QAction>
#include <QApplication>
#include <QCheckBox>
#include <QClipboard>
#include <QComboBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QMessageBox>
#include <QProgressBar>
#include <QPushButton>
#include <QToolBar>
#include <QTreeView>
#include <QVBoxLayout>

#include <spdlog/spdlog.h>

namespace coscope::gui {

ObjectDictionaryDock::ObjectDictionaryDock(Workspace* workspace, QWidget* parent)
    : QDockWidget(tr("Object Dictionary"), parent), workspace_(workspace) {
    setObjectName(QStringLiteral("ObjectDictionaryDock"));
    buildUi();
    rebind();
}

ObjectDictionaryDock::~ObjectDictionaryDock() = default;

void ObjectDictionaryDock::buildUi() {
    auto* root = new QWidget(this);
    auto* layout = new QVBoxLayout(root);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->setSpacing(3);

    header_ = new QLabel(root);
    header_->setObjectName(QStringLiteral("odHeader"));
    header_->setTextFormat(Qt::RichText);
    layout->addWidget(header_);

    auto* searchRow = new QHBoxLayout;
    search_ = new QLineEdit(root);
    search_->setObjectName(QStringLiteral("odSearch"));
    search_->setPlaceholderText(tr("Search index or name (6060, 0x1018, heartbeat)"));
    search_->setClearButtonEnabled(true);
    onlyChanged_ = new QCheckBox(tr("Only changed"), root);
    onlyChanged_->setToolTip(tr("Show only the values read from the node that differ from the dictionary's default"));
    searchRow->addWidget(search_, 1);
    searchRow->addWidget(onlyChanged_);
    layout->addLayout(searchRow);

    auto* bar = new QToolBar(root);
    bar->setIconSize(QSize(16, 16));
    bar->setToolButtonStyle(Qt::ToolButtonTextOnly);
    readAll_ = bar->addAction(tr("Read all"), this, [this] { readAll(); });
    readAll_->setObjectName(QStringLiteral("odReadAll"));
    readAll_->setToolTip(tr("Read every readable object of the node over SDO (DOMAINs are skipped)"));
    cancel_ = bar->addAction(tr("Cancel"), this, &ObjectDictionaryDock::cancelReadAll);
    progress_ = new QProgressBar(root);
    progress_->setObjectName(QStringLiteral("odProgress"));
    progress_->setMaximumHeight(16);
    progress_->setTextVisible(true);
    progress_->setFormat(QStringLiteral("%v / %m"));
    progress_->setMinimumWidth(90);
    bar->addWidget(progress_);
    bar->addSeparator();
    export_ = bar->addAction(tr("Export DCF…"), this, [this] {
        // The format by the filter: a DCF (CiA 306) or a concise DCF (CiA 302-3, 1F22h) as *.bin.
        const QString concise = tr("Concise DCF, CiA 302-3 (*.bin)");
        QString filter;
        QString path = files::askSaveFile(this, files::kDictionaries, tr("Export node %1 as DCF").arg(node_),
                                          QStringLiteral("node%1.dcf").arg(node_),
                                          tr("Device configuration (*.dcf)") + QStringLiteral(";;") + concise, &filter);
        if (filter == concise && !path.isEmpty() && !path.endsWith(QStringLiteral(".bin"), Qt::CaseInsensitive))
            path = (path.endsWith(QStringLiteral(".dcf"), Qt::CaseInsensitive) ? path.chopped(4) : path) +
                   QStringLiteral(".bin");
        if (!path.isEmpty()) exportDcf(path);
    });
    apply_ = bar->addAction(tr("Apply DCF…"), this, [this] {
        const QString path = files::askOpenFile(this, files::kDictionaries, tr("Apply a DCF to node %1").arg(node_),
                                                tr("Device configuration (*.dcf *.eds);;All files (*)"));
        if (!path.isEmpty()) applyDcf(path);
    });
    layout->addWidget(bar);

    // Shown instead of the tree when no dictionary is known for the node.
    noDictionary_ = new QWidget(root);
    auto* nd = new QVBoxLayout(noDictionary_);
    noDictionaryText_ = new QLabel(noDictionary_);
    noDictionaryText_->setWordWrap(true);
    auto* assignRow = new QHBoxLayout;
    dictChoice_ = new QComboBox(noDictionary_);
    dictChoice_->addItems(eds::DictionaryLibrary().names());
    auto* assign = new QPushButton(tr("Assign dictionary"), noDictionary_);
    connect(assign, &QPushButton::clicked, this, [this] { assignDictionary(dictChoice_->currentText()); });
    assignRow->addWidget(dictChoice_, 1);
    assignRow->addWidget(assign);
    nd->addWidget(noDictionaryText_);
    nd->addLayout(assignRow);
    nd->addStretch(1);
    layout->addWidget(noDictionary_, 1);

    model_ = new OdTreeModel(this);
    filter_ = new OdFilterModel(this);
    filter_->setSourceModel(model_);
    view_ = new QTreeView(root);
    view_->setObjectName(QStringLiteral("odTree"));
    view_->setModel(filter_);
    auto* delegate = new OdValueDelegate(model_, view_);
    view_->setItemDelegateForColumn(OdTreeModel::Value, delegate);
    connect(delegate, &OdValueDelegate::refused, this,
            [this](const QString& why) { showMessage(tr("Node %1: not written: %2").arg(node_).arg(why), true); });
    view_->setAlternatingRowColors(true);
    view_->setUniformRowHeights(true);
    view_->setSelectionBehavior(QAbstractItemView::SelectRows);
    view_->setEditTriggers(QAbstractItemView::EditKeyPressed | QAbstractItemView::SelectedClicked |
                           QAbstractItemView::DoubleClicked);
    view_->setContextMenuPolicy(Qt::CustomContextMenu);
    view_->header()->setStretchLastSection(false);
    view_->setColumnWidth(OdTreeModel::Object, 78);
    view_->setColumnWidth(OdTreeModel::Name, 190);
    view_->setColumnWidth(OdTreeModel::Value, 150);
    view_->setColumnWidth(OdTreeModel::Unit, 50);
    view_->setColumnWidth(OdTreeModel::Default, 110);
    view_->setColumnWidth(OdTreeModel::Type, 100);
    view_->setColumnWidth(OdTreeModel::Access, 50);
    view_->setColumnWidth(OdTreeModel::Pdo, 36);
    layout->addWidget(view_, 1);

    messageLine_ = new QLabel(root);
    messageLine_->setObjectName(QStringLiteral("odMessage"));
    messageLine_->setWordWrap(true);
    messageLine_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    layout->addWidget(messageLine_);
    setWidget(root);

    readSelected_ = new QAction(tr("Read"), this);
    connect(readSelected_, &QAction::triggered, this, [this] {
        const QModelIndex i = view_->currentIndex();
        if (i.isValid() && i.data(OdTreeModel::SubRole).toInt() >= 0)
            readEntry(static_cast<uint16_t>(i.data(OdTreeModel::IndexRole).toInt()),
                      static_cast<uint8_t>(i.data(OdTreeModel::SubRole).toInt()));
    });
    // F2 edits the value of the current row, whichever of its cells is current, while the focus
    // is in this dock (the trace's F2 jumps to its bookmarks only there).
    writeSelected_ = new QAction(tr("Write value…"), this);
    writeSelected_->setShortcut(QKeySequence(Qt::Key_F2));
    writeSelected_->setShortcutContext(Qt::WidgetWithChildrenShortcut);
    view_->addAction(writeSelected_);
    connect(writeSelected_, &QAction::triggered, this, [this] { editValue(view_->currentIndex()); });

    connect(search_, &QLineEdit::textChanged, this, [this](const QString& t) {
        filter_->setSearch(t);
        if (!t.isEmpty()) view_->expandAll();
    });
    connect(onlyChanged_, &QCheckBox::toggled, this, [this](bool on) {
        filter_->setOnlyChanged(on);
        if (on) view_->expandAll();
    });
    // Double-click: a writable value is edited (where users look for editing), any other entry read.
    connect(view_, &QTreeView::doubleClicked, this, [this](const QModelIndex& i) {
        if (i.data(OdTreeModel::SubRole).toInt() < 0) return;  // an ARRAY/RECORD row expands
        if (i.siblingAtColumn(OdTreeModel::Value).flags() & Qt::ItemIsEditable) {
            if (i.column() != OdTreeModel::Value) editValue(i);  // on the value itself the view edits
        } else
            readEntry(static_cast<uint16_t>(i.data(OdTreeModel::IndexRole).toInt()),
                      static_cast<uint8_t>(i.data(OdTreeModel::SubRole).toInt()));
    });
    connect(view_, &QWidget::customContextMenuRequested, this, &ObjectDictionaryDock::contextMenu);
    connect(model_, &OdTreeModel::writeRequested, this,
            [this](uint16_t index, uint8_t sub, const od::Value& v) { writeEntry(index, sub, v); });
}

void ObjectDictionaryDock::editValue(const QModelIndex& row) {
    if (!row.isValid() || row.data(OdTreeModel::SubRole).toInt() < 0) return;
    const QModelIndex value = row.siblingAtColumn(OdTreeModel::Value);
    if (value.flags() & Qt::ItemIsEditable) {
        view_->setCurrentIndex(value);
        view_->edit(value);
        return;
    }
    const auto index = static_cast<uint16_t>(row.data(OdTreeModel::IndexRole).toInt());
    const auto sub = static_cast<uint8_t>(row.data(OdTreeModel::SubRole).toInt());
    if (refuseIfOffline(tr("Write %1").arg(canopen::objectRef(index, sub)))) return;
    if (const od::SubObject* e = model_->dictionary().entry(index, sub); e && !od::isWritable(e->access))
        showMessage(tr("%1 %2 is %3: not writable")
                        .arg(canopen::objectRef(index, sub),
                             dissect::localDisplayName(model_->dictionary(), index, sub, dissect::vendorTextLanguage()),
                             od::accessName(e->access)),
                    true);
}

void ObjectDictionaryDock::contextMenu(const QPoint& pos) {
    const QModelIndex i = view_->indexAt(pos);
    const bool entry = i.isValid() && i.data(OdTreeModel::SubRole).toInt() >= 0;
    QMenu menu(this);
    if (entry) {
        const auto index = static_cast<uint16_t>(i.data(OdTreeModel::IndexRole).toInt());
        const auto sub = static_cast<uint8_t>(i.data(OdTreeModel::SubRole).toInt());
        const od::SubObject* e = model_->dictionary().entry(index, sub);
        addMenuTitle(menu, QStringLiteral("%1 %2").arg(canopen::objectRef(index, sub),
                                                       dissect::localDisplayName(model_->dictionary(), index, sub,
                                                                                 dissect::vendorTextLanguage())));
        readSelected_->setEnabled(canTransmit() && e && od::isReadable(e->access));
        writeSelected_->setEnabled(canTransmit() && e && od::isWritable(e->access));
        menu.addAction(readSelected_);
        menu.addAction(writeSelected_);
        const QString value = model_->actualText(index, sub);
        menu.addAction(tr("Copy value"), this, [value] { QApplication::clipboard()->setText(value); })
            ->setEnabled(!value.isEmpty());
        const QString error = model_->errorText(index, sub);
        if (!error.isEmpty())
            menu.addAction(tr("Copy error"), this, [error] { QApplication::clipboard()->setText(error); });
        menu.addSeparator();
    }
    menu.addAction(readAll_);
    menu.addAction(tr("Expand all"), view_, &QTreeView::expandAll);
    menu.addAction(tr("Collapse all"), view_, &QTreeView::collapseAll);
    if (!canTransmit())
        menu.addSection(workspace_->bus() && workspace_->bus()->isListenOnly() ? tr("Listen-only: SDO disabled")
                                                                               : tr("Not connected"));
    menu.exec(view_->viewport()->mapToGlobal(pos));
    updateEnabled();  // the menu enabled Read/Write for its entry; F2 works on any row again
}

bool ObjectDictionaryDock::canTransmit() const { return workspace_->canTransmit() && workspace_->sdo() != nullptr; }

void ObjectDictionaryDock::rebind() {
    ++generation_;
    delete config_;
    config_ = workspace_->sdo() ? new canopen::DeviceConfiguration(*workspace_->sdo(), this) : nullptr;
    pendingExport_.clear();
    readAllFinished_ = false;
    autoReadDone_ = false;
    resetProgress();
    kept_.clear();  // values read over the bus before: start again
    watchSdo();
    if (store_.lock() != workspace_->store()) {
        // Another bus or log: nothing of the previous one stays on screen.
        store_ = workspace_->store();
        node_ = -1;
        autoPicked_ = false;
        dictName_.clear();
        model_->clear();
        setMessageLine({}, false);
    } else if (model_->hasDictionary()) {
        // Disconnected: the node stays selected; its values were read over that bus: start again.
        model_->setDictionary(model_->dictionary(), model_->node());
    }
    lastCanTransmit_ = !canTransmit();  // force updateEnabled
    updateEnabled();
}

void ObjectDictionaryDock::setNode(int node) {
    if (node == node_) return;
    const int previous = node_;
    if (previous > 0 && model_->hasDictionary())
        kept_[previous] = {dictName_, model_->values(), messageLine_->text(), messageIsError_, {}};
    node_ = node;
    autoPicked_ = false;
    autoReadDone_ = false;
    readAllFinished_ = false;
    ++generation_;
    const bool stopped = config_ && config_->isRunning();
    if (stopped) config_->cancel();
    resetProgress();  // the bar counts this node's reads only
    dictName_.clear();
    model_->clear();
    loadDictionary();
    // The status line is the shown node's: its last message, or none.
    const auto kept = kept_.find(node_);
    const bool restore = kept != kept_.end() && kept->second.dictionary == dictName_ && model_->hasDictionary();
    if (restore) {
        model_->setValues(kept->second.values);
        applyWritten(kept->second);
    }
    setMessageLine(restore ? kept->second.message : QString(), restore && kept->second.messageIsError);
    if (stopped) showMessage(tr("Reading node %1 stopped: another node was chosen").arg(previous));
    updateHeader();
}

void ObjectDictionaryDock::resetProgress() {
    progress_->setRange(0, 1);
    progress_->reset();  // empty: no "n / m" text
}

void ObjectDictionaryDock::loadDictionary() {
    if (node_ <= 0) {
        updateHeader();
        updateEnabled();
        return;
    }
    const auto info = workspace_->nodes().node(node_);
    const QString name = info ? info->dictionary : QString();
    if (name == dictName_ && (name.isEmpty() || model_->hasDictionary())) {
        updateHeader();
        updateEnabled();
        return;
    }
    dictName_ = name;
    model_->clear();
    if (!name.isEmpty()) {
        auto it = dictionaryCache_.find(name);
        if (it == dictionaryCache_.end()) {
            eds::ReadResult r = eds::loadDictionaryByPathOrName(name);
            if (!r.usable) {
                showMessage(tr("Dictionary %1 of node %2 cannot be loaded").arg(name).arg(node_), true);
                dictName_.clear();
            } else {
                it = dictionaryCache_.emplace(name, std::move(r.dictionary)).first;
            }
        }
        if (it != dictionaryCache_.end()) model_->setDictionary(it->second, static_cast<uint8_t>(node_));
    }
    ++generation_;
    updateHeader();
    updateEnabled();
}

void ObjectDictionaryDock::assignDictionary(const QString& name) {
    if (node_ <= 0 || name.isEmpty()) return;
    // As the Nodes dock does: the node table and the master services' abort texts.
    workspace_->nodes().setDictionary(node_, name);
    if (workspace_->master()) workspace_->master()->setNodeDictionary(static_cast<uint8_t>(node_), name);
    workspace_->syncDictionaries();
    loadDictionary();
    showMessage(tr("Node %1 uses dictionary %2").arg(node_).arg(name));
}

void ObjectDictionaryDock::refresh() {
    // With no node chosen, show the first identified node of the network (and on the simulated
    // network read its values: reading a real device is the user's decision).
    if (node_ < 0 && isVisible()) {
        for (const canopen::NodeInfo& n : workspace_->nodes().snapshot())
            if (!n.dictionary.isEmpty() && n.seenHeartbeat) {
                setNode(n.node);
                autoPicked_ = true;
                break;
            }
    }
    followMoves();
    if (node_ > 0) {
        const auto info = workspace_->nodes().node(node_);
        if (info && info->dictionary != dictName_) loadDictionary();
        if (autoPicked_ && !autoReadDone_ && model_->hasDictionary() && canTransmit() &&
            workspace_->bus()->url().scheme == u"sim" && !isBusy()) {
            autoReadDone_ = true;
            readAll();
        }
    }
    // Also once a read ends whose answers were dropped (another node chosen meanwhile).
    if (lastCanTransmit_ != canTransmit() || isBusy() || lastBusy_) updateEnabled();
}

bool ObjectDictionaryDock::hasContent() const {
    return model_->hasDictionary() && readAllFinished_ && model_->valuesRead() > 0;
}

bool ObjectDictionaryDock::isBusy() const { return config_ && config_->isRunning(); }

void ObjectDictionaryDock::updateHeader() {
    if (node_ <= 0) {
        header_->setText(tr("<b>No node selected</b> — pick one in the Nodes dock"));
        noDictionaryText_->setText(tr("Select a node in the Nodes dock to see its object dictionary."));
        noDictionary_->setVisible(true);
        view_->setVisible(false);
        return;
    }
    const auto info = workspace_->nodes().node(node_);
    QString text = tr("<b>Node %1</b>").arg(node_);
    if (info && !info->deviceName.isEmpty()) text += QStringLiteral(" · %1").arg(info->deviceName.toHtmlEscaped());
    text += dictName_.isEmpty() ? tr(" · <span style='color:#b00020'>no dictionary</span>")
                                : QStringLiteral(" · %1").arg(dictName_.toHtmlEscaped());
    if (model_->hasDictionary())
        text += tr(" · %1 entries, %2 read").arg(model_->entryCount()).arg(model_->valuesRead());
    if (!canTransmit())
        text += workspace_->bus() && workspace_->bus()->isListenOnly() ? tr(" · <i>listen-only: no SDO</i>")
                                                                       : tr(" · <i>offline: no SDO</i>");
    header_->setText(text);
    const bool have = model_->hasDictionary();
    noDictionary_->setVisible(!have);
    view_->setVisible(have);
    if (!have)
        noDictionaryText_->setText(
            tr("No dictionary is known for node %1: it was not identified (1018h) or matched none in the library. "
               "Assign one to see its objects.")
                .arg(node_));
}

void ObjectDictionaryDock::updateEnabled() {
    const bool can = canTransmit();
    lastCanTransmit_ = can;
    const bool have = model_->hasDictionary();
    const bool busy = isBusy();
    lastBusy_ = busy;
    model_->setWritable(can);
    readAll_->setEnabled(can && have && !busy);
    cancel_->setEnabled(busy);
    apply_->setEnabled(can && have && !busy);
    export_->setEnabled(have && !busy && (can || model_->valuesRead() > 0));
    readSelected_->setEnabled(can && have);
    writeSelected_->setEnabled(can && have);
    updateHeader();
}

void ObjectDictionaryDock::setMessageLine(const QString& text, bool error) {
    messageIsError_ = error;
    messageLine_->setStyleSheet(error ? QStringLiteral("color: #b00020;") : QString());
    messageLine_->setText(text);
    messageLine_->setToolTip(text);
}

void ObjectDictionaryDock::showMessage(const QString& text, bool error) {
    setMessageLine(text, error);
    if (error) spdlog::warn("{}", text.toStdString());
    emit message(text);
}

QString ObjectDictionaryDock::messageText() const { return messageLine_->text(); }

bool ObjectDictionaryDock::confirm(const QString& title, const QString& question) {
    if (autoConfirm_) return true;
    return QMessageBox::question(this, title, question, QMessageBox::Yes | QMessageBox::Cancel, QMessageBox::Cancel) ==
           QMessageBox::Yes;
}

bool ObjectDictionaryDock::refuseIfOffline(const QString& what) {
    if (canTransmit() && node_ > 0 && model_->hasDictionary()) return false;
    if (node_ <= 0) showMessage(tr("%1: no node selected").arg(what), true);
    else if (!model_->hasDictionary())
        showMessage(tr("%1: no dictionary for node %2 (assign one)").arg(what).arg(node_), true);
    else if (workspace_->bus() && workspace_->bus()->isListenOnly())
        showMessage(tr("%1: the bus is listen-only, nothing is sent").arg(what), true);
    else showMessage(tr("%1: not connected to a bus").arg(what), true);
    return true;
}

bool ObjectDictionaryDock::readEntry(uint16_t index, uint8_t sub) { return upload(index, sub, true); }

bool ObjectDictionaryDock::upload(uint16_t index, uint8_t sub, bool announce) {
    if (refuseIfOffline(tr("Read %1").arg(canopen::objectRef(index, sub)))) return false;
    const od::SubObject* e = model_->dictionary().entry(index, sub);
    if (!e) return false;
    if (!od::isReadable(e->access)) {
        showMessage(tr("%1 %2 is write-only")
                        .arg(canopen::objectRef(index, sub), dissect::localDisplayName(model_->dictionary(), index, sub,
                                                                                       dissect::vendorTextLanguage())),
                    true);
        return false;
    }
    model_->setState(index, sub, OdTreeModel::State::Reading);
    QPointer<ObjectDictionaryDock> self(this);
    const quint64 gen = generation_;
    workspace_->sdo()->upload(
        static_cast<uint8_t>(node_), index, sub, [self, gen, index, sub, announce](const canopen::SdoResult& r) {
            if (!self || self->generation_ != gen) return;
            if (r.ok) {
                self->model_->setUploaded(index, sub, r.data);
                const QString err = self->model_->errorText(index, sub);
                if (!err.isEmpty()) self->showMessage(err, true);
                else if (announce)
                    self->showMessage(tr("Node %1 %2 %3 = %4")
                                          .arg(r.node)
                                          .arg(canopen::objectRef(index, sub),
                                               dissect::localDisplayName(self->model_->dictionary(), index, sub,
                                                                         dissect::vendorTextLanguage()),
                                               self->model_->actualText(index, sub)));
            } else {
                self->model_->setError(index, sub, r.error);
                self->showMessage(r.error, true);
            }
            self->updateHeader();
        });
    return true;
}

QString ObjectDictionaryDock::writeQuestion(uint16_t index, uint8_t sub, const od::Value& value) const {
    const od::SubObject* e = model_->dictionary().entry(index, sub);
    if (!e) return {};
    const QString ref = QStringLiteral("%1h:%2")
                            .arg(index, 4, 16, QLatin1Char('0'))
                            .arg(sub, 2, 16, QLatin1Char('0'))
                            .toUpper()
                            .replace(QLatin1String("H:"), QLatin1String("h:"));
    return tr("Write %1 %2 = %3 to node %4?")
        .arg(ref, dissect::localDisplayName(model_->dictionary(), index, sub, dissect::vendorTextLanguage()),
             model_->valueText(*e, value))
        .arg(node_);
}

bool ObjectDictionaryDock::writeEntryText(uint16_t index, uint8_t sub, const QString& text) {
    const od::SubObject* e = model_->dictionary().entry(index, sub);
    if (!e) return false;
    const od::ValueResult r = od::Value::parse(e->dataType, text, e->limits());
    if (!r.ok()) {
        const QString err = tr("Node %1 %2: %3").arg(node_).arg(canopen::objectRef(index, sub), r.error);
        showMessage(err, true);
        return false;
    }
    return writeEntry(index, sub, r.value);
}

bool ObjectDictionaryDock::writeEntry(uint16_t index, uint8_t sub, const od::Value& value) {
    if (refuseIfOffline(tr("Write %1").arg(canopen::objectRef(index, sub)))) return false;
    const od::SubObject* e = model_->dictionary().entry(index, sub);
    if (!e) return false;
    if (!od::isWritable(e->access)) {
        showMessage(tr("%1 %2 is %3: not writable")
                        .arg(canopen::objectRef(index, sub),
                             dissect::localDisplayName(model_->dictionary(), index, sub, dissect::vendorTextLanguage()),
                             od::accessName(e->access)),
                    true);
        return false;
    }
    QString encError;
    const QByteArray data = value.encode(e->dataType, &encError);
    if (!encError.isEmpty()) {
        showMessage(tr("Node %1 %2: %3").arg(node_).arg(canopen::objectRef(index, sub), encError), true);
        return false;
    }
    const QString question = writeQuestion(index, sub, value);
    if (!confirm(tr("Write object"),
                 question + tr("\n\nSDO download of %n byte(s): %1", nullptr, static_cast<int>(data.size()))
                                .arg(QString::fromLatin1(data.toHex(' ').toUpper()))))
        return false;
    model_->setState(index, sub, OdTreeModel::State::Writing);
    QPointer<ObjectDictionaryDock> self(this);
    const quint64 gen = generation_;
    const QString what = model_->valueText(*e, value);
    workspace_->sdo()->download(
        static_cast<uint8_t>(node_), index, sub, data, [self, gen, index, sub, what](const canopen::SdoResult& r) {
            if (!self || self->generation_ != gen) return;
            if (!r.ok) {
                self->model_->setError(index, sub, r.error);
                self->showMessage(r.error, true);
                return;
            }
            self->showMessage(tr("Node %1 %2 written: %3").arg(r.node).arg(canopen::objectRef(index, sub), what));
            // Read back what the node holds now (it may round or refuse silently).
            if (od::isReadable(self->model_->dictionary().entry(index, sub)->access)) self->readEntry(index, sub);
            else self->model_->setState(index, sub, OdTreeModel::State::Unknown);
        });
    return true;
}

bool ObjectDictionaryDock::readAll() {
    if (refuseIfOffline(tr("Read all"))) return false;
    if (!config_) return false;
    if (isBusy()) {
        showMessage(tr("A read or DCF application is already running"), true);
        return false;
    }
    const auto entries = canopen::DeviceConfiguration::readableEntries(model_->dictionary());
    progress_->setRange(0, static_cast<int>(entries.size()));
    progress_->setValue(0);
    readAllFinished_ = false;
    showMessage(tr("Reading %1 objects of node %2…").arg(entries.size()).arg(node_));
    QPointer<ObjectDictionaryDock> self(this);
    const quint64 gen = generation_;
    config_->read(
        static_cast<uint8_t>(node_), model_->dictionary(), entries,
        [self, gen](const canopen::ConfigEntryResult& e, int done, int total) {
            if (!self || self->generation_ != gen) return;
            if (e.ok) self->model_->setUploaded(e.index, e.sub, e.data);
            else self->model_->setError(e.index, e.sub, e.error);
            self->progress_->setMaximum(total);  // shrinks when entries turn out empty (1003h)
            self->progress_->setValue(done);
        },
        [self, gen](const canopen::ConfigReadResult& r) {
            if (!self || self->generation_ != gen) return;
            self->onReadAllDone(r.failed, r.cancelled);
        });
    updateEnabled();
    return true;
}

void ObjectDictionaryDock::cancelReadAll() {
    if (config_ && config_->isRunning()) config_->cancel();
}

void ObjectDictionaryDock::onReadAllDone(int failed, bool cancelled) {
    readAllFinished_ = !cancelled;
    const int read = model_->valuesRead();
    if (cancelled) showMessage(tr("Read of node %1 cancelled: %2 values read").arg(node_).arg(read));
    else if (failed)
        showMessage(tr("Node %1: %2 values read, %3 refused (red rows; the tool tip has the abort text)")
                        .arg(node_)
                        .arg(read)
                        .arg(failed),
                    true);
    else showMessage(tr("Node %1: %2 values read").arg(node_).arg(read));
    updateEnabled();
    if (!pendingExport_.isEmpty()) {
        const QString path = pendingExport_;
        pendingExport_.clear();
        if (!cancelled) writeDcfFile(path);
    }
}

}  // namespace coscope::gui
