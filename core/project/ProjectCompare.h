// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/canopen/SdoClient.h"
#include "core/project/ProjectMatch.h"

#include <QObject>

#include <memory>

namespace coscope::project {

enum class RowState : uint8_t { Same, Differs, Unreadable };
QString rowStateName(RowState s);  // "same", "differs", "unreadable"

// One configured object of the project against the drive.
struct CompareRow {
    uint8_t node = 0;
    uint16_t index = 0;
    uint8_t sub = 0;
    QString name;
    QString projectValue;
    QString driveValue;    // empty when unreadable
    QString defaultValue;  // the dictionary's default, empty when it has none
    RowState state = RowState::Same;
    QString error;  // why unreadable (abort text)
};

struct NodeComparison {
    uint8_t node = 0;
    QString name;  // the project's name, or the dictionary found
    NodeMatch match = NodeMatch::Missing;
    QString detail;
    int differences = 0;
    int unreadable = 0;
};

struct CompareReport {
    QString projectName;
    QString busUrl;
    std::vector<NodeComparison> nodes;
    std::vector<CompareRow> rows;
    // Nothing to report: every node the same and every object the same.
    bool clean() const;
    int differences() const;  // differing rows + nodes not "same"
};

// Compares the machine with the project: scans the bus (NetworkScan), matches each node by
// node-ID and identity (matchNodes), then reads what the project expects of each project node that
// answers with the same vendor and product (expectedValues: its parameters, and every other
// configuration entry at its default), one node after the other (DeviceConfiguration), and the
// program it runs where the project names one (softwareRows: 1F56h, 100Ah).
class ProjectCompare : public QObject {
    Q_OBJECT
public:
    using Progress = std::function<void(const QString& what, int done, int total)>;
    using Done = std::function<void(const CompareReport&)>;

    ProjectCompare(canopen::SdoClient& sdo, DictionaryResolver resolver, QObject* parent = nullptr);

    void setScanRange(uint8_t first, uint8_t last) {
        first_ = first;
        last_ = last;
    }
    void setScanTimeout(int ms) { scanTimeoutMs_ = ms; }
    // Names the dictionaries the scan writes into the node table (eds::scanMatcher()).
    void setMatcher(canopen::NetworkScan::Matcher m) { matcher_ = std::move(m); }

    void start(const Project& project, Progress progress, Done done);
    bool isRunning() const { return running_; }

private:
    struct Run;
    void compareNext(std::shared_ptr<Run> run);
    // The node's program against the project's (ProjectFirmware): the "software" rows.
    void compareSoftware(std::shared_ptr<Run> run, size_t at);

    canopen::SdoClient& sdo_;
    DictionaryResolver resolver_;
    uint8_t first_ = 1, last_ = 127;
    int scanTimeoutMs_ = 0;
    canopen::NetworkScan::Matcher matcher_;
    bool running_ = false;
};

}  // namespace coscope::project
