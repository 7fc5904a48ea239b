// SPDX-License-Identifier: GPL-3.0-or-later
// DictionaryLibrary: user folder, replacing bundled names, identity matching, unit sidecars.
#include "eds/DictionaryLibrary.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QTest>

using namespace coscope;

namespace {

void writeEds(const QString& path, const char* vendor, const char* product, const char* revision, const char* name,
              const char* deviceType = "0x00020192", const char* deviceName = nullptr) {
    QFile f(path);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(
        QByteArray("[DeviceInfo]\nVendorName=T\nVendorNumber=") + vendor + "\nProductNumber=" + product +
        "\nRevisionNumber=" + revision + "\nProductName=" + name +
        "\n[MandatoryObjects]\nSupportedObjects=1\n1=0x1000\n[1000]\nParameterName=Device "
        "type\nDataType=0x0007\nAccessType=ro\n"
        "DefaultValue=" +
        deviceType + "\n" +
        (deviceName
             ? QByteArray(
                   "[1008]\nParameterName=Manufacturer device name\nDataType=0x0009\nAccessType=const\nDefaultValue=") +
                   deviceName + "\n"
             : QByteArray()) +
        "[6064]\nParameterName=Position actual value\nDataType=0x0004\nAccessType=ro\nPDOMapping=1\n");
}

}  // namespace

class TestEdsLibrary : public QObject {
    Q_OBJECT
private slots:
    void userFolderAndIdentity();
    void unitsSidecar();
    void unknownName();
    void bundledNamesLoad();
    void noIdentityMatchesByDeviceTypeAndName();
    void noIdentityTieMatchesNothing();
    void identityFromItsSections();
};

void TestEdsLibrary::userFolderAndIdentity() {
    QTemporaryDir dir;
    writeEds(dir.filePath("a-rev1.eds"), "0x100", "0x20", "0x00010001", "A1");
    writeEds(dir.filePath("a-rev3.eds"), "0x100", "0x20", "0x00010003", "A3");
    writeEds(dir.filePath("a-rev2-0.eds"), "0x100", "0x20", "0x00020000", "A20");
    writeEds(dir.filePath("b.dcf"), "0x100", "0x21", "0x1", "B");
    const eds::DictionaryLibrary lib(dir.path());
    QVERIFY(lib.names().contains("a-rev1"));
    QVERIFY(lib.names().contains("b"));
    // Exact revision.
    QCOMPARE(lib.findByIdentity(0x100, 0x20, 0x00010001u)->name, QString("a-rev1"));
    // Same major revision, highest minor.
    QCOMPARE(lib.findByIdentity(0x100, 0x20, 0x00010007u)->name, QString("a-rev3"));
    // Unknown major: the highest revision.
    QCOMPARE(lib.findByIdentity(0x100, 0x20, 0x00090000u)->name, QString("a-rev2-0"));
    QCOMPARE(lib.findByIdentity(0x100, 0x21)->name, QString("b"));
    QVERIFY(!lib.findByIdentity(0x100, 0x22));
    QVERIFY(!lib.findByIdentity(0x101, 0x20));
}

// Issue 13: AIMOTOR and DEXMART have no 1018h (both answer 0/0). 0/0 never matches by
// identity; the device type (1000h) and device name (1008h) tell them apart.
void TestEdsLibrary::noIdentityMatchesByDeviceTypeAndName() {
    const eds::DictionaryLibrary& lib = eds::DictionaryLibrary::shared();
    QVERIFY(!lib.findByIdentity(0, 0));
    auto nameOf = [&](const eds::DeviceIdentity& d) {
        const auto* e = lib.match(d);
        return e ? e->name : QString();
    };
    eds::DeviceIdentity dexmart;
    dexmart.vendorId = 0;
    dexmart.productCode = 0;
    dexmart.deviceType = 0;
    QCOMPARE(nameOf(dexmart), QString("dexmart-dev"));  // 1000h = 0
    dexmart.deviceName = QString("DLV-N050CQE");
    QCOMPARE(nameOf(dexmart), QString("dexmart-dev"));
    eds::DeviceIdentity aimotor;
    aimotor.vendorId = 0;
    aimotor.productCode = 0;
    aimotor.deviceType = 0x192;
    QCOMPARE(nameOf(aimotor), QString("aimotor"));
    // 0/0 alone says nothing.
    eds::DeviceIdentity none;
    none.vendorId = 0;
    none.productCode = 0;
    QCOMPARE(nameOf(none), QString());
    // A device name the dictionary does not document rules it out.
    none.deviceType = 0;
    none.deviceName = QString("SOMETHING-ELSE");
    QCOMPARE(nameOf(none), QString());
    // 1018h not read: the device type alone (0192h is common) is not enough, a name is.
    eds::DeviceIdentity unread;
    unread.deviceType = 0x192;
    QCOMPARE(nameOf(unread), QString());
    unread.softwareVersion = QString("AIMOTOR_CIA402 V1.2");
    QCOMPARE(nameOf(unread), QString("aimotor"));
    // A real identity still matches by it.
    eds::DeviceIdentity delta;
    delta.vendorId = 0x1DD;
    delta.productCode = 0x6030;  // ASDA-M, a variant in the sidecar
    delta.deviceType = 0;
    QCOMPARE(nameOf(delta), QString("delta-asda-a2"));
}

void TestEdsLibrary::noIdentityTieMatchesNothing() {
    QTemporaryDir dir;
    writeEds(dir.filePath("x1.eds"), "0", "0", "0", "X1", "0x00010191", "X-ONE");
    writeEds(dir.filePath("x2.eds"), "0", "0", "0", "X2", "0x00010191", "X-TWO");
    const eds::DictionaryLibrary lib(dir.path());
    eds::DeviceIdentity d;
    d.vendorId = 0;
    d.productCode = 0;
    d.deviceType = 0x10191;
    QVERIFY(!lib.match(d));  // both say 1000h = 00010191h: a tie
    d.deviceName = QString("X-TWO");
    QVERIFY(lib.match(d));
    QCOMPARE(lib.match(d)->name, QString("x2"));
}

void TestEdsLibrary::unitsSidecar() {
    QTemporaryDir dir;
    writeEds(dir.filePath("drive.eds"), "0x1", "0x2", "0x3", "D");
    QFile j(dir.filePath("drive.json"));
    QVERIFY(j.open(QIODevice::WriteOnly));
    j.write(R"({"units": {"6064:00": {"unit": "counts", "factor": 0.5}, "7000:00": {"unit": "x"}}})");
    j.close();
    const eds::DictionaryLibrary lib(dir.path());
    const auto r = lib.load("drive");
    QVERIFY(r.usable);
    const auto u = r.dictionary.unit(0x6064, 0);
    QVERIFY(u);
    QCOMPARE(u->text, QString("counts"));
    QCOMPARE(u->factor, 0.5);
    QVERIFY(!r.dictionary.unit(0x1000, 0));
    bool warned = false;
    for (const auto& d : r.diagnostics) warned |= d.message.contains("'7000:00' is not an entry");
    QVERIFY(warned);
}

void TestEdsLibrary::unknownName() {
    QTemporaryDir dir;
    const auto r = eds::DictionaryLibrary(dir.path()).load("no-such-drive");
    QVERIFY(!r.usable);
    QCOMPARE(r.errorCount(), 1);
    QVERIFY(!eds::loadDictionaryByPathOrName("no-such-drive-either").usable);
}

void TestEdsLibrary::bundledNamesLoad() {
    QTemporaryDir dir;
    const eds::DictionaryLibrary lib(dir.path());
    if (lib.entries().empty()) QSKIP("no bundled dictionaries in this build");
    for (const auto& e : lib.entries()) {
        QVERIFY(e.bundled);
        const auto r = lib.load(e.name);
        QVERIFY2(r.usable, qPrintable(e.name));
        QVERIFY2(r.errorCount() == 0, qPrintable(e.name));
    }
}

// The library reads a bundled dictionary's identity from the sections that hold it
// (readDocumentedIdentity): the same identity as the whole file gives, for every bundled
// dictionary and for an identity in 1018h with $NODEID defaults and a [DeviceCommissioning].
void TestEdsLibrary::identityFromItsSections() {
    QTemporaryDir dir;
    const eds::DictionaryLibrary lib(dir.path());
    for (const auto& e : lib.entries()) {
        const auto fromSections = eds::readDocumentedIdentity(e.path);
        QVERIFY2(fromSections.has_value(), qPrintable(e.name));
        const eds::DocumentedIdentity whole = eds::documentedIdentity(eds::readDictionaryFile(e.path).dictionary);
        QVERIFY2(*fromSections == whole, qPrintable(e.name));
        QVERIFY2(e.vendorId == whole.vendorId, qPrintable(e.name));
        QVERIFY2(e.productCode == whole.productCode, qPrintable(e.name));
        QVERIFY2(e.revision == whole.revision, qPrintable(e.name));
        QCOMPARE(e.deviceName, whole.deviceName);
    }
    const QString path = dir.filePath("nodeid.eds");
    QFile f(path);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(
        "[DeviceInfo]\nVendorName=T\n[DeviceCommissioning]\nNodeID=5\n"
        "[MandatoryObjects]\nSupportedObjects=3\n1=0x1000\n2=0x1018\n3=0x6064\n"
        "[1000]\nParameterName=Device type\nDataType=0x0007\nAccessType=ro\nDefaultValue=0x00020192\n"
        "[6064]\nParameterName=Position actual value\nDataType=0x0004\nAccessType=ro\n"
        "  [1018]  ; identity\nParameterName=Identity\nObjectType=0x9\nSubNumber=4\n"
        "[1018sub0]\nParameterName=n\nDataType=0x0005\nAccessType=ro\nDefaultValue=3\n"
        "[1018sub1]\nParameterName=Vendor\nDataType=0x0007\nAccessType=ro\nDefaultValue=$NODEID+0x100\n"
        "[1018sub2]\nParameterName=Product\nDataType=0x0007\nAccessType=ro\nDefaultValue=0x42\n"
        "[1018sub3]\nParameterName=Revision\nDataType=0x0007\nAccessType=ro\nDefaultValue=0x00010002\n"
        "[1008]\nParameterName=Manufacturer device name\nDataType=0x0009\nAccessType=const\n"
        "DefaultValue= Drive X \n");
    f.close();
    const eds::DocumentedIdentity whole = eds::documentedIdentity(eds::readDictionaryFile(path).dictionary);
    QVERIFY(whole.vendorId == std::optional<std::uint32_t>(0x105));
    QCOMPARE(whole.deviceName, QString("Drive X"));
    const auto fromSections = eds::readDocumentedIdentity(path);
    QVERIFY(fromSections.has_value());
    QVERIFY(*fromSections == whole);
}

QTEST_GUILESS_MAIN(TestEdsLibrary)
#include "test_eds_library.moc"
