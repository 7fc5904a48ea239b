// SPDX-License-Identifier: GPL-3.0-or-later
// The concise DCF (CiA 302-3, the value of 1F22h) of a small DCF, byte for byte: entry count,
// then index, sub-index, size and data of each write, little-endian; read-only entries and
// command objects left out; a PDO's writes framed by "invalid" COB-IDs as "dcf apply" writes
// them; $NODEID resolved. Also the parser and `coscope-cli dcf concise`.
#include "core/canopen/ConciseDcf.h"
#include "eds/EdsReader.h"
#include "tests/CliRun.h"

#include <QFile>
#include <QTemporaryDir>
#include <QtTest>

using namespace coscope;

namespace {
const char* kDcf = R"(
[DeviceInfo]
VendorName=Test
ProductName=Concise
[DeviceCommissioning]
NodeID=5
[MandatoryObjects]
SupportedObjects=2
1=0x1000
2=0x1001
[OptionalObjects]
SupportedObjects=5
1=0x1010
2=0x1017
3=0x1800
4=0x1A00
5=0x1008
[ManufacturerObjects]
SupportedObjects=1
1=0x2000
[1000]
ParameterName=Device type
ObjectType=0x7
DataType=0x0007
AccessType=ro
DefaultValue=0x00020192
ParameterValue=0x00020192
[1001]
ParameterName=Error register
ObjectType=0x7
DataType=0x0005
AccessType=ro
ParameterValue=0
[1008]
ParameterName=Manufacturer device name
ObjectType=0x7
DataType=0x0009
AccessType=const
ParameterValue=Concise
[1010]
ParameterName=Store parameters
ObjectType=0x8
SubNumber=2
[1010sub0]
ParameterName=Highest sub-index supported
ObjectType=0x7
DataType=0x0005
AccessType=ro
DefaultValue=1
[1010sub1]
ParameterName=Save all parameters
ObjectType=0x7
DataType=0x0007
AccessType=rw
ParameterValue=0x65766173
[1017]
ParameterName=Producer heartbeat time
ObjectType=0x7
DataType=0x0006
AccessType=rw
DefaultValue=0
ParameterValue=1000
[1800]
ParameterName=TPDO1 communication parameter
ObjectType=0x9
SubNumber=3
[1800sub0]
ParameterName=Highest sub-index supported
ObjectType=0x7
DataType=0x0005
AccessType=ro
DefaultValue=2
[1800sub1]
ParameterName=COB-ID used by TPDO
ObjectType=0x7
DataType=0x0007
AccessType=rw
DefaultValue=$NODEID+0x180
ParameterValue=$NODEID+0x180
[1800sub2]
ParameterName=Transmission type
ObjectType=0x7
DataType=0x0005
AccessType=rw
ParameterValue=254
[1A00]
ParameterName=TPDO1 mapping parameter
ObjectType=0x9
SubNumber=2
[1A00sub0]
ParameterName=Number of mapped objects
ObjectType=0x7
DataType=0x0005
AccessType=rw
ParameterValue=1
[1A00sub1]
ParameterName=Mapped object 1
ObjectType=0x7
DataType=0x0007
AccessType=rw
ParameterValue=0x60410010
[2000]
ParameterName=Offset
ObjectType=0x7
DataType=0x0004
AccessType=rw
ParameterValue=-2
)";

// What the concise DCF of kDcf for node 5 must be (CiA 302-3 1F22h layout).
QByteArray expected() {
    return QByteArray::fromHex(
        "08000000"  // 8 entries
        "171000"
        "02000000"
        "E803"  // 1017h = 1000
        "001801"
        "04000000"
        "85010080"  // 1800h:01 = 80000185h: TPDO1 invalid while configured
        "001802"
        "01000000"
        "FE"  // 1800h:02 = 254
        "001A00"
        "01000000"
        "00"  // 1A00h:00 = 0 while mapping
        "001A01"
        "04000000"
        "10004160"  // 1A00h:01 = 60410010h (statusword)
        "001A00"
        "01000000"
        "01"  // 1A00h:00 = 1
        "001801"
        "04000000"
        "85010000"  // 1800h:01 = 185h ($NODEID+0x180), valid
        "002000"
        "04000000"
        "FEFFFFFF");  // 2000h = -2 (INTEGER32)
}
}  // namespace

class TestConciseDcf : public QObject {
    Q_OBJECT
private slots:
    void byteExactForASmallDcf() {
        const eds::ReadResult r = eds::readDictionary(QByteArray(kDcf), QStringLiteral("concise.dcf"));
        QVERIFY(r.usable);
        std::vector<canopen::SkippedEntry> skipped;
        const QByteArray bytes = canopen::conciseDcf(5, r.dictionary, &skipped);
        QCOMPARE(bytes.toHex().toUpper(), expected().toHex().toUpper());
        // Left out: 1000h, 1001h (ro), 1008h (const), 1010h:01 (a command, not configuration).
        QCOMPARE(int(skipped.size()), 4);
    }

    void parsesBack() {
        QString error;
        const auto entries = canopen::parseConciseDcf(expected(), &error);
        QVERIFY2(entries, qPrintable(error));
        QCOMPARE(int(entries->size()), 8);
        QCOMPARE(entries->front().index, uint16_t(0x1017));
        QCOMPARE(entries->back().data, QByteArray::fromHex("FEFFFFFF"));
        QVERIFY(!canopen::parseConciseDcf(expected().chopped(1), &error));
        QVERIFY2(error.contains(QStringLiteral("entry 8 of 8")), qPrintable(error));
        QVERIFY(!canopen::parseConciseDcf(expected() + QByteArray(1, '\0'), &error));
    }

    void cliWritesTheSameBytes() {
        QTemporaryDir dir;
        const QString in = dir.filePath(QStringLiteral("node5.dcf")), out = dir.filePath(QStringLiteral("node5.bin"));
        QFile f(in);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(kDcf);
        f.close();
        const auto run = cli({QStringLiteral("dcf"), QStringLiteral("concise"), in, out});
        QVERIFY2(run.code == 0, qPrintable(run.err));
        QVERIFY2(run.out.contains(QStringLiteral("8 entries, 81 bytes for node 5")), qPrintable(run.out));
        QFile o(out);
        QVERIFY(o.open(QIODevice::ReadOnly));
        QCOMPARE(o.readAll().toHex(), expected().toHex());
        // Another node: the $NODEID COB-ID follows it.
        const auto run7 = cli(
            {QStringLiteral("dcf"), QStringLiteral("concise"), in, out, QStringLiteral("--node"), QStringLiteral("7")});
        QVERIFY2(run7.code == 0, qPrintable(run7.err));
        o.close();
        QVERIFY(o.open(QIODevice::ReadOnly));
        QVERIFY(o.readAll().toHex().contains("87010000"));
    }
};

QTEST_GUILESS_MAIN(TestConciseDcf)
#include "test_concise_dcf.moc"
