// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/language/Language.h"

#include "dissectors/VendorTable.h"

#include <QCoreApplication>
#include <QLibraryInfo>
#include <QSettings>
#include <QTranslator>

#include <spdlog/spdlog.h>

namespace coscope::gui::language {

namespace {
const QString kKey = QStringLiteral("ui/language");

struct Installed {
    QTranslator app;
    QTranslator qt;  // QDialogButtonBox, QWizard, QMessageBox, QFileDialog texts
    QString code = QStringLiteral("en");
};

Installed& installed() {
    static Installed i;
    return i;
}
}  // namespace

QStringList available() { return {QStringLiteral("en"), QStringLiteral("zh_TW"), QStringLiteral("zh_CN")}; }

QString nativeName(const QString& code) {
    if (code == u"zh_TW") return QStringLiteral("繁體中文");
    if (code == u"zh_CN") return QStringLiteral("简体中文");
    return QStringLiteral("English");
}

QString forLocale(const QLocale& locale) {
    if (locale.language() != QLocale::Chinese) return QStringLiteral("en");
    if (locale.script() == QLocale::TraditionalChineseScript) return QStringLiteral("zh_TW");
    if (locale.script() == QLocale::SimplifiedChineseScript) return QStringLiteral("zh_CN");
    const auto t = locale.territory();
    const bool traditional = t == QLocale::Taiwan || t == QLocale::HongKong || t == QLocale::Macao;
    return traditional ? QStringLiteral("zh_TW") : QStringLiteral("zh_CN");
}

QString saved() { return QSettings().value(kKey).toString(); }

void save(const QString& code) {
    QSettings s;
    if (code.isEmpty()) s.remove(kKey);
    else s.setValue(kKey, code);
}

QString resolve(const QString& code) { return available().contains(code) ? code : forLocale(QLocale::system()); }

bool apply(const QString& wanted) {
    const QString code = resolve(wanted);
    Installed& i = installed();
    QCoreApplication::removeTranslator(&i.app);
    QCoreApplication::removeTranslator(&i.qt);
    i.code = QStringLiteral("en");
    // Vendor alarm and parameter names (resources/alarms, dictionary sidecars) follow the UI.
    dissect::setVendorTextLanguage(i.code);
    if (code == u"en") return true;
    if (!i.app.load(QStringLiteral(":/i18n/coscope_%1.qm").arg(code))) {
        spdlog::warn("no translation for {} in the program; the UI stays in English", code.toStdString());
        return false;
    }
    // Qt's own texts come with the system (Debian qt6-translations-l10n); without them those stay English.
    if (i.qt.load(QStringLiteral("qtbase_%1").arg(code), QLibraryInfo::path(QLibraryInfo::TranslationsPath)))
        QCoreApplication::installTranslator(&i.qt);
    else
        spdlog::info("Qt's own translation qtbase_{} not found; its dialog buttons stay in English",
                     code.toStdString());
    QCoreApplication::installTranslator(&i.app);
    i.code = code;
    dissect::setVendorTextLanguage(code);
    return true;
}

QString current() { return installed().code; }

}  // namespace coscope::gui::language
