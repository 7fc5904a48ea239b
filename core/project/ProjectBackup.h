// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/canopen/SdoClient.h"
#include "core/project/ProjectMatch.h"

#include <QObject>

#include <memory>

namespace coscope::project {

struct BackupNodeResult {
    uint8_t node = 0;
    QString name;
    bool ok = false;
    int parameters = 0;  // configured objects kept
    int read = 0;        // objects read
    int failed = 0;      // reads refused or unanswered
    QString message;     // "12 configured objects of 240 read", "missing: kept as it was", ...
};

// "Back up the machine": scans the bus, and for every node found (in the project, or new: then
// added with the dictionary matched to its identity) reads all readable objects
// (DeviceConfiguration) and keeps as its parameters the configuration objects whose value differs
// from the dictionary's default (isConfigurationEntry); the identity 1018h is taken as found, and
// the program it runs (1F56h, 100Ah) as nodes[].firmware.
// Project nodes that do not answer are kept as they were.
class ProjectBackup : public QObject {
    Q_OBJECT
public:
    using Progress = std::function<void(const QString& what, int done, int total)>;
    using Done = std::function<void(const Project& project, const std::vector<BackupNodeResult>& results)>;
    // Dictionary name for a node not in the project (eds::scanMatcher()'s answer); empty = none.
    using Matcher = canopen::NetworkScan::Matcher;

    ProjectBackup(canopen::SdoClient& sdo, DictionaryResolver resolver, QObject* parent = nullptr);
    void setScanRange(uint8_t first, uint8_t last) {
        first_ = first;
        last_ = last;
    }
    void setScanTimeout(int ms) { scanTimeoutMs_ = ms; }
    void setMatcher(Matcher m) { matcher_ = std::move(m); }

    void start(const Project& project, Progress progress, Done done);

    // The configured parameters of a node read in full: configuration entries whose value
    // differs from the dictionary's default, in index order.
    static std::vector<ProjectParameter> configuredParameters(const od::ObjectDictionary& values, uint8_t node);

private:
    struct Run;
    void backupNext(std::shared_ptr<Run> run);
    void backupSoftware(std::shared_ptr<Run> run, uint8_t id, BackupNodeResult result);

    canopen::SdoClient& sdo_;
    DictionaryResolver resolver_;
    Matcher matcher_;
    uint8_t first_ = 1, last_ = 127;
    int scanTimeoutMs_ = 0;
};

}  // namespace coscope::project
