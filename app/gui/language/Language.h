// SPDX-License-Identifier: GPL-3.0-or-later
// Folder app/gui/language/ owns the UI language: which translation is loaded (the system locale,
// `coscope --lang`, View ▸ Language) and the remembered choice. The CLI never loads one.
#pragma once

#include <QLocale>
#include <QString>
#include <QStringList>

namespace coscope::gui::language {

// The languages the app speaks: "en" (the source texts), "zh_TW", "zh_CN".
QStringList available();

// A language's name in its own script ("English", "繁體中文", "简体中文"): never translated, so a
// reader finds their language whatever the UI shows now.
QString nativeName(const QString& code);

// The available language for a locale: Traditional Chinese for zh_TW/zh_HK/zh_MO and zh-Hant,
// Simplified Chinese for other Chinese locales, English otherwise.
QString forLocale(const QLocale& locale);

// The user's choice from View ▸ Language (QSettings "ui/language"); empty = follow the system.
QString saved();
void save(const QString& code);

// "" or an unknown code resolve to the system locale's language.
QString resolve(const QString& code);

// Loads the app's and Qt's own translations for `code` (resolved) and installs them, replacing
// the ones loaded before; "en" removes them. Qt then sends every widget QEvent::LanguageChange.
// Returns false when the embedded translation could not be loaded (English stays).
bool apply(const QString& wanted);

// The language apply() installed last ("en" before the first call).
QString current();

}  // namespace coscope::gui::language
