// SPDX-License-Identifier: GPL-3.0-or-later
// Folder app/gui/od/ owns the object dictionary dock: the tree of a node's dictionary with filter,
// SDO read/write of values and applying a DCF.
#pragma once

#include "app/gui/od/OdTreeModel.h"
#include "core/od/ObjectDictionary.h"

#include <QDockWidget>
#include <QPointer>

#include <map>
#include <memory>
#include <vector>

class QAction;
class QCheckBox;
class QComboBox;
class QLabel;
class QLineEdit;
class QProgressBar;
class QPushButton;
class QTreeView;
class QWidget;

namespace coscope {
class TraceStore;
}
namespace coscope::canopen {
class DeviceConfiguration;
struct ConfigEntryResult;
}  // namespace coscope::canopen

namespace coscope::gui {

class DcfApplyDialog;
class OdFilterModel;
class OdTreeModel;
class Workspace;
struct PendingApply;

// The Object Dictionary dock: the selected node's dictionary as a tree (index/sub, name, value,
// unit, default, type, access, PDO-mappable), read and written over SDO through the workspace's
// SDO client and the DeviceConfiguration service (never blocking). Read one entry (double-click,
// context menu) or all (progress, cancel); write with an editor fitting the type and limits
// after a confirmation that says exactly what is sent, then read back. Values that differ from
// the default are bold blue ("Only changed" filters them); SDO errors are red on their row with
// the abort text, and in the dock's message line. Export the values as a DCF; apply a DCF
// (preview, confirm, report). Reading and writing are disabled when listen-only or offline.
class ObjectDictionaryDock : public QDockWidget {
    Q_OBJECT
public:
    explicit ObjectDictionaryDock(Workspace* workspace, QWidget* parent = nullptr);
    ~ObjectDictionaryDock() override;

    // The workspace's source changed: another bus or log starts with no node shown, no message
    // and no progress; after a disconnect the node stays (the same trace is reviewed).
    void rebind();
    void refresh();          // the window's ≤ 30 Hz tick
    void setNode(int node);  // -1 = none
    int node() const { return node_; }
    // True when there is something worth a screenshot (a node's dictionary with values).
    bool hasContent() const;

    OdTreeModel* model() const { return model_; }
    OdFilterModel* filter() const { return filter_; }
    QTreeView* view() const { return view_; }
    QLineEdit* searchBox() const { return search_; }
    QCheckBox* onlyChangedBox() const { return onlyChanged_; }
    QProgressBar* progressBar() const { return progress_; }
    QString messageText() const;
    QString dictionaryName() const { return dictName_; }

    // The commands (also behind the buttons and menus). false when refused (message says why).
    bool readEntry(uint16_t index, uint8_t sub);
    bool readAll();
    void cancelReadAll();
    bool isBusy() const;
    bool writeEntry(uint16_t index, uint8_t sub, const od::Value& value);
    bool writeEntryText(uint16_t index, uint8_t sub, const QString& text);
    // A path ending in .bin gets the concise DCF (CiA 302-3, 1F22h) of the values instead.
    bool exportDcf(const QString& path);
    bool applyDcf(const QString& path);
    void assignDictionary(const QString& name);
    bool canTransmit() const;
    // The last DCF application's results (for tests and the report).
    const std::vector<canopen::ConfigEntryResult>& lastApplyResults() const { return applyResults_; }
    // Test hook: answer confirmations without showing a dialog.
    void setAutoConfirm(bool on) { autoConfirm_ = on; }

    // "Write 6060h:00 Modes of operation = 1 (Profile position (PP)) to node 5?"
    QString writeQuestion(uint16_t index, uint8_t sub, const od::Value& value) const;

signals:
    void message(const QString& text);

private:
    void buildUi();
    void loadDictionary();
    void updateEnabled();
    void updateHeader();
    void resetProgress();
    void showMessage(const QString& text, bool error = false);
    bool confirm(const QString& title, const QString& question);
    bool refuseIfOffline(const QString& what);
    void contextMenu(const QPoint& pos);
    // Opens the value editor of `row`'s entry when it is writable, else says why not.
    void editValue(const QModelIndex& row);
    void setMessageLine(const QString& text, bool error);
    void onReadAllDone(int failed, bool cancelled);
    void runApply(std::shared_ptr<PendingApply> pending);
    bool writeDcfFile(const QString& path);
    bool upload(uint16_t index, uint8_t sub, bool announce);

    Workspace* workspace_;
    OdTreeModel* model_ = nullptr;
    OdFilterModel* filter_ = nullptr;
    QTreeView* view_ = nullptr;
    QLabel* header_ = nullptr;
    QLineEdit* search_ = nullptr;
    QCheckBox* onlyChanged_ = nullptr;
    QProgressBar* progress_ = nullptr;
    QLabel* messageLine_ = nullptr;
    QWidget* noDictionary_ = nullptr;
    QLabel* noDictionaryText_ = nullptr;
    QComboBox* dictChoice_ = nullptr;
    QAction* readAll_ = nullptr;
    QAction* cancel_ = nullptr;
    QAction* readSelected_ = nullptr;
    QAction* writeSelected_ = nullptr;  // F2 in the tree
    QAction* export_ = nullptr;
    QAction* apply_ = nullptr;
    canopen::DeviceConfiguration* config_ = nullptr;
    QPointer<DcfApplyDialog> applyDialog_;
    std::vector<canopen::ConfigEntryResult> applyResults_;
    std::map<QString, od::ObjectDictionary> dictionaryCache_;
    // Per node shown before: its values (with the dictionary they belong to) and its status line,
    // put back when the node is shown again (issue 35: Read all, node 2, node 1 again).
    struct KeptNode {
        QString dictionary;
        OdTreeModel::NodeValues values;
        QString message;
        bool messageIsError = false;
        std::map<uint32_t, QByteArray> written;  // confirmed SDO downloads since (index << 8 | sub)
    };
    // ObjectDictionaryDockFollow.cpp: values and node-IDs the rest of the app changed.
    void watchSdo();
    void onWritten(quint8 node, quint16 index, quint8 sub, const QByteArray& data);
    void applyWritten(const KeptNode& kept);
    void followMoves();
    QMetaObject::Connection sdoWritten_;
    size_t movesSeen_ = 0;  // NodeTable::moves() followed
    std::map<int, KeptNode> kept_;
    bool messageIsError_ = false;

    std::weak_ptr<const TraceStore> store_;  // the trace the shown node belongs to
    int node_ = -1;
    QString dictName_;  // the dictionary shown ("" = none)
    bool autoPicked_ = false;
    bool autoReadDone_ = false;
    bool readAllFinished_ = false;
    QString pendingExport_;   // export once read-all finishes
    quint64 generation_ = 0;  // bumped when node, dictionary or bus change: late answers are dropped
    bool autoConfirm_ = false;
    bool lastCanTransmit_ = false;
    bool lastBusy_ = false;
};

}  // namespace coscope::gui
