// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/can/SocketCanLinks.h"
#include "core/can/SocketCanLinkJob.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QProcessEnvironment>

namespace coscope {

namespace {

int intOf(const QJsonValue& v) {
    // iproute2 prints numbers as numbers, but a few fields (sample_point) as strings.
    return v.isString() ? v.toString().toInt() : v.toInt();
}

QString rateText(int bps) {
    if (bps % 1000000 == 0) return QStringLiteral("%1 Mbit/s").arg(bps / 1000000);
    if (bps % 1000 == 0) return QStringLiteral("%1 kbit/s").arg(bps / 1000);
    return QStringLiteral("%1 bit/s").arg(bps);
}

}  // namespace

bool parseIpLinkJson(const QByteArray& json, QList<SocketCanLink>* links, QString* error) {
    QJsonParseError perr;
    const QJsonDocument doc = QJsonDocument::fromJson(json, &perr);
    if (doc.isNull() || !doc.isArray()) {
        if (error)
            *error = doc.isNull() ? QStringLiteral("`ip -json` output is not JSON (offset %1: %2)")
                                        .arg(perr.offset)
                                        .arg(perr.errorString())
                                  : QStringLiteral("`ip -json` output is not a list of links");
        return false;
    }
    links->clear();
    for (const QJsonValue v : doc.array()) {
        const QJsonObject o = v.toObject();
        if (o.value(u"link_type").toString() != u"can") continue;  // ARPHRD_CAN: can, vcan, vxcan, slcan
        SocketCanLink l;
        l.name = o.value(u"ifname").toString();
        const QJsonObject info = o.value(u"linkinfo").toObject();
        l.kind = info.value(u"info_kind").toString(QStringLiteral("can"));
        const QJsonArray flags = o.value(u"flags").toArray();
        l.up = flags.contains(QStringLiteral("UP"));
        const QJsonObject data = info.value(u"info_data").toObject();
        l.controllerState = data.value(u"state").toString();
        l.bitrate = intOf(data.value(u"bittiming").toObject().value(u"bitrate"));
        l.dataBitrate = intOf(data.value(u"data_bittiming").toObject().value(u"bitrate"));
        l.fd = data.value(u"ctrlmode").toArray().contains(QStringLiteral("FD")) || o.value(u"mtu").toInt() == 72;
        if (data.contains(u"berr_counter")) {
            const QJsonObject bc = data.value(u"berr_counter").toObject();
            l.txErrors = bc.value(u"tx").toInt();
            l.rxErrors = bc.value(u"rx").toInt();
        }
        if (!l.name.isEmpty()) links->append(l);
    }
    return true;
}

QList<SocketCanLink> listSocketCanLinks(QString* error) {
    const QString program = ipProgram();
    QProcess p;
    p.start(program,
            {QStringLiteral("-details"), QStringLiteral("-json"), QStringLiteral("link"), QStringLiteral("show")});
    if (!p.waitForStarted(2000)) {
        if (error)
            *error = QStringLiteral("cannot run `%1` (Debian package iproute2) to list CAN interfaces").arg(program);
        return {};
    }
    if (!p.waitForFinished(3000) || p.exitStatus() != QProcess::NormalExit || p.exitCode() != 0) {
        p.kill();
        if (error)
            *error = QStringLiteral("`%1 -details -json link show` failed: %2")
                         .arg(program, QString::fromLocal8Bit(p.readAllStandardError()).trimmed());
        return {};
    }
    QList<SocketCanLink> links;
    if (!parseIpLinkJson(p.readAllStandardOutput(), &links, error)) return {};
    return links;
}

QString bringUpCommand(const SocketCanLink& link, int bitrate, int dataBitrate) {
    QStringList lines;
    for (const QStringList& args : bringUpSteps(link, bitrate, dataBitrate))
        lines << QStringLiteral("sudo ip ") + args.join(u' ');
    return lines.join(QStringLiteral("; "));
}

QString describeLink(const SocketCanLink& link) {
    if (!link.up) return QStringLiteral("down");
    if (link.isVirtual()) return QStringLiteral("up (virtual)");
    QStringList parts{QStringLiteral("up")};
    if (link.bitrate > 0) parts << rateText(link.bitrate);
    if (link.dataBitrate > 0) parts << QStringLiteral("FD ") + rateText(link.dataBitrate);
    if (!link.controllerState.isEmpty()) parts << link.controllerState;
    if (link.txErrors > 0 || link.rxErrors > 0)
        parts << QStringLiteral("TEC %1 REC %2").arg(link.txErrors).arg(link.rxErrors);
    return parts.join(QStringLiteral(", "));
}

QString explainSocketCanError(const QString& interfaceName, const QString& rawError, int bitrate) {
    const QString e = rawError.toLower();
    SocketCanLink named;
    named.name = interfaceName;
    named.kind = interfaceName.startsWith(u"vcan") ? QStringLiteral("vcan") : QStringLiteral("can");
    const QString upCommand = bringUpCommand(named, bitrate > 0 ? bitrate : 500000);
    QString advice;
    if (e.contains(u"address family not supported")) {
        // socket(PF_CAN, ...) fails with EAFNOSUPPORT when the kernel has no CAN protocol family.
        advice = QStringLiteral(
            "this kernel has no CAN support loaded: load it with `sudo modprobe can_raw` "
            "and, for a virtual bus, `sudo modprobe vcan`; or use a socketcand server or sim://");
    } else if (e.contains(u"no such device")) {
        QString why;
        const QList<SocketCanLink> links = listSocketCanLinks(&why);
        QStringList names;
        for (const SocketCanLink& l : links) names << l.name;
        advice = QStringLiteral("there is no CAN interface named '%1'").arg(interfaceName);
        advice += names.isEmpty()
                      ? QStringLiteral(
                            "; no CAN interfaces exist (plug in the adapter, or for a virtual one: "
                            "`sudo modprobe vcan; sudo ip link add dev vcan0 type vcan; sudo ip link set vcan0 up`)")
                      : QStringLiteral("; the CAN interfaces here are: %1").arg(names.join(QStringLiteral(", ")));
    } else if (e.contains(u"network is down")) {
        advice = QStringLiteral("interface %1 is down; bring it up with `%2`").arg(interfaceName, upCommand);
    } else if (e.contains(u"operation not permitted") || e.contains(u"permission denied")) {
        advice = QStringLiteral(
                     "no permission to configure %1 (setting the bit rate or restarting needs CAP_NET_ADMIN); "
                     "configure it once with `%2` and connect without bitrate=, or run as root")
                     .arg(interfaceName, upCommand);
    } else if (e.contains(u"libsocketcan")) {
        advice = QStringLiteral(
            "install libsocketcan2 (`sudo apt install libsocketcan2`) so the bit rate can be set and the "
            "controller restarted after bus-off");
    }
    return advice.isEmpty() ? rawError : QStringLiteral("%1 (%2)").arg(rawError, advice);
}

}  // namespace coscope
