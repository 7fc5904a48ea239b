// SPDX-License-Identifier: GPL-3.0-or-later
// The project services against the virtual drives: the file written and read back (a malformed
// one named by file and line or key), "back up" keeps what differs from the defaults, "compare"
// names a changed object, a replaced drive (other serial), a missing node and one not in the
// project; "apply" puts the project's values back, and a node that refuses a write stops it with
// that node's old values put back and the nodes after it untouched.
#include "SvcTestRig.h"

#include "core/canopen/SdoClient.h"
#include "core/canopen/ServiceWait.h"
#include "core/project/CompareReportFormat.h"
#include "core/project/ProjectApply.h"
#include "core/project/ProjectBackup.h"
#include "core/project/ProjectCompare.h"
#include "core/project/ProjectFile.h"
#include "eds/ProjectDictionaries.h"
#include "eds/ScanMatcher.h"

#include <QTemporaryDir>
#include <QtTest>

using namespace coscope;
using namespace coscope::project;
using namespace svctest;

namespace {
const QString kSpec = QStringLiteral("1:delta-asda-a2,2:aimotor,3:generic-cia402");

struct Machine {
    Rig rig;
    std::unique_ptr<canopen::SdoClient> sdo;
    bool open() {
        if (!rig.useSpec(kSpec) || !rig.open()) return false;
        sdo = std::make_unique<canopen::SdoClient>(*rig.context);
        return true;
    }
    std::optional<od::Value> value(uint8_t node, uint16_t index, uint8_t sub) {
        std::optional<od::Value> v;
        rig.onDevice(node, [&](sim::VirtualDevice& d) { v = d.value(index, sub); });
        return v;
    }
    void set(uint8_t node, uint16_t index, uint8_t sub, uint64_t v) {
        rig.onDevice(node, [&](sim::VirtualDevice& d) { d.setValue(index, sub, od::Value::unsignedInt(v)); });
    }
    Project backup(Project start = {}) {
        ProjectBackup b(*sdo, eds::projectDictionaryResolver({}));
        b.setScanRange(1, 5);
        b.setMatcher(eds::scanMatcher());
        std::optional<Project> out;
        b.start(start, {}, [&](const Project& p, const std::vector<BackupNodeResult>& results) {
            for (const auto& r : results) QVERIFY2(r.ok, qPrintable(r.message));
            out = p;
        });
        canopen::waitUntil([&] { return out.has_value(); }, 60000);
        return out.value_or(Project{});
    }
    CompareReport compare(const Project& p) {
        ProjectCompare c(*sdo, eds::projectDictionaryResolver({}));
        c.setScanRange(1, 5);
        std::optional<CompareReport> out;
        c.start(p, {}, [&](const CompareReport& r) { out = r; });
        canopen::waitUntil([&] { return out.has_value(); }, 60000);
        return out.value_or(CompareReport{});
    }
    ApplyReport apply(const Project& p, std::vector<NodeApplyPlan>* plansOut = nullptr) {
        ProjectApply a(*sdo, eds::projectDictionaryResolver({}));
        std::optional<std::vector<NodeApplyPlan>> plans;
        a.prepare(p, {}, [&](std::vector<NodeApplyPlan> pl) { plans = std::move(pl); });
        canopen::waitUntil([&] { return plans.has_value(); }, 60000);
        if (plansOut) *plansOut = plans.value_or(std::vector<NodeApplyPlan>{});
        std::optional<ApplyReport> out;
        a.run(plans.value_or(std::vector<NodeApplyPlan>{}), {}, [&](ApplyReport r) { out = std::move(r); });
        canopen::waitUntil([&] { return out.has_value(); }, 60000);
        return out.value_or(ApplyReport{});
    }
};

const NodeComparison* nodeOf(const CompareReport& r, uint8_t node) {
    for (const auto& n : r.nodes)
        if (n.node == node) return &n;
    return nullptr;
}
std::vector<CompareRow> differing(const CompareReport& r) {
    std::vector<CompareRow> out;
    for (const auto& row : r.rows)
        if (row.state != RowState::Same) out.push_back(row);
    return out;
}
}  // namespace

class TestSvcProject : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;

private slots:
    void fileRoundTrip() {
        Project p;
        p.name = QStringLiteral("Press 4");
        p.busUrl = QStringLiteral("socketcan://can0");
        p.bitRate = 500000;
        ProjectNode n;
        n.id = 3;
        n.name = QStringLiteral("Axis Z");
        n.dictionary = QStringLiteral("delta-asda-a2");
        n.identity.vendorId = 0x1DD;
        n.identity.serial = 0x51000003;
        n.parameters = {{0x1017, 0, QStringLiteral("Producer heartbeat time"), QStringLiteral("0x00FA")},
                        {0x1A00, 1, QStringLiteral("Mapped object 1"), QStringLiteral("0x60410010")}};
        p.nodes.push_back(n);
        p.transmit.append(QJsonObject{{QStringLiteral("id"), 0x80}});
        p.unknown.insert(QStringLiteral("scripts"), QJsonArray{QStringLiteral("home.txt")});
        const QString path = dir_.filePath(QStringLiteral("press.coscope"));
        QString error;
        QVERIFY2(ProjectFile::write(p, path, &error), qPrintable(error));
        const ProjectReadResult r = ProjectFile::read(path);
        QVERIFY2(r.project, qPrintable(r.error));
        QCOMPARE(r.project->name, p.name);
        QCOMPARE(r.project->bitRate, 500000u);
        QCOMPARE(r.project->nodes.size(), size_t(1));
        const ProjectNode& back = r.project->nodes[0];
        QCOMPARE(back.identity.vendorId, std::optional<uint32_t>(0x1DD));
        QCOMPARE(back.identity.productCode, std::optional<uint32_t>());
        QCOMPARE(back.parameters.size(), size_t(2));
        QCOMPARE(back.parameters[1].index, uint16_t(0x1A00));
        QCOMPARE(back.parameters[1].value, QStringLiteral("0x60410010"));
        QCOMPARE(r.project->transmit.size(), 1);
        QCOMPARE(r.project->unknown.value(QStringLiteral("scripts")).toArray().size(), 1);  // unknown keys kept
        const QByteArray text = ProjectFile::serialize(*r.project);
        QVERIFY(text.contains("\"1017:00\""));
        QVERIFY(text.contains("TPDO1 mapping 1A00:01 = 0x60410010"));  // PDO layouts listed for people
    }

    void malformedFileNamesLineOrKey() {
        const ProjectReadResult syntax = ProjectFile::parse(
            "{\n  \"format\": 1,\n  \"nodes\": [\n    {\"id\": 1,}\n  ]\n}\n", QStringLiteral("m.coscope"));
        QVERIFY(!syntax.project);
        QVERIFY2(syntax.error.startsWith(QStringLiteral("m.coscope:4: error:")), qPrintable(syntax.error));
        const ProjectReadResult badId =
            ProjectFile::parse(R"({"format": 1, "nodes": [{"id": 1}, {"id": 200}]})", QStringLiteral("m.coscope"));
        QCOMPARE(badId.error, QStringLiteral("m.coscope: nodes[1].id: must be a node-ID 1-127"));
        const ProjectReadResult badObject = ProjectFile::parse(
            R"({"format": 1, "nodes": [{"id": 1, "parameters": [{"object": "60z1", "value": "1"}]}]})",
            QStringLiteral("m.coscope"));
        QVERIFY2(badObject.error.startsWith(QStringLiteral("m.coscope: nodes[0].parameters[0].object:")),
                 qPrintable(badObject.error));
        const ProjectReadResult newer = ProjectFile::parse(R"({"format": 9})", QStringLiteral("m.coscope"));
        QVERIFY2(newer.error.contains(QStringLiteral("format")) && newer.error.contains(QStringLiteral("newer")),
                 qPrintable(newer.error));
        const ProjectReadResult missing = ProjectFile::read(dir_.filePath(QStringLiteral("none.coscope")));
        QVERIFY(missing.error.contains(QStringLiteral("none.coscope")));
    }

    void backupKeepsWhatDiffersFromDefaults() {
        Machine m;
        QVERIFY(m.open());
        m.set(1, 0x1017, 0, 250);
        const Project p = m.backup();
        QCOMPARE(p.nodes.size(), size_t(3));
        const ProjectNode* n1 = p.node(1);
        QVERIFY(n1);
        QCOMPARE(n1->dictionary, QStringLiteral("delta-asda-a2"));
        QCOMPARE(n1->identity.vendorId, std::optional<uint32_t>(0x1DD));
        QCOMPARE(n1->identity.serial, std::optional<uint32_t>());  // the Delta dictionary has no 1018h:04
        QCOMPARE(p.node(3)->identity.serial, std::optional<uint32_t>(0x51000003));
        QVERIFY(n1->parameter(0x1017, 0));
        QCOMPARE(n1->parameter(0x1017, 0)->value, QStringLiteral("0x00FA"));
        QVERIFY(!n1->parameter(0x6081, 0));  // at its default: not configured
        QVERIFY(!n1->parameter(0x1018, 4));  // read-only: identity, not configuration
        QVERIFY(!n1->parameter(0x6040, 0));  // controlword: a command
        // The same machine compared with its backup is clean.
        const CompareReport same = m.compare(p);
        QVERIFY2(same.clean(), qPrintable(compareText(same, true)));
        QVERIFY(!same.rows.empty());
        // Written and read back, the same project.
        const QString path = dir_.filePath(QStringLiteral("machine.coscope"));
        QString error;
        QVERIFY(ProjectFile::write(p, path, &error));
        const auto back = ProjectFile::read(path);
        QVERIFY2(back.project, qPrintable(back.error));
        QCOMPARE(back.project->node(1)->parameters.size(), n1->parameters.size());
        QVERIFY(m.compare(*back.project).clean());
    }

    void compareNamesDifferencesReplacedMissingAndExtra() {
        Machine m;
        QVERIFY(m.open());
        m.set(1, 0x1017, 0, 250);
        Project p = m.backup();
        ProjectNode ghost = *p.node(2);
        ghost.id = 5;
        p.nodes.push_back(ghost);  // missing on the bus
        p.nodes.erase(std::find_if(p.nodes.begin(), p.nodes.end(),
                                   [](const auto& n) { return n.id == 2; }));  // node 2: not in project
        m.set(1, 0x1017, 0, 100);
        m.set(1, 0x6081, 0, 5000);
        p.node(1)->parameters.push_back(
            {0x6081, 0, {}, QStringLiteral("0x00002710")});  // the default, configured on purpose
        QString error;
        QVERIFY2(m.rig.network->replaceDevice(3, 0x51000099, &error), qPrintable(error));
        const CompareReport r = m.compare(p);
        QVERIFY(!r.clean());
        QCOMPARE(nodeOf(r, 1)->match, NodeMatch::Same);
        QCOMPARE(nodeOf(r, 2)->match, NodeMatch::NotInProject);
        QCOMPARE(nodeOf(r, 3)->match, NodeMatch::Replaced);
        QVERIFY2(nodeOf(r, 3)->detail.contains(QStringLiteral("0x51000099")), qPrintable(nodeOf(r, 3)->detail));
        QCOMPARE(nodeOf(r, 5)->match, NodeMatch::Missing);
        const auto diffs = differing(r);
        QCOMPARE(diffs.size(), size_t(2));
        QCOMPARE(diffs[0].index, uint16_t(0x1017));
        QCOMPARE(diffs[0].projectValue, QStringLiteral("0x00FA"));
        QCOMPARE(diffs[0].driveValue, QStringLiteral("0x0064"));
        QCOMPARE(diffs[0].defaultValue, QStringLiteral("0x0000"));
        QCOMPARE(diffs[1].index, uint16_t(0x6081));
        QCOMPARE(diffs[1].driveValue, QStringLiteral("0x00001388"));
        QCOMPARE(r.differences(), 2 + 3);
        // Another product at a project node-ID is a different device.
        Project other = p;
        other.node(1)->identity.productCode = 0x12345678;
        QCOMPARE(nodeOf(m.compare(other), 1)->match, NodeMatch::DifferentDevice);
        // Exports carry the rows.
        QVERIFY(compareCsv(r, true).contains(QStringLiteral("1,1017:00,")));
        QVERIFY(compareHtml(r, true).contains(QStringLiteral("replaced")));
        QVERIFY(QJsonDocument::fromJson(compareJson(r)).object().value(QStringLiteral("differences")).toInt() == 5);
    }

    void applyPutsTheProjectBack() {
        Machine m;
        QVERIFY(m.open());
        m.set(1, 0x1017, 0, 250);
        m.set(2, 0x1017, 0, 300);
        const Project p = m.backup();
        m.set(1, 0x1017, 0, 100);
        m.set(2, 0x1017, 0, 0);
        std::vector<NodeApplyPlan> plans;
        const ApplyReport r = m.apply(p, &plans);
        QVERIFY2(r.ok(), qPrintable(applyReportText(r)));
        QCOMPARE(plans.size(), size_t(3));
        QCOMPARE(plans[0].plan.writes.size(), size_t(1));  // only what differs
        QCOMPARE(plans[0].plan.writes[0].currentText, QStringLiteral("0x0064"));
        QVERIFY(applyPlanText(plans).contains(QStringLiteral("write 1017:00")));
        QCOMPARE(r.nodes[0].state, NodeApplyState::Written);
        QCOMPARE(r.nodes[2].state, NodeApplyState::NothingToWrite);
        QCOMPARE(m.value(1, 0x1017, 0)->toUInt64(), std::optional<uint64_t>(250));
        QCOMPARE(m.value(2, 0x1017, 0)->toUInt64(), std::optional<uint64_t>(300));
        QVERIFY(m.compare(p).clean());
    }

    void refusalRollsBackThatNodeAndStops() {
        Machine m;
        QVERIFY(m.open());
        m.set(1, 0x1017, 0, 250);
        m.set(1, 0x6081, 0, 5000);
        m.set(2, 0x1017, 0, 300);
        const Project p = m.backup();
        m.set(1, 0x1017, 0, 100);
        m.set(1, 0x6081, 0, 7000);
        m.set(2, 0x1017, 0, 0);
        // Node 1 refuses 6081h (written after 1017h): 1017h gets its old value back, node 2 is not written.
        m.rig.onDevice(1, [](sim::VirtualDevice& d) {
            d.sdoFaults().abortOn = std::make_tuple(uint16_t(0x6081), uint8_t(0), uint32_t(0x08000020));
        });
        const ApplyReport r = m.apply(p);
        QVERIFY(!r.ok());
        QCOMPARE(r.nodes[0].state, NodeApplyState::RefusedRolledBack);
        QVERIFY2(r.nodes[0].message.contains(QStringLiteral("6081:00")), qPrintable(r.nodes[0].message));
        QCOMPARE(r.nodes[0].writes.size(), size_t(2));
        QVERIFY(r.nodes[0].writes[0].ok);
        QCOMPARE(r.nodes[0].rollback.size(), size_t(1));
        QCOMPARE(r.nodes[1].state, NodeApplyState::NotReached);
        QCOMPARE(m.value(1, 0x1017, 0)->toUInt64(), std::optional<uint64_t>(100));  // old value back
        QCOMPARE(m.value(2, 0x1017, 0)->toUInt64(), std::optional<uint64_t>(0));    // untouched
        QVERIFY(applyReportText(r).contains(QStringLiteral("back   1017:00")));
    }

    void storeSavesTheParameters() {
        Machine m;
        QVERIFY(m.open());
        ProjectApply a(*m.sdo, eds::projectDictionaryResolver({}));
        std::optional<std::vector<canopen::ConfigEntryResult>> stored;
        m.set(1, 0x1017, 0, 250);
        a.store({1}, [&](std::vector<canopen::ConfigEntryResult> r) { stored = std::move(r); });
        QVERIFY(canopen::waitUntil([&] { return stored.has_value(); }, 10000));
        QCOMPARE(stored->size(), size_t(1));
        QVERIFY2(stored->at(0).ok, qPrintable(stored->at(0).error));
        m.rig.onDevice(1, [](sim::VirtualDevice& d) { d.powerCycle(); });
        QCOMPARE(m.value(1, 0x1017, 0)->toUInt64(), std::optional<uint64_t>(250));  // survived the power cycle
    }
};

QTEST_GUILESS_MAIN(TestSvcProject)
#include "test_svc_project.moc"
