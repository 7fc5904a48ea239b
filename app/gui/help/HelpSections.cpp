// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/help/HelpSections.h"

#include <QWidget>
#include <QWizard>

#include <map>

namespace coscope::gui::help {

namespace {
// The guide's sectionTable (docs/guide/*.md, "<!-- #anchor -->" before a heading) by the objectName of
// a dock or the class of a wizard or one of its pages. A new part may set the property
// "helpSection" on itself instead.
const std::map<QString, QString>& sectionTable() {
    static const std::map<QString, QString> table = {
        {QStringLiteral("TraceDock"), QStringLiteral("trace")},
        {QStringLiteral("NodesDock"), QStringLiteral("nodes")},
        {QStringLiteral("ObjectDictionaryDock"), QStringLiteral("od")},
        {QStringLiteral("PlotDock"), QStringLiteral("plot")},
        {QStringLiteral("EventsDock"), QStringLiteral("events")},
        {QStringLiteral("HealthDock"), QStringLiteral("health")},
        {QStringLiteral("ConsoleDock"), QStringLiteral("console")},
        {QStringLiteral("TransmitDock"), QStringLiteral("transmit")},
        {QStringLiteral("processDataDock"), QStringLiteral("processdata")},
        {QStringLiteral("ConnectDialog"), QStringLiteral("connect")},
        {QStringLiteral("NodeIdWizard"), QStringLiteral("wizard-nodeid")},
        {QStringLiteral("NodeIdFindPage"), QStringLiteral("wizard-nodeid-find")},
        {QStringLiteral("NodeIdChangePage"), QStringLiteral("wizard-nodeid-change")},
        {QStringLiteral("NodeIdRunPage"), QStringLiteral("wizard-nodeid-run")},
        {QStringLiteral("PdoWizard"), QStringLiteral("wizard-pdo")},
        {QStringLiteral("PdoChoosePage"), QStringLiteral("wizard-pdo-choose")},
        {QStringLiteral("PdoMappingPage"), QStringLiteral("wizard-pdo-mapping")},
        {QStringLiteral("PdoTimingPage"), QStringLiteral("wizard-pdo-timing")},
        {QStringLiteral("PdoApplyPage"), QStringLiteral("wizard-pdo-apply")},
        {QStringLiteral("Ds402Wizard"), QStringLiteral("wizard-ds402")},
        {QStringLiteral("Ds402HomingBox"), QStringLiteral("wizard-ds402-homing")},
        {QStringLiteral("Ds402PositionMoveBox"), QStringLiteral("wizard-ds402-position")},
    };
    return table;
}

QString sectionNamed(const QString& name) {
    const auto it = sectionTable().find(name);
    return it == sectionTable().end() ? QString() : it->second;
}

QString unqualifiedClassName(const QObject* o) {
    const QString full = QString::fromLatin1(o->metaObject()->className());
    return full.mid(full.lastIndexOf(u':') + 1);  // without "coscope::gui::"
}
}  // namespace

QString sectionFor(const QWidget* w) {
    for (; w; w = w->parentWidget()) {
        if (const QVariant p = w->property("helpSection"); p.isValid()) return p.toString();
        if (QString a = sectionNamed(w->objectName()); !a.isEmpty()) return a;
        // The focus on a wizard's own buttons: the page it shows.
        if (auto* wizard = qobject_cast<const QWizard*>(w); wizard && wizard->currentPage())
            if (QString a = sectionNamed(unqualifiedClassName(wizard->currentPage())); !a.isEmpty()) return a;
        if (QString a = sectionNamed(unqualifiedClassName(w)); !a.isEmpty()) return a;
    }
    return {};
}

}  // namespace coscope::gui::help
