// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/help/AboutBox.h"

#include "app/BuildInfo.h"

#include <QApplication>
#include <QCoreApplication>
#include <QMessageBox>

namespace coscope::gui::help {

namespace {
struct AboutBox {
    Q_DECLARE_TR_FUNCTIONS(AboutBox)
};
}  // namespace

QString aboutText() {
    QStringList p;
    p << QStringLiteral("<h3>CoScope %1</h3>").arg(buildinfo::version().toHtmlEscaped());
    p << QStringLiteral("<p>%1</p>").arg(AboutBox::tr("CANopen bus analyzer and servo-drive commissioning tool."));
    p << QStringLiteral("<p>%1</p>")
             .arg(AboutBox::tr("Version %1, source revision %2, built with Qt %3 (running on Qt %4).")
                      .arg(buildinfo::version(), buildinfo::revision(), QStringLiteral(QT_VERSION_STR),
                           QString::fromLatin1(qVersion()))
                      .toHtmlEscaped());
    p << QStringLiteral("<p>%1</p>")
             .arg(AboutBox::tr("CoScope is free software under the GNU General Public License, version 3 or later "
                               "(GPL-3.0-or-later), and comes with no warranty."));
    p << QStringLiteral("<p>%1</p><ul><li>%2</li><li>%3</li><li>%4</li></ul>")
             .arg(AboutBox::tr("It is built on:"),
                  AboutBox::tr("Qt, under the GNU Lesser General Public License version 3 (LGPLv3)"),
                  AboutBox::tr("QCustomPlot, under the GNU General Public License version 3 (GPLv3)"),
                  AboutBox::tr("spdlog and fmt, under the MIT license"));
    return p.join(QString());
}

void showAbout(QWidget* parent) {
    QMessageBox box(QMessageBox::Information, AboutBox::tr("About CoScope"), aboutText(), QMessageBox::Ok, parent);
    box.setObjectName(QStringLiteral("aboutBox"));
    box.setTextFormat(Qt::RichText);
    box.setIconPixmap(QApplication::windowIcon().pixmap(64, 64));
    box.exec();
}

}  // namespace coscope::gui::help
