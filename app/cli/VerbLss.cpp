// SPDX-License-Identifier: GPL-3.0-or-later
// coscope-cli lss BUS inquire | set-node-id ID | set-bit-rate RATE | store | fastscan
#include "app/cli/BusSession.h"
#include "app/cli/CliVerb.h"
#include "core/canopen/Lss.h"
#include "core/canopen/LssMaster.h"
#include "core/canopen/ServiceWait.h"

#include <QTextStream>

namespace coscope::cli {

static int runLss(const QStringList& args) {
    const QString verb = QStringLiteral("lss");
    QCommandLineParser p;
    p.setApplicationDescription(
        QStringLiteral("Layer setting services (CiA 305). Actions:\n"
                       "  inquire              identity (1018h:01-04) and node-ID of the slave in configuration state\n"
                       "  set-node-id ID       configure node-ID (1-127, or 255 = unconfigured)\n"
                       "  set-bit-rate RATE    configure bit timing from the standard table (bit/s, e.g. 500000)\n"
                       "  activate [DELAY_MS]  activate the configured bit timing on all slaves\n"
                       "  store                store the configuration in the slave\n"
                       "  fastscan             find an unconfigured slave and put it in configuration state\n"
                       "With --serial etc. the slave is selected first (switch state selective), otherwise all\n"
                       "slaves are switched to configuration state (use with one slave on the bus)."));
    p.addPositionalArgument(QStringLiteral("BUS"), QStringLiteral("Bus URL"));
    p.addPositionalArgument(QStringLiteral("ACTION"),
                            QStringLiteral("inquire, set-node-id, set-bit-rate, activate, store, fastscan"));
    const QCommandLineOption vendor(QStringLiteral("vendor"), QStringLiteral("Vendor-ID for selective switch."),
                                    QStringLiteral("ID"));
    const QCommandLineOption product(QStringLiteral("product"), QStringLiteral("Product code for selective switch."),
                                     QStringLiteral("CODE"));
    const QCommandLineOption revision(QStringLiteral("revision"), QStringLiteral("Revision for selective switch."),
                                      QStringLiteral("REV"));
    const QCommandLineOption serial(QStringLiteral("serial"), QStringLiteral("Serial number for selective switch."),
                                    QStringLiteral("SN"));
    const QCommandLineOption timeout(QStringLiteral("timeout"), QStringLiteral("Answer timeout in ms (default 1000)."),
                                     QStringLiteral("MS"), QStringLiteral("1000"));
    p.addOptions({vendor, product, revision, serial, timeout});
    int code = 0;
    if (!parseArgs(p, verb, args, &code)) return code;
    const QStringList pos = p.positionalArguments();
    if (pos.size() < 2) return usageError(verb, QStringLiteral("expects BUS ACTION [ARG]"));
    const QString action = pos[1].toLower();
    static const QStringList actions = {QStringLiteral("inquire"),      QStringLiteral("set-node-id"),
                                        QStringLiteral("set-bit-rate"), QStringLiteral("activate"),
                                        QStringLiteral("store"),        QStringLiteral("fastscan")};
    if (!actions.contains(action))
        return usageError(
            verb, QStringLiteral("unknown action '%1'; use %2").arg(pos[1], actions.join(QStringLiteral(", "))));
    const bool needsArg = action == u"set-node-id" || action == u"set-bit-rate";
    if (needsArg ? pos.size() != 3 : pos.size() > (action == u"activate" ? 3 : 2))
        return usageError(verb, QStringLiteral("wrong number of arguments for %1").arg(action));
    bool ok = false;
    uint argValue = pos.size() > 2 ? pos[2].toUInt(&ok, 0) : 0;
    if (pos.size() > 2 && !ok) return usageError(verb, QStringLiteral("'%1' is not a number").arg(pos[2]));
    if (action == u"set-node-id" && !((argValue >= 1 && argValue <= 127) || argValue == 255))
        return usageError(verb, QStringLiteral("node-ID must be 1-127 or 255"));
    if (action == u"set-bit-rate" && canopen::lssTableIndexForBitRate(static_cast<int>(argValue)) < 0)
        return usageError(
            verb,
            QStringLiteral(
                "%1 bit/s is not in the CiA 305 table (10000, 20000, 50000, 125000, 250000, 500000, 800000, 1000000)")
                .arg(argValue));
    const bool selective = p.isSet(vendor) || p.isSet(product) || p.isSet(revision) || p.isSet(serial);
    canopen::LssIdentity id;
    if (selective) {
        bool a = false, b = false, c = false, d = false;
        id.vendorId = p.value(vendor).toUInt(&a, 0);
        id.productCode = p.value(product).toUInt(&b, 0);
        id.revision = p.value(revision).toUInt(&c, 0);
        id.serial = p.value(serial).toUInt(&d, 0);
        if (!(a && b && c && d))
            return usageError(verb,
                              QStringLiteral("selective switch needs --vendor, --product, --revision and --serial"));
    }

    BusSession s;
    QString error;
    if (!s.open(pos[0], &error)) return failure(verb, error);
    canopen::LssMaster lss(s.context());
    lss.setTimeout(p.value(timeout).toInt() > 0 ? p.value(timeout).toInt() : 1000);
    QTextStream out(stdout);
    auto wait = [&](const std::function<void(canopen::LssCallback)>& start) {
        auto r = canopen::waitForResult<canopen::LssResult>(start, 120000);
        return r ? *r : canopen::LssResult{false, 0, 0, {}, false, QStringLiteral("no result")};
    };
    auto hex = [](uint32_t v) { return QStringLiteral("0x%1").arg(v, 8, 16, QChar(u'0')); };

    if (action == u"fastscan") {
        const auto r = wait([&](auto cb) { lss.fastscan(cb); });
        if (!r.ok) return failure(verb, r.error);
        out << "found vendor " << hex(r.identity.vendorId) << " product " << hex(r.identity.productCode) << " revision "
            << hex(r.identity.revision) << " serial " << hex(r.identity.serial) << " (now in configuration state)\n";
        return Ok;
    }
    if (action == u"activate") {
        if (!lss.activateBitTiming(static_cast<uint16_t>(pos.size() > 2 ? argValue : 100), &error))
            return failure(verb, error);
        canopen::waitUntil([&] { return s.bus()->counters().tx > 0; }, 1000);
        out << "activate bit timing sent\n";
        return Ok;
    }
    if (selective) {
        const auto r = wait([&](auto cb) { lss.switchStateSelective(id, cb); });
        if (!r.ok) return failure(verb, r.error);
    } else if (!lss.switchStateGlobal(true, &error)) {
        return failure(verb, error);
    }
    canopen::LssResult r;
    if (action == u"inquire") {
        r = wait([&](auto cb) { lss.inquireIdentity(cb); });
        if (!r.ok) return failure(verb, r.error);
        const auto n = wait([&](auto cb) { lss.inquireNodeId(cb); });
        if (!n.ok) return failure(verb, n.error);
        out << "vendor " << hex(r.identity.vendorId) << " product " << hex(r.identity.productCode) << " revision "
            << hex(r.identity.revision) << " serial " << hex(r.identity.serial) << " node-ID "
            << (n.value == 0xFF ? QStringLiteral("unconfigured (255)") : QString::number(n.value)) << "\n";
    } else if (action == u"set-node-id") {
        r = wait([&](auto cb) { lss.configureNodeId(static_cast<uint8_t>(argValue), cb); });
        if (!r.ok) return failure(verb, r.error);
        out << "node-ID " << argValue << " configured (store, then reset the node to apply)\n";
    } else if (action == u"set-bit-rate") {
        r = wait([&](auto cb) { lss.configureBitRate(static_cast<int>(argValue), cb); });
        if (!r.ok) return failure(verb, r.error);
        out << "bit rate " << argValue << " configured (store, then activate or reset to apply)\n";
    } else if (action == u"store") {
        r = wait([&](auto cb) { lss.storeConfiguration(cb); });
        if (!r.ok) return failure(verb, r.error);
        out << "configuration stored\n";
    }
    lss.switchStateGlobal(false, nullptr);
    canopen::waitUntil([] { return false; }, 20);  // let the last frame leave
    return Ok;
}

COSCOPE_CLI_VERB({QStringLiteral("lss"),
                  QStringLiteral("LSS (CiA 305): inquire, set node-ID or bit rate, store, fastscan."), runLss});

}  // namespace coscope::cli
