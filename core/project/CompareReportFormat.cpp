// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/project/CompareReportFormat.h"

#include "core/logio/CsvField.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTextStream>

namespace coscope::project {

using logio::csvField;

namespace {
bool shown(const CompareRow& r, bool onlyDifferences) { return !onlyDifferences || r.state != RowState::Same; }

}  // namespace

QString compareText(const CompareReport& report, bool onlyDifferences) {
    QString text;
    QTextStream out(&text);
    for (const NodeComparison& n : report.nodes) {
        out << "node " << n.node << (n.name.isEmpty() ? QString() : QStringLiteral(" (%1)").arg(n.name)) << ": "
            << nodeMatchName(n.match);
        if (!n.detail.isEmpty()) out << " - " << n.detail;
        if (n.differences || n.unreadable)
            out << "; " << n.differences << " object(s) differ, " << n.unreadable << " unreadable";
        out << "\n";
        for (const CompareRow& r : report.rows) {
            if (r.node != n.node || !shown(r, onlyDifferences)) continue;
            out << "  " << rowStateName(r.state).leftJustified(10) << " " << objectKey(r.index, r.sub) << " " << r.name
                << ": project " << r.projectValue << ", drive "
                << (r.driveValue.isEmpty() ? QStringLiteral("-") : r.driveValue) << ", default "
                << (r.defaultValue.isEmpty() ? QStringLiteral("-") : r.defaultValue);
            if (!r.error.isEmpty()) out << " (" << r.error << ")";
            out << "\n";
        }
    }
    out << (report.clean() ? QStringLiteral("the machine is as in the project\n")
                           : QStringLiteral("%1 difference(s)\n").arg(report.differences()));
    return text;
}

QByteArray compareJson(const CompareReport& report) {
    QJsonObject top;
    top.insert(QStringLiteral("project"), report.projectName);
    top.insert(QStringLiteral("bus"), report.busUrl);
    top.insert(QStringLiteral("clean"), report.clean());
    top.insert(QStringLiteral("differences"), report.differences());
    QJsonArray nodes;
    for (const NodeComparison& n : report.nodes) {
        QJsonObject o;
        o.insert(QStringLiteral("node"), n.node);
        o.insert(QStringLiteral("name"), n.name);
        o.insert(QStringLiteral("state"), nodeMatchName(n.match));
        o.insert(QStringLiteral("detail"), n.detail);
        o.insert(QStringLiteral("differences"), n.differences);
        o.insert(QStringLiteral("unreadable"), n.unreadable);
        nodes.append(o);
    }
    top.insert(QStringLiteral("nodes"), nodes);
    QJsonArray rows;
    for (const CompareRow& r : report.rows) {
        QJsonObject o;
        o.insert(QStringLiteral("node"), r.node);
        o.insert(QStringLiteral("object"), objectKey(r.index, r.sub));
        o.insert(QStringLiteral("name"), r.name);
        o.insert(QStringLiteral("project"), r.projectValue);
        o.insert(QStringLiteral("drive"), r.driveValue);
        o.insert(QStringLiteral("default"), r.defaultValue);
        o.insert(QStringLiteral("state"), rowStateName(r.state));
        if (!r.error.isEmpty()) o.insert(QStringLiteral("error"), r.error);
        rows.append(o);
    }
    top.insert(QStringLiteral("objects"), rows);
    return QJsonDocument(top).toJson(QJsonDocument::Indented);
}

QString compareHtml(const CompareReport& report, bool onlyDifferences) {
    QString html;
    QTextStream out(&html);
    const QString title =
        report.projectName.isEmpty() ? QStringLiteral("Machine and project") : report.projectName.toHtmlEscaped();
    out << "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>" << title << "</title>\n"
        << "<style>body{font-family:sans-serif}table{border-collapse:collapse}td,th{border:1px solid #bbb;padding:2px "
           "6px;text-align:left}"
           ".differs{background:#fde2c8}.unreadable{background:#eee}.bad{color:#a00}</style></head><body>\n"
        << "<h1>" << title << "</h1>\n<p>Bus " << report.busUrl.toHtmlEscaped() << ": "
        << (report.clean() ? QStringLiteral("the machine is as in the project")
                           : QStringLiteral("%1 difference(s)").arg(report.differences()))
        << "</p>\n"
        << "<h2>Nodes</h2>\n<table><tr><th>Node</th><th>Name</th><th>State</th><th>Detail</th><th>Objects "
           "differing</th><th>Unreadable</th></tr>\n";
    for (const NodeComparison& n : report.nodes)
        out << "<tr" << (n.match == NodeMatch::Same ? "" : " class=\"bad\"") << "><td>" << n.node << "</td><td>"
            << n.name.toHtmlEscaped() << "</td><td>" << nodeMatchName(n.match) << "</td><td>"
            << n.detail.toHtmlEscaped() << "</td><td>" << n.differences << "</td><td>" << n.unreadable
            << "</td></tr>\n";
    out << "</table>\n<h2>Objects</h2>\n<table><tr><th>Node</th><th>Object</th><th>Name</th><th>Project</th><th>Drive</"
           "th><th>Default</th><th>State</th></tr>\n";
    for (const CompareRow& r : report.rows) {
        if (!shown(r, onlyDifferences)) continue;
        out << "<tr class=\"" << rowStateName(r.state) << "\"><td>" << r.node << "</td><td>"
            << objectKey(r.index, r.sub) << "</td><td>" << r.name.toHtmlEscaped() << "</td><td>"
            << r.projectValue.toHtmlEscaped() << "</td><td>"
            << (r.driveValue.isEmpty() ? r.error : r.driveValue).toHtmlEscaped() << "</td><td>"
            << r.defaultValue.toHtmlEscaped() << "</td><td>" << rowStateName(r.state) << "</td></tr>\n";
    }
    out << "</table>\n</body></html>\n";
    return html;
}

QString compareCsv(const CompareReport& report, bool onlyDifferences) {
    QString csv;
    QTextStream out(&csv);
    out << "node,object,name,project,drive,default,state,note\r\n";
    for (const NodeComparison& n : report.nodes)
        if (n.match != NodeMatch::Same)
            out << n.node << ",,,"
                << ",,," << csvField(nodeMatchName(n.match)) << "," << csvField(n.detail) << "\r\n";
    for (const CompareRow& r : report.rows) {
        if (!shown(r, onlyDifferences)) continue;
        out << r.node << "," << objectKey(r.index, r.sub) << "," << csvField(r.name) << "," << csvField(r.projectValue)
            << "," << csvField(r.driveValue) << "," << csvField(r.defaultValue) << "," << rowStateName(r.state) << ","
            << csvField(r.error) << "\r\n";
    }
    return csv;
}

}  // namespace coscope::project
