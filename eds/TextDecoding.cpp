// SPDX-License-Identifier: GPL-3.0-or-later
#include "eds/TextDecoding.h"

#include <QStringDecoder>

namespace coscope::eds {

namespace {

// Windows-1252 code points for bytes 0x80..0x9F (0 = undefined, kept as the C1 control).
constexpr char16_t kCp1252High[32] = {0x20AC, 0,      0x201A, 0x0192, 0x201E, 0x2026, 0x2020, 0x2021,
                                      0x02C6, 0x2030, 0x0160, 0x2039, 0x0152, 0,      0x017D, 0,
                                      0,      0x2018, 0x2019, 0x201C, 0x201D, 0x2022, 0x2013, 0x2014,
                                      0x02DC, 0x2122, 0x0161, 0x203A, 0x0153, 0,      0x017E, 0x0178};

QString fromCp1252(const QByteArray& b) {
    QString s;
    s.resize(b.size());
    QChar* out = s.data();
    for (qsizetype i = 0; i < b.size(); ++i) {
        const auto c = static_cast<unsigned char>(b[i]);
        char16_t u = c;
        if (c >= 0x80 && c <= 0x9F && kCp1252High[c - 0x80]) u = kCp1252High[c - 0x80];
        out[i] = QChar(u);
    }
    return s;
}

}  // namespace

QString decodeDictionaryText(const QByteArray& bytes, QString* encoding) {
    auto set = [&](const char* e) {
        if (encoding) *encoding = QString::fromLatin1(e);
    };
    if (bytes.startsWith("\xEF\xBB\xBF")) {
        QStringDecoder d(QStringDecoder::Utf8);
        QString s = d.decode(bytes.mid(3));
        if (!d.hasError()) {
            set("UTF-8");
            return s;
        }
        set("Windows-1252");
        return fromCp1252(bytes.mid(3));
    }
    if (bytes.startsWith("\xFF\xFE") || bytes.startsWith("\xFE\xFF")) {
        const bool le = bytes.startsWith("\xFF\xFE");
        QStringDecoder d(le ? QStringDecoder::Utf16LE : QStringDecoder::Utf16BE);
        set(le ? "UTF-16LE" : "UTF-16BE");
        return d.decode(bytes.mid(2));
    }
    QStringDecoder d(QStringDecoder::Utf8);
    QString s = d.decode(bytes);
    if (!d.hasError()) {
        set("UTF-8");
        return s;
    }
    set("Windows-1252");
    return fromCp1252(bytes);
}

}  // namespace coscope::eds
