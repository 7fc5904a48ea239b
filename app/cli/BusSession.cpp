// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/cli/BusSession.h"

#include "core/canopen/DriveDisable.h"
#include "core/canopen/ServiceWait.h"
#include "eds/DictionaryLibrary.h"
#include "eds/SimulatorDictionaries.h"

#include <QRegularExpression>

#include <cstdio>

namespace coscope::cli {

BusSession::BusSession() = default;

BusSession::~BusSession() {
    master_.reset();  // its last frames go out before the bus closes
    sdo_.reset();
    // Whatever ended the verb (a failure, an interrupt, a bug): a drive it left enabled gets
    // Disable voltage, seen going out, before the bus closes. Verbs that leave a drive enabled
    // on purpose (ds402 enable) take it off the record first.
    if (context_ && bus_ && !context_->enabledDrives().isEmpty()) {
        const canopen::DriveDisableOutcome outcome = canopen::disableEnabledDrives(*context_);
        if (!outcome.drives.empty())
            std::fprintf(stderr, "coscope-cli: before closing the bus: %s\n",
                         qPrintable(outcome.summary().replace(u'\n', QStringLiteral("; "))));
    }
    if (session_) session_->stop();
    if (bus_) bus_->close();
}

bool BusSession::open(const QString& url, QString* error, int timeoutMs) {
    if (url.startsWith(QStringLiteral("sim:"), Qt::CaseInsensitive)) eds::installSimulatorDictionaries();
    bus_ = createBus(url, error);
    if (!bus_) return false;
    context_ = std::make_unique<canopen::MasterContext>(bus_.get());
    session_ = std::make_unique<CaptureSession>();
    session_->addConsumer(context_->dispatcher().consumer());
    bus_->open();
    if (!bus_->waitForOpen(timeoutMs)) {
        if (error)
            *error = QStringLiteral("cannot open %1: %2")
                         .arg(url, bus_->errorString().isEmpty() ? QStringLiteral("timed out") : bus_->errorString());
        return false;
    }
    session_->start(bus_.get());
    sdo_ = std::make_unique<canopen::SdoClient>(*context_);
    master_ = std::make_unique<canopen::BusMaster>(*context_);
    return true;
}

std::optional<od::ObjectDictionary> BusSession::nodeDictionary(uint8_t node, const QString& dictOption, QString* name,
                                                               QString* error) {
    QString dictName = dictOption;
    if (dictName.isEmpty()) {
        // Match by identity: 1018h:01 vendor-ID, :02 product code, :03 revision; without one
        // (0/0), by 1000h device type, 1008h device name and 100Ah software version.
        auto read = [&](uint16_t index, uint8_t sub) {
            return canopen::waitForResult<canopen::SdoResult>([&](auto cb) { sdo_->upload(node, index, sub, cb); },
                                                              10000);
        };
        auto u32 = [](const QByteArray& d) {
            uint32_t v = 0;
            for (int i = 0; i < std::min<int>(4, static_cast<int>(d.size())); ++i)
                v |= uint32_t(uint8_t(d[i])) << (8 * i);
            return v;
        };
        eds::DeviceIdentity device;
        for (uint8_t sub = 1; sub <= 3; ++sub) {
            auto r = read(0x1018, sub);
            if (!r || !r->ok) {
                if (sub < 3) {
                    if (error) *error = r ? r->error : QStringLiteral("no answer reading 1018h");
                    return std::nullopt;
                }
                continue;
            }
            (sub == 1 ? device.vendorId : sub == 2 ? device.productCode : device.revision) = u32(r->data);
        }
        if (!device.hasIdentity()) {
            if (auto r = read(0x1000, 0); r && r->ok) device.deviceType = u32(r->data);
            if (auto r = read(0x1008, 0); r && r->ok)
                device.deviceName = QString::fromUtf8(r->data).section(QChar(0), 0, 0);
            if (auto r = read(0x100A, 0); r && r->ok)
                device.softwareVersion = QString::fromUtf8(r->data).section(QChar(0), 0, 0);
        }
        const auto* entry = eds::DictionaryLibrary::shared().match(device);
        if (!entry) {
            if (error)
                *error = QStringLiteral("no dictionary matches node %1's identity (vendor 0x%2, product 0x%3)")
                             .arg(node)
                             .arg(device.vendorId.value_or(0), 8, 16, QChar(u'0'))
                             .arg(device.productCode.value_or(0), 8, 16, QChar(u'0'));
            return std::nullopt;
        }
        dictName = entry->name;
    }
    eds::ReadResult rr = eds::loadDictionaryByPathOrName(dictName);
    if (!rr.usable) {
        if (error) *error = QStringLiteral("cannot load dictionary '%1'").arg(dictName);
        return std::nullopt;
    }
    const QString base = dictName.section(u'/', -1).section(u'.', 0, 0);
    if (name) *name = base;
    context_->setNodeDictionary(node, base);
    return std::move(rr.dictionary);
}

std::optional<uint8_t> parseNodeId(const QString& text, bool allowAll) {
    if (allowAll && text.compare(QStringLiteral("all"), Qt::CaseInsensitive) == 0) return uint8_t(0);
    bool ok = false;
    const uint v = text.toUInt(&ok, 0);
    if (!ok || v < 1 || v > 127) return std::nullopt;
    return static_cast<uint8_t>(v);
}

bool parseObjectRef(const QString& text, uint16_t* index, uint8_t* sub) {
    static const QRegularExpression re(
        QStringLiteral("^(?:0x)?([0-9a-f]{1,4})(?:(?::|sub|\\.)(?:0x)?([0-9a-f]{1,2}))?$"),
        QRegularExpression::CaseInsensitiveOption);
    const auto m = re.match(text.trimmed());
    if (!m.hasMatch()) return false;
    *index = static_cast<uint16_t>(m.captured(1).toUInt(nullptr, 16));
    *sub = static_cast<uint8_t>(m.captured(2).isEmpty() ? 0 : m.captured(2).toUInt(nullptr, 16));
    return true;
}

}  // namespace coscope::cli
