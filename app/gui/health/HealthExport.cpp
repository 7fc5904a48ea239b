// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/health/HealthExport.h"

#include "dissectors/HealthOutput.h"

#include <QBuffer>
#include <QFont>
#include <QPageLayout>
#include <QPageSize>
#include <QPdfWriter>
#include <QRegularExpression>
#include <QSaveFile>
#include <QTextDocument>
#include <QUrl>

namespace coscope::gui {

namespace {
bool saveBytes(const QString& path, const QByteArray& bytes, QString* error) {
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly) || file.write(bytes) != bytes.size() || !file.commit()) {
        if (error) *error = QStringLiteral("%1: %2").arg(path, file.errorString());
        return false;
    }
    return true;
}
}  // namespace

bool writeHealthHtml(const QString& path, const dissect::HealthReport& report, const QString& title, QString* error) {
    return saveBytes(path, dissect::healthHtml(report, title), error);
}

bool writeHealthPdf(const QString& path, const dissect::HealthReport& report, const QString& title,
                    const QImage& loadChart, QString* error) {
    QString html = QString::fromUtf8(dissect::healthHtml(report, title));
    // Qt's rich text draws no SVG: the chart as a picture instead.
    static const QRegularExpression svg(QStringLiteral("<svg[^>]*>.*?</svg>"),
                                        QRegularExpression::DotMatchesEverythingOption);
    html.replace(svg, loadChart.isNull() ? QString() : QStringLiteral("<img src='coscope:loadchart' width='640'>"));
    // The severity badge's padding is CSS that Qt's rich text does not apply: a space instead.
    html.replace(QStringLiteral("<span class='sev'>"), QStringLiteral("<span class='sev'>["));
    html.replace(QRegularExpression(QStringLiteral("(<span class='sev'>\\[[^<]*)</span>")),
                 QStringLiteral("\\1]</span> "));
    QByteArray pdf;
    {
        QBuffer buffer(&pdf);
        buffer.open(QIODevice::WriteOnly);
        QPdfWriter writer(&buffer);
        writer.setTitle(title);
        writer.setCreator(QStringLiteral("CoScope"));
        writer.setPageSize(QPageSize(QPageSize::A4));
        writer.setPageMargins(QMarginsF(15, 15, 15, 15), QPageLayout::Millimeter);
        writer.setResolution(150);
        QTextDocument doc;
        if (!loadChart.isNull())
            doc.addResource(QTextDocument::ImageResource, QUrl(QStringLiteral("coscope:loadchart")), loadChart);
        doc.setDefaultFont(QFont(QStringLiteral("DejaVu Sans"), 9));
        doc.setHtml(html);
        doc.setPageSize(writer.pageLayout().paintRectPixels(writer.resolution()).size());
        doc.print(&writer);
    }
    return saveBytes(path, pdf, error);
}

}  // namespace coscope::gui
