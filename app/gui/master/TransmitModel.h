// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/canopen/TransmitList.h"

#include <QAbstractTableModel>

#include <memory>
#include <optional>
#include <vector>

namespace coscope::canopen {
class MasterContext;
}

namespace coscope::gui {

// The Transmit panel's table over the open bus's transmit list (core TransmitList): one row per
// frame, its fields editable in place (ID in hex, type, RTR, FD/BRS, DLC, data bytes in hex, the
// period in ms with µs resolution, a comment), the periodic switch and the sent count. Without a
// bus it shows and edits the rows kept in QSettings ("transmit/rows", the list of the last
// session), which the next bus starts with. Counts are pulled by refresh() (≤ 30 Hz), never
// pushed per frame.
class TransmitModel : public QAbstractTableModel {
    Q_OBJECT
public:
    enum Column { Run, Id, Extended, Remote, Fd, Brs, Dlc, Data, Every, Sent, Comment, ColumnCount };

    explicit TransmitModel(QObject* parent = nullptr);

    // The list of the bus now open (null: none). A new list gets the saved rows.
    void rebind(canopen::TransmitList* list);
    // The list shown: the bus's, or without a bus one that cannot send (its rows are kept).
    canopen::TransmitList* list() const { return list_; }
    bool hasBus() const { return list_ != offlineList_.get(); }
    void refresh();
    // The rows kept in the settings again (a project was opened): the list is replaced, its
    // periodic rows stopped.
    void reloadSaved();

    canopen::TransmitEntry entry(int row) const;
    bool setEntry(int row, const canopen::TransmitEntry& e);
    int addEntry(const canopen::TransmitEntry& e);
    bool removeEntry(int row);
    bool isRunning(int row) const;

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;
    Qt::ItemFlags flags(const QModelIndex& index) const override;
    bool setData(const QModelIndex& index, const QVariant& value, int role = Qt::EditRole) override;

    // "100" (ms) -> 100000 µs; "0.5" -> 500; "" or "0" -> 0 (once only). nullopt when not a time.
    static std::optional<uint32_t> parsePeriodMs(const QString& text);
    // "601", "601h", "0x601" -> 0x601 (identifiers are hex).
    static std::optional<uint32_t> parseId(const QString& text);

signals:
    // The user switched a row's periodic sending on or off (the dock decides and confirms).
    void runToggled(int row, bool on);
    // An edit was refused: what is wrong.
    void editRefused(const QString& why);

private:
    void save() const;
    void load();

    std::unique_ptr<canopen::MasterContext> offlineContext_;  // no bus: sends nothing
    std::unique_ptr<canopen::TransmitList> offlineList_;
    canopen::TransmitList* list_ = nullptr;
    uint64_t revision_ = ~uint64_t{0};
    std::vector<uint64_t> sent_;
    std::vector<bool> running_;
};

}  // namespace coscope::gui
