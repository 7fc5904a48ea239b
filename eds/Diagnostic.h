// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QSet>
#include <QString>

#include <vector>

namespace coscope::eds {

// One finding about a dictionary file, printed as "FILE:LINE: warning|error: message"
// (line 0 = the file as a whole: "FILE: error: message").
struct Diagnostic {
    enum class Severity { Warning, Error };
    QString file;
    int line = 0;
    Severity severity = Severity::Warning;
    QString message;

    QString toString() const;
};

using Diagnostics = std::vector<Diagnostic>;

// Collects diagnostics for one file.
class DiagnosticSink {
public:
    explicit DiagnosticSink(QString file) : file_(std::move(file)) {}
    // The same message for the same line is reported once.
    void warning(int line, const QString& message) { add(line, Diagnostic::Severity::Warning, message); }
    void error(int line, const QString& message) { add(line, Diagnostic::Severity::Error, message); }
    const QString& file() const { return file_; }
    Diagnostics take() { return std::move(list_); }
    const Diagnostics& list() const { return list_; }

private:
    void add(int line, Diagnostic::Severity sev, const QString& message) {
        const QString key = QString::number(line) + u'|' + message;
        if (seen_.contains(key)) return;
        seen_.insert(key);
        list_.push_back({file_, line, sev, message});
    }
    QSet<QString> seen_;
    QString file_;
    Diagnostics list_;
};

}  // namespace coscope::eds
