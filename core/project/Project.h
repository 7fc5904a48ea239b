// SPDX-License-Identifier: GPL-3.0-or-later
// Folder core/project/ owns the project: a machine kept as one file (DESIGN.md "Project file"),
// its reading and writing, and the services that compare the machine with it, back it up into it
// and apply it (ProjectCompare, ProjectBackup, ProjectApply).
#pragma once

#include <QJsonArray>
#include <QJsonObject>
#include <QJsonValue>
#include <QString>

#include <cstdint>
#include <optional>
#include <vector>

namespace coscope::project {

// One configured object of a node: its value as CiA 306 ParameterValue text (the DCF view,
// CiA 306 4.7), e.g. "0x01F4", "-20", "text".
struct ProjectParameter {
    uint16_t index = 0;
    uint8_t sub = 0;
    QString name;  // for people reading the file; not used to match
    QString value;
};

// The identity a node is expected to answer in 1018h:01..04 (CiA 301 7.5.2.24); nullopt = not
// checked.
struct ProjectIdentity {
    std::optional<uint32_t> vendorId, productCode, revision, serial;
};

// The program a node is expected to run (CiA 302-3 program download). `file` is the image sent to
// 1F50h program data, relative to the project file's folder or absolute; `softwareId` is what the
// node answers in 1F56h program software identification and `version` in 100Ah manufacturer
// software version (CiA 302-3 §4, CiA 301 7.5.2.8) once it runs that program. Empty = not checked.
struct ProjectFirmware {
    QString file;
    uint8_t program = 1;  // the sub-index of 1F50h/1F51h/1F56h/1F57h
    std::optional<uint32_t> softwareId;
    QString version;
    bool expectsSomething() const { return softwareId.has_value() || !version.isEmpty(); }
};

// One node of the machine.
struct ProjectNode {
    uint8_t id = 0;
    QString name;
    // A bundled dictionary's name ("delta-asda-a2") or an EDS/DCF/XDD file, relative to the
    // project file's folder or absolute.
    QString dictionary;
    ProjectIdentity identity;
    // Writable objects whose value differs from the dictionary's default, in index order.
    std::vector<ProjectParameter> parameters;
    std::optional<ProjectFirmware> firmware;
    QJsonObject unknown;  // keys this version does not know, kept as they were

    const ProjectParameter* parameter(uint16_t index, uint8_t sub) const;
};

// A machine kept as a project. The parts the GUI owns (transmit list, raw signals, plots, trace
// filters, SYNC/heartbeat settings) are kept as JSON the app fills and reads; core only carries
// them.
struct Project {
    static constexpr int kFormat = 1;
    int format = kFormat;
    QString name;
    QString busUrl;
    uint32_t bitRate = 0;  // 0 = not given
    std::vector<ProjectNode> nodes;
    QJsonObject master;        // SYNC and heartbeat settings
    QJsonArray transmit;       // transmit list
    QJsonArray rawSignals;     // raw signal specs
    QJsonObject plots;         // plot layouts
    QJsonObject traceFilters;  // trace filters
    QJsonObject unknown;       // keys this version does not know, kept as they were

    ProjectNode* node(uint8_t id);
    const ProjectNode* node(uint8_t id) const;
};

// "0x000001DD" for people and files (1018h identity, 1F56h software identification).
QString hex32Text(uint32_t value);
// "6081:00" for people and files.
QString objectKey(uint16_t index, uint8_t sub);
// Reads "6081:00" / "0x6081:0" / "6081sub0".
bool parseObjectKey(const QString& text, uint16_t* index, uint8_t* sub);

}  // namespace coscope::project
