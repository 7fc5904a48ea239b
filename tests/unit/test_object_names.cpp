// SPDX-License-Identifier: GPL-3.0-or-later
// The standard objects of the bundled dictionaries named as the Chinese manuals name them
// (issue 17; resources/dictionaries/NAME.json "objectNames", glossary.md "Standard objects"):
// zh_TW and zh_CN for a bundled dictionary, the EDS's own words in English and for a dictionary
// the user loads from a file.
#include "dissectors/ObjectNames.h"
#include "eds/DictionaryLibrary.h"

#include <QDir>
#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>

using namespace coscope;
using dissect::localDisplayName;
using dissect::localObjectName;

namespace {
const QString kTW = QStringLiteral("zh_TW"), kCN = QStringLiteral("zh_CN"), kEN = QStringLiteral("en");

od::ObjectDictionary bundled(const QString& name) {
    const eds::ReadResult r = eds::DictionaryLibrary().load(name);
    return r.dictionary;
}
}  // namespace

class TestObjectNames : public QObject {
    Q_OBJECT
private slots:
    void bundledDictionaryKnowsItsName() {
        QCOMPARE(bundled(QStringLiteral("delta-asda-a2")).bundledName, QStringLiteral("delta-asda-a2"));
        QCOMPARE(bundled(QStringLiteral("generic-cia402")).bundledName, QStringLiteral("generic-cia402"));
    }

    // Statusword, controlword, device type, identity: the glossary's words in each script.
    void standardObjectsInBothScripts() {
        const od::ObjectDictionary delta = bundled(QStringLiteral("delta-asda-a2"));
        QCOMPARE(localObjectName(delta.bundledName, 0x6041, -1, QStringLiteral("Statusword"), kTW),
                 QStringLiteral(u"狀態字"));
        QCOMPARE(localObjectName(delta.bundledName, 0x6041, -1, QStringLiteral("Statusword"), kCN),
                 QStringLiteral(u"状态字"));
        QCOMPARE(localObjectName(delta.bundledName, 0x6040, -1, QStringLiteral("Controlword"), kTW),
                 QStringLiteral(u"控制字"));
        QCOMPARE(localObjectName(delta.bundledName, 0x6040, -1, QStringLiteral("Controlword"), kCN),
                 QStringLiteral(u"控制字"));
        QCOMPARE(localDisplayName(delta, 0x1000, 0, kTW), QStringLiteral(u"裝置類型"));
        QCOMPARE(localDisplayName(delta, 0x1000, 0, kCN), QStringLiteral(u"设备类型"));
        QCOMPARE(localDisplayName(delta, 0x1018, 1, kTW), QStringLiteral(u"廠商ID標示物件: 供應商 ID"));
        QCOMPARE(localDisplayName(delta, 0x1018, 1, kCN), QStringLiteral(u"厂商ID标示对象: 供应商 ID"));
        QCOMPARE(localDisplayName(delta, 0x1A00, 1, kTW), QStringLiteral(u"TPDO1 映射參數: 映射物件 1"));
        QCOMPARE(localDisplayName(delta, 0x1800, 2, kCN), QStringLiteral(u"TPDO1 通讯参数: 传输类型"));
        const od::ObjectDictionary aimotor = bundled(QStringLiteral("aimotor"));
        QCOMPARE(localDisplayName(aimotor, 0x6060, 0, kCN), QStringLiteral(u"运行模式设置"));  // [A] 2.1.1
        QCOMPARE(localDisplayName(aimotor, 0x6060, 0, kTW), QStringLiteral(u"操作模式"));      // [I] 6.6
        // A vendor parameter keeps its code and takes the manual's name (ParameterNames.h).
        QCOMPARE(localDisplayName(delta, 0x2300, 0, kTW), QStringLiteral(u"P3-00 ADR 局號設定"));
    }

    void englishIsTheEdsName() {
        const od::ObjectDictionary delta = bundled(QStringLiteral("delta-asda-a2"));
        QCOMPARE(localObjectName(delta.bundledName, 0x6041, -1, QStringLiteral("Statusword"), kEN),
                 QStringLiteral("Statusword"));
        QCOMPARE(localDisplayName(delta, 0x1018, 1, kEN), delta.displayName(0x1018, 1));
        QCOMPARE(localDisplayName(delta, 0x2300, 0, kEN), QStringLiteral("P3-00 ADR Node-ID (station number)"));
    }

    // The same EDS loaded from the user's file: his words stay as written, in every language.
    void userFileStaysAsWritten() {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString path = dir.filePath(QStringLiteral("delta-asda-a2.eds"));
        QVERIFY(QFile::copy(QStringLiteral(":/dictionaries/delta-asda-a2.eds"), path));
        const eds::ReadResult r = eds::DictionaryLibrary::loadFile(path);
        QVERIFY(r.usable);
        QVERIFY(r.dictionary.bundledName.isEmpty());
        for (const QString& lang : {kTW, kCN, kEN}) {
            QCOMPARE(localDisplayName(r.dictionary, 0x6041, 0, lang), QStringLiteral("Statusword"));
            QCOMPARE(localDisplayName(r.dictionary, 0x1000, 0, lang), QStringLiteral("Device type"));
        }
        QCOMPARE(localObjectName(QString(), 0x6041, -1, QStringLiteral("Statusword"), kTW),
                 QStringLiteral("Statusword"));
    }

    // ICP DAS ECAT-2094P: four axes, index + 800h each; the EDS's axis becomes the manual's 第 n 軸.
    void axesOfAMultiAxisDrive() {
        const od::ObjectDictionary icp = bundled(QStringLiteral("icpdas-ecat-2094p"));
        QCOMPARE(localDisplayName(icp, 0x6841, 0, kTW), QStringLiteral(u"狀態字（第 2 軸）"));
        QCOMPARE(localDisplayName(icp, 0x7040, 0, kCN), QStringLiteral(u"控制字（第 3 轴）"));
        QCOMPARE(localDisplayName(icp, 0x6041, 0, kEN), QStringLiteral("Statusword (axis 1)"));
    }

    // Each name of each sidecar is an entry of its EDS, in both scripts, with its source.
    void everySidecarNameIsComplete() {
        static const QRegularExpression han(QStringLiteral("\\p{Han}"));
        for (const QString& name : eds::DictionaryLibrary().names()) {
            QFile f(QStringLiteral(":/dictionaries/%1.json").arg(name));
            if (!f.open(QIODevice::ReadOnly)) continue;
            const QJsonObject names =
                QJsonDocument::fromJson(f.readAll()).object().value(QStringLiteral("objectNames")).toObject();
            QVERIFY2(names.size() > 100, qPrintable(name));
            const od::ObjectDictionary d = bundled(name);
            for (auto it = names.begin(); it != names.end(); ++it) {
                const QString key = it.key();
                const uint16_t index = static_cast<uint16_t>(key.left(4).toUInt(nullptr, 16));
                const int sub = key.size() > 4 ? static_cast<int>(key.mid(5).toUInt(nullptr, 16)) : -1;
                QVERIFY2(sub < 0 ? d.object(index) != nullptr : d.entry(index, static_cast<uint8_t>(sub)) != nullptr,
                         qPrintable(name + u' ' + key));
                const QJsonObject o = it.value().toObject();
                for (const char* field : {"zh_TW", "zh_CN", "source"})
                    QVERIFY2(!o.value(QLatin1String(field)).toString().isEmpty(),
                             qPrintable(name + u' ' + key + u' ' + QLatin1String(field)));
                for (const char* lang : {"zh_TW", "zh_CN"}) {
                    const QString text = o.value(QLatin1String(lang)).toString();
                    QVERIFY2(text.contains(han) || text == u"COB-ID", qPrintable(name + u' ' + key + u' ' + text));
                }
            }
        }
    }
};

QTEST_GUILESS_MAIN(TestObjectNames)
#include "test_object_names.moc"
