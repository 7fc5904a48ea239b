// SPDX-License-Identifier: GPL-3.0-or-later
// Folder core/od/ owns the object dictionary model: data types, values and how numbers are written
// and read.
#pragma once

#include "core/od/DataType.h"
#include "core/od/Value.h"

#include <QList>
#include <QPair>
#include <QString>
#include <QStringList>

#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <unordered_map>
#include <vector>

namespace coscope::od {

// Object codes (CiA 301 v4.2, 7.4.3 table 42).
enum class ObjectType : std::uint8_t {
    Null = 0x0,
    Domain = 0x2,
    DefType = 0x5,
    DefStruct = 0x6,
    Var = 0x7,
    Array = 0x8,
    Record = 0x9
};
QString objectTypeName(ObjectType t);  // "VAR", "ARRAY", ...

// Access attributes (CiA 306 v1.3 4.6.3): rwr/rww are read-write, preferably mapped to a
// TPDO (rwr) or an RPDO (rww).
enum class Access : std::uint8_t { ReadOnly, WriteOnly, ReadWrite, ReadWriteRead, ReadWriteWrite, Const };
QString accessName(Access a);                            // "ro", "wo", "rw", "rwr", "rww", "const"
std::optional<Access> accessFromString(const QString&);  // case-insensitive
inline bool isReadable(Access a) { return a != Access::WriteOnly; }
inline bool isWritable(Access a) { return a != Access::ReadOnly && a != Access::Const; }

// Unknown keys of a section in file order with their original spelling (kept for round trip).
using ExtraKeys = QList<QPair<QString, QString>>;

// Display unit of an entry: display = raw * factor, then unit text.
struct Unit {
    QString text;
    double factor = 1.0;
};

// One sub-object (for a VAR: the object itself at sub 0). Values are kept as the text of the
// file, so `$NODEID` relations stay symbolic; the typed views resolve them.
struct SubObject {
    std::uint16_t index = 0;
    std::uint8_t sub = 0;
    QString name;
    DataType dataType = DataType::Unsigned8;
    Access access = Access::ReadOnly;
    bool pdoMappable = false;
    QString defaultValue;    // EDS DefaultValue as written ("$NODEID+0x180", "0x10", "")
    QString parameterValue;  // DCF ParameterValue: the device's actual value ("" = none)
    QString lowLimit;        // as written, "" = none
    QString highLimit;
    QString denotation;  // DCF Denotation
    std::uint32_t objFlags = 0;
    std::optional<Unit> unit;
    ExtraKeys extraKeys;
    int line = 0;  // line of the section in its source file (0 = synthesized)

    bool defaultUsesNodeId() const;
    // DefaultValue as a typed value, `$NODEID` replaced by nodeId. nullopt when empty or not
    // readable as the data type (*error then says why).
    std::optional<Value> resolvedDefault(std::uint8_t nodeId, QString* error = nullptr) const;
    // ParameterValue if present, otherwise the resolved default.
    std::optional<Value> resolvedValue(std::uint8_t nodeId, QString* error = nullptr) const;
    Limits limits() const;  // LowLimit/HighLimit read as the data type (unreadable ones ignored)
    // Reads EDS/DCF value text for this entry's type (CiA 306 numbers, $NODEID formulas).
    std::optional<Value> interpret(const QString& text, std::uint8_t nodeId, QString* error = nullptr) const;
};

// One object: VAR (one sub-object, sub 0), ARRAY, RECORD, DOMAIN, DEFTYPE or DEFSTRUCT.
struct Object {
    std::uint16_t index = 0;
    QString name;
    ObjectType objectType = ObjectType::Var;
    DataType dataType = DataType::Unsigned8;  // VAR/DOMAIN type; ARRAY/RECORD: the DataType key if any
    std::vector<SubObject> subs;              // sorted by sub-index
    std::vector<std::uint16_t> objectLinks;   // [XXXXObjectLinks] (CiA 306 4.6.6)
    std::uint32_t objFlags = 0;
    int compactSubObj = 0;  // CompactSubObj as read (0 = subs were listed)
    ExtraKeys extraKeys;
    int line = 0;

    const SubObject* sub(std::uint8_t s) const;
    bool isComposite() const {
        return objectType == ObjectType::Array || objectType == ObjectType::Record ||
               objectType == ObjectType::DefStruct;
    }
};

// [FileInfo] (CiA 306 4.6.1). Texts as written.
struct FileInfo {
    QString fileName, fileVersion, fileRevision, edsVersion, description;
    QString creationTime, creationDate, createdBy, modificationTime, modificationDate, modifiedBy;
    ExtraKeys extraKeys;
};

// [DeviceInfo] (CiA 306 4.6.2).
struct DeviceInfo {
    QString vendorName;
    std::optional<std::uint32_t> vendorNumber;
    QString productName;
    std::optional<std::uint32_t> productNumber;
    std::optional<std::uint32_t> revisionNumber;
    QString orderCode;
    QList<int> baudRates;  // supported, in kbit/s (10, 20, 50, 125, 250, 500, 800, 1000)
    bool simpleBootUpMaster = false, simpleBootUpSlave = false;
    int granularity = 8;
    bool dynamicChannelsSupported = false;
    int groupMessaging = 0;
    int nrOfRxPdo = 0, nrOfTxPdo = 0;
    bool lssSupported = false;
    int compactPdo = 0;  // CompactPDO bit mask as read
    ExtraKeys extraKeys;
};

// [DeviceCommissioning] (CiA 306 4.7, DCF only; also read from the old "DeviceComissioning").
struct Commissioning {
    std::uint8_t nodeId = 0;  // 0 = not set
    QString nodeName;
    int baudRate = 0;  // kbit/s, 0 = not set
    std::uint32_t netNumber = 0;
    QString networkName;
    bool canopenManager = false;
    std::optional<std::uint32_t> lssSerialNumber;
    ExtraKeys extraKeys;
};

// [DynamicChannels] segment (CiA 306 4.6.7).
struct DynamicChannel {
    DataType type = DataType::Unsigned8;
    QString dir;  // "ro", "rww", ...
    std::uint16_t rangeFirst = 0, rangeLast = 0;
    std::uint32_t ppOffset = 0;
};

// Any other section kept verbatim ([Comments], [ToolInfos], vendor sections).
struct ExtraSection {
    QString name;
    ExtraKeys keys;
};

// The object dictionary of one device. Lookup by (index, sub) is a hash lookup (dissectors
// call it per frame); iteration is in index order. Copyable; not internally synchronized
// (share a const instance between threads).
class ObjectDictionary {
public:
    ObjectDictionary() = default;
    ObjectDictionary(const ObjectDictionary& o);
    ObjectDictionary& operator=(const ObjectDictionary& o);
    ObjectDictionary(ObjectDictionary&&) noexcept = default;
    ObjectDictionary& operator=(ObjectDictionary&&) noexcept = default;

    // Adds or replaces the object at obj.index (subs are sorted by sub-index).
    void insert(Object obj);
    bool remove(std::uint16_t index);
    void clear();

    const Object* object(std::uint16_t index) const;
    const SubObject* entry(std::uint16_t index, std::uint8_t sub) const;
    // For changing fields of one entry in place (not the set of subs: re-insert for that).
    SubObject* entryForEdit(std::uint16_t index, std::uint8_t sub);
    // Sets the DCF ParameterValue text of an entry; false when the entry does not exist.
    bool setParameterValue(std::uint16_t index, std::uint8_t sub, const QString& text);

    const std::map<std::uint16_t, Object>& objects() const { return objects_; }
    int objectCount() const { return static_cast<int>(objects_.size()); }
    int subObjectCount() const { return static_cast<int>(index_.size()); }
    bool isEmpty() const { return objects_.empty(); }

    // "Object name" for the object, "Object name: sub name" for a sub of a composite.
    QString displayName(std::uint16_t index, std::uint8_t sub) const;

    // The node-ID this dictionary is configured for (DCF NodeID), 0 = unknown.
    std::uint8_t nodeId() const { return commissioning.nodeId; }
    void setNodeId(std::uint8_t id) { commissioning.nodeId = id; }

    // Identity (1018h) as described: DeviceInfo numbers, else 1018h sub 1..3 defaults.
    std::optional<std::uint32_t> vendorId() const;
    std::optional<std::uint32_t> productCode() const;
    std::optional<std::uint32_t> revisionNumber() const;

    // Unit of an entry, if known (from the entry or the dictionary's sidecar).
    std::optional<Unit> unit(std::uint16_t index, std::uint8_t sub) const;

    FileInfo fileInfo;
    DeviceInfo device;
    Commissioning commissioning;
    std::array<bool, 8> dummyUsage{};  // [DummyUsage] Dummy0001..0007 (index 1..7; 0 unused)
    std::vector<DynamicChannel> dynamicChannels;
    std::vector<ExtraSection> extraSections;
    QStringList comments;  // [Comments] LineN texts
    // NAME of a dictionary compiled into CoScope (":/dictionaries/NAME.eds", set by
    // eds::DictionaryLibrary::loadFile); empty for a user's EDS/DCF/XDD. The GUI names the
    // standard objects of a bundled one in its language (dissectors/ObjectNames.h).
    QString bundledName;

private:
    static std::uint32_t key(std::uint16_t index, std::uint8_t sub) { return (std::uint32_t(index) << 8) | sub; }
    void indexObject(const Object& o);
    void unindexObject(const Object& o);
    void rebuildIndex();

    std::map<std::uint16_t, Object> objects_;
    std::unordered_map<std::uint32_t, SubObject*> index_;
};

}  // namespace coscope::od
