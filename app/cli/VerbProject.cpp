// SPDX-License-Identifier: GPL-3.0-or-later
// coscope-cli project compare|backup|apply|program BUS FILE: the machine against its project file
// (README "Projects"): compare (exit 3 when the machine differs), back up into the file, apply the
// file (dry run first, --yes to write, --store to save in the nodes), load the project's programs
// into the nodes whose software differs (CiA 302-3, through the `program` verb's download).
#include "app/cli/BusSession.h"
#include "app/cli/CliVerb.h"
#include "app/cli/ProgramRun.h"
#include "core/canopen/ServiceWait.h"
#include "core/project/CompareReportFormat.h"
#include "core/project/ProjectApply.h"
#include "core/project/ProjectBackup.h"
#include "core/project/ProjectCompare.h"
#include "core/project/ProjectFile.h"
#include "core/project/ProjectSoftware.h"
#include "eds/ProjectDictionaries.h"
#include "eds/ScanMatcher.h"

#include <QFile>
#include <QFileInfo>
#include <QTextStream>

namespace coscope::cli {

namespace {

using namespace coscope::project;
using canopen::ProgramDownloadRequest;

constexpr int kDifferences = 3;  // compare: the machine is not as in the project
constexpr int kWaitMs = 3600000;

QCommandLineOption rangeOption() {
    return {QStringLiteral("nodes"), QStringLiteral("Node range scanned, FIRST-LAST (default 1-127)."),
            QStringLiteral("RANGE"), QStringLiteral("1-127")};
}

bool parseRange(const QString& text, uint8_t* first, uint8_t* last) {
    const QStringList r = text.split(u'-');
    const auto a = parseNodeId(r.value(0));
    const auto b = parseNodeId(r.value(r.size() - 1));
    if (!a || !b || *a > *b) return false;
    *first = *a;
    *last = *b;
    return true;
}

void addCommon(QCommandLineParser& p, const QString& description) {
    p.setApplicationDescription(description);
    p.addPositionalArgument(QStringLiteral("BUS"), QStringLiteral("Bus URL, e.g. socketcan://can0 or sim://"));
    p.addPositionalArgument(QStringLiteral("FILE"), QStringLiteral("The project file (*.coscope)"));
}

std::optional<Project> readProject(const QString& verb, const QString& path, int* code) {
    ProjectReadResult r = ProjectFile::read(path);
    if (!r.project) *code = failure(verb, r.error);
    return r.project;
}

bool openBus(const QString& verb, BusSession& s, const QString& url, int* code) {
    QString error;
    if (!s.open(url, &error)) {
        *code = failure(verb, error);
        return false;
    }
    if (s.bus()->isListenOnly()) {
        *code = failure(verb, QStringLiteral("cannot work on a listen-only bus: reading a node sends SDO requests"));
        return false;
    }
    return true;
}

QString folderOf(const QString& path) { return QFileInfo(path).absolutePath(); }

int runCompare(const QStringList& args) {
    const QString verb = QStringLiteral("project compare");
    QCommandLineParser p;
    addCommon(p,
              QStringLiteral("Compare the machine with its project: scan the bus, match each node by node-ID and "
                             "identity (1018h), read every configured "
                             "object. Exit 0 when the machine is as in the project, 3 when it differs, 1 on failure."));
    const QCommandLineOption format{QStringLiteral("format"), QStringLiteral("text (default), json or html."),
                                    QStringLiteral("FORMAT"), QStringLiteral("text")};
    const QCommandLineOption all{QStringLiteral("all"),
                                 QStringLiteral("text and html: also list the objects that are the same.")};
    const QCommandLineOption range = rangeOption();
    p.addOptions({format, all, range});
    int code = 0;
    if (!parseArgs(p, verb, args, &code)) return code;
    const QStringList pos = p.positionalArguments();
    if (pos.size() != 2) return usageError(verb, QStringLiteral("expects BUS FILE"));
    const QString fmt = p.value(format);
    if (fmt != QLatin1String("text") && fmt != QLatin1String("json") && fmt != QLatin1String("html"))
        return usageError(verb, QStringLiteral("--format must be text, json or html"));
    uint8_t first = 1, last = 127;
    if (!parseRange(p.value(range), &first, &last))
        return usageError(verb, QStringLiteral("--nodes must be FIRST-LAST within 1-127"));
    const auto project = readProject(verb, pos[1], &code);
    if (!project) return code;
    BusSession s;
    if (!openBus(verb, s, pos[0], &code)) return code;
    ProjectCompare compare(s.sdo(), eds::projectDictionaryResolver(folderOf(pos[1])));
    compare.setScanRange(first, last);
    compare.setMatcher(eds::scanMatcher());
    std::optional<CompareReport> report;
    compare.start(*project, {}, [&report](const CompareReport& r) { report = r; });
    canopen::waitUntil([&] { return report.has_value(); }, kWaitMs);
    if (!report) return failure(verb, QStringLiteral("the comparison did not finish"));
    QTextStream out(stdout);
    if (fmt == QLatin1String("json")) out << QString::fromUtf8(compareJson(*report));
    else if (fmt == QLatin1String("html")) out << compareHtml(*report, !p.isSet(all));
    else out << compareText(*report, !p.isSet(all));
    out.flush();
    return report->clean() ? Ok : kDifferences;
}

int runBackup(const QStringList& args) {
    const QString verb = QStringLiteral("project backup");
    QCommandLineParser p;
    addCommon(
        p,
        QStringLiteral(
            "Back up the machine into its project: scan the bus, read every node's objects and keep those that differ "
            "from the "
            "dictionary's defaults. A FILE that does not exist is made (nodes added with their matched dictionary)."));
    const QCommandLineOption range = rangeOption();
    p.addOptions({range});
    int code = 0;
    if (!parseArgs(p, verb, args, &code)) return code;
    const QStringList pos = p.positionalArguments();
    if (pos.size() != 2) return usageError(verb, QStringLiteral("expects BUS FILE"));
    uint8_t first = 1, last = 127;
    if (!parseRange(p.value(range), &first, &last))
        return usageError(verb, QStringLiteral("--nodes must be FIRST-LAST within 1-127"));
    Project project;
    project.busUrl = pos[0];
    project.name = QFileInfo(pos[1]).completeBaseName();
    if (QFile::exists(pos[1])) {
        const auto read = readProject(verb, pos[1], &code);
        if (!read) return code;
        project = *read;
    }
    BusSession s;
    if (!openBus(verb, s, pos[0], &code)) return code;
    if (project.busUrl.isEmpty()) project.busUrl = pos[0];
    if (!project.bitRate && s.bus()->url().bitrate() > 0)
        project.bitRate = static_cast<uint32_t>(s.bus()->url().bitrate());
    ProjectBackup backup(s.sdo(), eds::projectDictionaryResolver(folderOf(pos[1])));
    backup.setScanRange(first, last);
    backup.setMatcher(eds::scanMatcher());
    std::optional<std::pair<Project, std::vector<BackupNodeResult>>> done;
    backup.start(project, {},
                 [&done](const Project& pr, const std::vector<BackupNodeResult>& r) { done.emplace(pr, r); });
    canopen::waitUntil([&] { return done.has_value(); }, kWaitMs);
    if (!done) return failure(verb, QStringLiteral("the backup did not finish"));
    QTextStream out(stdout);
    int failed = 0;
    for (const BackupNodeResult& r : done->second) {
        out << "node " << r.node << (r.name.isEmpty() ? QString() : QStringLiteral(" (%1)").arg(r.name)) << ": "
            << (r.ok ? "ok" : "NOT BACKED UP") << " - " << r.message << "\n";
        failed += r.ok ? 0 : 1;
    }
    out.flush();
    QString error;
    if (!ProjectFile::write(done->first, pos[1], &error)) return failure(verb, error);
    out << done->first.nodes.size() << " node(s) in " << pos[1] << "\n";
    if (failed)
        return failure(verb,
                       QStringLiteral("%1 node(s) not backed up (their entries were kept as they were)").arg(failed));
    return Ok;
}

int runApply(const QStringList& args) {
    const QString verb = QStringLiteral("project apply");
    QCommandLineParser p;
    addCommon(p, QStringLiteral(
                     "Write the project's configuration to the machine: shows the SDO writes per node first (only "
                     "objects that differ), "
                     "writes only with --yes; the first refused write stops, that node's old values are put back."));
    const QCommandLineOption dryRun{QStringLiteral("dry-run"), QStringLiteral("Show the writes; write nothing.")};
    const QCommandLineOption yes{QStringLiteral("yes"), QStringLiteral("Write without asking (required to write).")};
    const QCommandLineOption store{
        QStringLiteral("store"),
        QStringLiteral("Then save the parameters in each written node (1010h:01 = \"save\").")};
    const QCommandLineOption report{QStringLiteral("report"), QStringLiteral("Also write the report to this file."),
                                    QStringLiteral("FILE")};
    const QCommandLineOption node{QStringLiteral("node"), QStringLiteral("Only this node (repeatable)."),
                                  QStringLiteral("ID")};
    p.addOptions({dryRun, yes, store, report, node});
    int code = 0;
    if (!parseArgs(p, verb, args, &code)) return code;
    const QStringList pos = p.positionalArguments();
    if (pos.size() != 2) return usageError(verb, QStringLiteral("expects BUS FILE"));
    if (p.isSet(dryRun) && (p.isSet(yes) || p.isSet(store)))
        return usageError(verb, QStringLiteral("--dry-run excludes --yes and --store"));
    std::vector<uint8_t> only;
    for (const QString& n : p.values(node)) {
        const auto id = parseNodeId(n);
        if (!id) return usageError(verb, QStringLiteral("--node '%1' must be 1-127").arg(n));
        only.push_back(*id);
    }
    const auto project = readProject(verb, pos[1], &code);
    if (!project) return code;
    BusSession s;
    if (!openBus(verb, s, pos[0], &code)) return code;
    ProjectApply apply(s.sdo(), eds::projectDictionaryResolver(folderOf(pos[1])));
    apply.setNodes(only);
    apply.setMatcher(eds::scanMatcher());
    std::optional<std::vector<NodeApplyPlan>> plans;
    apply.prepare(*project, {}, [&plans](std::vector<NodeApplyPlan> pl) { plans = std::move(pl); });
    canopen::waitUntil([&] { return plans.has_value(); }, kWaitMs);
    if (!plans) return failure(verb, QStringLiteral("reading the nodes did not finish"));
    QTextStream out(stdout);
    QString text = QStringLiteral("dry run:\n") + applyPlanText(*plans);
    out << text;
    out.flush();
    int writes = 0;
    for (const NodeApplyPlan& pl : *plans) writes += pl.writable() ? static_cast<int>(pl.plan.writes.size()) : 0;
    if (p.isSet(dryRun)) return Ok;
    if (writes > 0 && !p.isSet(yes))
        return failure(
            verb,
            QStringLiteral(
                "would write %1 object(s); nothing written: give --yes to write them (or --dry-run to only list them)")
                .arg(writes));
    std::optional<ApplyReport> result;
    apply.run(*plans, {}, [&result](ApplyReport r) { result = std::move(r); });
    canopen::waitUntil([&] { return result.has_value(); }, kWaitMs);
    if (!result) return failure(verb, QStringLiteral("the writes did not finish"));
    const QString reportText = applyReportText(*result);
    out << "result:\n" << reportText;
    text += QStringLiteral("result:\n") + reportText;
    bool storeFailed = false;
    if (result->ok() && p.isSet(store)) {
        std::vector<uint8_t> written;
        for (const NodeApplyResult& n : result->nodes)
            if (n.state == NodeApplyState::Written || n.state == NodeApplyState::NothingToWrite)
                written.push_back(n.node);
        std::optional<std::vector<canopen::ConfigEntryResult>> stored;
        apply.store(written, [&stored](std::vector<canopen::ConfigEntryResult> r) { stored = std::move(r); });
        canopen::waitUntil([&] { return stored.has_value(); }, kWaitMs);
        for (const auto& e : stored.value_or(std::vector<canopen::ConfigEntryResult>{})) {
            const QString line = QStringLiteral("%1 %2%3\n")
                                     .arg(e.ok ? QStringLiteral("stored ") : QStringLiteral("NOT STORED"), e.name,
                                          e.ok ? QString() : QStringLiteral(": ") + e.error);
            out << line;
            text += line;
            storeFailed |= !e.ok;
        }
    }
    out.flush();
    if (p.isSet(report)) {
        QFile f(p.value(report));
        if (!f.open(QIODevice::WriteOnly | QIODevice::Truncate))
            return failure(verb, QStringLiteral("%1: cannot write: %2").arg(f.fileName(), f.errorString()));
        f.write(text.toUtf8());
    }
    if (!result->ok()) return failure(verb, QStringLiteral("the project was not applied in full (see above)"));
    if (storeFailed) return failure(verb, QStringLiteral("a node did not store its parameters"));
    return Ok;
}

QString softwareLine(const CompareRow& r) {
    return QStringLiteral("  %1 %2 %3: project %4, node %5")
        .arg(rowStateName(r.state).leftJustified(10), objectKey(r.index, r.sub), r.name, r.projectValue,
             r.driveValue.isEmpty() ? QStringLiteral("-") : r.driveValue);
}

int runProgramProject(const QStringList& args) {
    const QString verb = QStringLiteral("project program");
    QCommandLineParser p;
    addCommon(p, QStringLiteral("Load the project's programs (CiA 302-3 program download): reads 1F56h and 100Ah of "
                                "every node whose project names a program, "
                                "and downloads the project's image (nodes[].firmware.file) to each node whose software "
                                "differs, as `program` does. "
                                "Nothing is sent without --yes."));
    const QCommandLineOption node{QStringLiteral("node"),
                                  QStringLiteral("Only this node, downloaded whatever its software says."),
                                  QStringLiteral("ID")};
    const QCommandLineOption yes{QStringLiteral("yes"),
                                 QStringLiteral("Download without asking (required to download).")};
    p.addOptions({node, yes});
    int code = 0;
    if (!parseArgs(p, verb, args, &code)) return code;
    const QStringList pos = p.positionalArguments();
    if (pos.size() != 2) return usageError(verb, QStringLiteral("expects BUS FILE"));
    std::vector<uint8_t> only;
    if (p.isSet(node)) {
        const auto id = parseNodeId(p.value(node));
        if (!id) return usageError(verb, QStringLiteral("--node '%1' must be 1-127").arg(p.value(node)));
        only.push_back(*id);
    }
    const auto project = readProject(verb, pos[1], &code);
    if (!project) return code;
    for (uint8_t id : only) {
        const ProjectNode* n = project->node(id);
        if (!n || !n->firmware || n->firmware->file.isEmpty())
            return failure(verb,
                           QStringLiteral("node %1 has no program in %2 (nodes[].firmware.file)").arg(id).arg(pos[1]));
    }
    BusSession s;
    if (!openBus(verb, s, pos[0], &code)) return code;
    std::optional<std::vector<SoftwareCheck>> checks;
    checkSoftware(s.sdo(), *project, only, [&checks](std::vector<SoftwareCheck> c) { checks = std::move(c); });
    canopen::waitUntil([&] { return checks.has_value(); }, kWaitMs);
    if (!checks) return failure(verb, QStringLiteral("reading the nodes' software did not finish"));
    QTextStream out(stdout);
    std::vector<ProgramDownloadRequest> downloads;
    for (const SoftwareCheck& c : *checks) {
        const ProjectNode& n = *project->node(c.node);
        out << "node " << c.node << ": " << c.state.summary() << "\n";
        for (const CompareRow& r : c.rows) out << softwareLine(r) << "\n";
        if (!only.empty() || c.differs()) {
            const QString file = n.firmware ? firmwareFile(*n.firmware, folderOf(pos[1])) : QString();
            if (file.isEmpty())
                return failure(
                    verb, QStringLiteral(
                              "node %1: its software differs and the project names no image (nodes[].firmware.file)")
                              .arg(c.node));
            QFile f(file);
            if (!f.open(QIODevice::ReadOnly))
                return failure(verb, QStringLiteral("node %1: %2: %3").arg(c.node).arg(file, f.errorString()));
            ProgramDownloadRequest req;
            req.node = c.node;
            req.program = n.firmware->program;
            req.image = f.readAll();
            if (req.image.isEmpty()) return failure(verb, QStringLiteral("%1 is empty").arg(file));
            printProgramPlan(out, req, file);
            downloads.push_back(std::move(req));
        }
    }
    if (downloads.empty()) {
        out << "every node runs the project's program\n";
        return Ok;
    }
    if (!p.isSet(yes))
        return failure(verb, QStringLiteral("nothing sent: give --yes to download the project's program to %1 node(s)")
                                 .arg(downloads.size()));
    for (const ProgramDownloadRequest& req : downloads) {
        const auto result = runProgramDownload(s, req, out);
        if (!result) return failure(verb, QStringLiteral("node %1: the download did not end").arg(req.node));
        if (!result->ok) return failure(verb, QStringLiteral("node %1: %2").arg(req.node).arg(result->summary()));
        // The node runs the new program: it must now answer what the project expects.
        for (const CompareRow& r : softwareRows(*project->node(req.node), result->after))
            if (r.state != RowState::Same)
                return failure(verb,
                               QStringLiteral("node %1 took the program but answers %2 %3, the project expects %4")
                                   .arg(req.node)
                                   .arg(r.name, r.driveValue.isEmpty() ? QStringLiteral("nothing") : r.driveValue,
                                        r.projectValue));
    }
    out << downloads.size() << " node(s) run the project's program\n";
    return Ok;
}

}  // namespace

COSCOPE_CLI_VERB({QStringLiteral("project compare"),
                  QStringLiteral("Compare the machine with its project file (exit 3: differs)."), runCompare});
COSCOPE_CLI_VERB({QStringLiteral("project backup"),
                  QStringLiteral("Read every node's configuration into a project file."), runBackup});
COSCOPE_CLI_VERB(
    {QStringLiteral("project program"),
     QStringLiteral("Download the project's programs to the nodes whose software differs (--node, --yes)."),
     runProgramProject});
COSCOPE_CLI_VERB({QStringLiteral("project apply"),
                  QStringLiteral("Write a project's configuration to the machine (--dry-run, --yes, --store)."),
                  runApply});

}  // namespace coscope::cli
