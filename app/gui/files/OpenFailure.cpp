// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/files/OpenFailure.h"

#include <QCoreApplication>
#include <QFileInfo>
#include <QMessageBox>

namespace coscope::gui {

namespace {
struct OpenFailure {
    Q_DECLARE_TR_FUNCTIONS(OpenFailure)
};
}  // namespace

void showOpenFailed(QWidget* parent, const QString& path, const QString& error) {
    QMessageBox box(QMessageBox::Warning, OpenFailure::tr("Open log"),
                    OpenFailure::tr("%1 could not be opened as a CAN log.").arg(QFileInfo(path).fileName()),
                    QMessageBox::Ok, parent);
    box.setObjectName(QStringLiteral("openFailedBox"));
    box.setInformativeText(error + QStringLiteral("\n\n") +
                           OpenFailure::tr("Nothing was changed: the trace, nodes and signals shown are kept."));
    box.exec();
}

void showReadFailed(QWidget* parent, const QString& path, const QString& error, size_t framesShown) {
    auto* box = new QMessageBox(QMessageBox::Warning, OpenFailure::tr("Open log"),
                                OpenFailure::tr("Reading %1 stopped at an error.").arg(QFileInfo(path).fileName()),
                                QMessageBox::Ok, parent);
    box->setObjectName(QStringLiteral("readFailedBox"));
    box->setInformativeText(error + QStringLiteral("\n\n") +
                            OpenFailure::tr("The %L1 frames read before it are shown.").arg(framesShown));
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->open();  // not exec(): the window goes on refreshing behind it
}

}  // namespace coscope::gui
