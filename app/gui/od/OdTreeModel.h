// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/od/ObjectDictionary.h"

#include <QAbstractItemModel>

#include <cstdint>
#include <optional>
#include <unordered_map>
#include <vector>

namespace coscope::gui {

// One node's object dictionary as a tree: VAR objects are one row, ARRAY/RECORD objects have a
// row per sub-object. Each entry carries what was read from (or written to) the node: the
// actual value, whether it differs from the dictionary's default, and the last SDO error
// (shown in red on the row with the abort text as tool tip). Editing the Value column does not
// change the model: it asks for a write (writeRequested); the value shows once read back.
class OdTreeModel : public QAbstractItemModel {
    Q_OBJECT
public:
    enum Column { Object, Name, Value, Unit, Default, Type, Access, Pdo, ColumnCount };
    enum Role {
        IndexRole = Qt::UserRole + 1,  // object index (int)
        SubRole,                       // sub-index (int), -1 on a composite object's row
        ChangedRole,                   // bool: the actual value differs from the default
        SearchRole,                    // text the search box matches ("6060h:00 Modes of operation")
        ErrorRole,                     // the last SDO error of the entry ("" = none)
    };
    enum class State : uint8_t { Unknown, Reading, Writing, Read, Error };

    explicit OdTreeModel(QObject* parent = nullptr);

    void setDictionary(const od::ObjectDictionary& dictionary, uint8_t node);
    void clear();
    bool hasDictionary() const { return !rows_.empty(); }
    uint8_t node() const { return node_; }
    const od::ObjectDictionary& dictionary() const { return dictionary_; }

    // The entry of a row (composite object rows: nullptr).
    const od::SubObject* entryAt(const QModelIndex& index) const;
    QModelIndex indexOf(uint16_t index, uint8_t sub, int column = Object) const;

    // Results of SDO transfers.
    void setState(uint16_t index, uint8_t sub, State state);
    // Decodes an upload; a value that does not decode becomes the entry's error.
    void setUploaded(uint16_t index, uint8_t sub, const QByteArray& data);
    void setError(uint16_t index, uint8_t sub, const QString& error);
    State state(uint16_t index, uint8_t sub) const;
    std::optional<od::Value> actualValue(uint16_t index, uint8_t sub) const;
    QString actualText(uint16_t index, uint8_t sub) const;  // display text (unit, meaning), "" unread
    QString errorText(uint16_t index, uint8_t sub) const;
    bool isChanged(uint16_t index, uint8_t sub) const;
    int valuesRead() const { return valuesRead_; }
    int entryCount() const { return dictionary_.subObjectCount(); }
    // The dictionary with ParameterValue = the values read (for a DCF), NodeID = node.
    od::ObjectDictionary actualValues() const;

    // What was read from or written to the node, kept while another node is shown (issue 35):
    // taken before the node changes, put back once its dictionary is shown again.
    struct EntryState {
        State state = State::Unknown;
        std::optional<od::Value> value;
        QString error;
        bool changed = false;
    };
    struct NodeValues {
        std::unordered_map<uint32_t, EntryState> states;
        int valuesRead = 0;
    };
    // A read or write under way is not finished when taken: its entry keeps the value it had.
    NodeValues values() const;
    void setValues(const NodeValues& values);

    // When false (listen-only, no bus) the Value column is not editable.
    void setWritable(bool on) { writable_ = on; }

    // Display text of a value for this node's entry: unit, and the CiA 402 meaning of modes of
    // operation ("1 (Profile position (PP))").
    QString valueText(const od::SubObject& entry, const od::Value& value, bool withUnit = true) const;
    // The name the view shows for an object (sub -1) or entry: in the UI language for a bundled
    // dictionary's standard objects and vendor parameters, else the EDS name.
    QString localName(uint16_t index, int sub, const QString& edsName) const;
    // "\nBits on: ready to switch on, …, homing attained" for a statusword 6041h (bits 12/13 by
    // the mode of operation 6061h read from the node), else empty.
    QString statuswordBitsText(const od::SubObject& entry, const od::Value& value) const;

    QModelIndex index(int row, int column, const QModelIndex& parent = {}) const override;
    QModelIndex parent(const QModelIndex& child) const override;
    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role) const override;
    bool setData(const QModelIndex& index, const QVariant& value, int role) override;
    Qt::ItemFlags flags(const QModelIndex& index) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role) const override;

signals:
    // The user entered `value` for an entry (Value column): the view's owner confirms and writes.
    void writeRequested(uint16_t index, uint8_t sub, const coscope::od::Value& value);

private:
    struct ObjectRow {
        uint16_t index = 0;
        bool composite = false;
    };
    static uint32_t key(uint16_t index, uint8_t sub) { return (uint32_t(index) << 8) | sub; }
    const od::Object* objectAt(const QModelIndex& index) const;
    void entryChanged(uint16_t index, uint8_t sub);

    od::ObjectDictionary dictionary_;
    uint8_t node_ = 0;
    std::vector<ObjectRow> rows_;
    std::unordered_map<uint32_t, EntryState> states_;
    int valuesRead_ = 0;
    bool writable_ = false;
};

}  // namespace coscope::gui
