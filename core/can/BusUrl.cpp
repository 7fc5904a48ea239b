// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/can/BusUrl.h"

#include <QCanBus>
#include <QUrl>

namespace coscope {

namespace {
// Plugins Qt ships on some platform; listed so an URL naming one gives a clear "not installed here"
// instead of "unknown scheme".
const QStringList kQtPluginNames = {QStringLiteral("socketcan"), QStringLiteral("virtualcan"),
                                    QStringLiteral("peakcan"),   QStringLiteral("passthrucan"),
                                    QStringLiteral("tinycan"),   QStringLiteral("systeccan"),
                                    QStringLiteral("vectorcan")};
const QStringList kOwnSchemes = {QStringLiteral("socketcand"), QStringLiteral("sim"), QStringLiteral("replay")};
const QStringList kKnownOptions = {
    QStringLiteral("bitrate"), QStringLiteral("data-bitrate"), QStringLiteral("fd"),    QStringLiteral("listen-only"),
    QStringLiteral("speed"),   QStringLiteral("loop"),         QStringLiteral("nodes"), QStringLiteral("serials"),
    QStringLiteral("bus"),     QStringLiteral("demo")};

bool parseBool(const QString& v, bool fallback) {
    const QString s = v.trimmed().toLower();
    if (s == u"1" || s == u"true" || s == u"yes" || s == u"on" || s.isEmpty()) return v.isNull() ? fallback : true;
    if (s == u"0" || s == u"false" || s == u"no" || s == u"off") return false;
    return fallback;
}
}  // namespace

QStringList qtCanPlugins() { return QCanBus::instance()->plugins(); }

QStringList knownBusSchemes() {
    QStringList all = qtCanPlugins();
    for (const QString& p : kQtPluginNames)
        if (!all.contains(p)) all << p;
    all << kOwnSchemes;
    return all;
}

int BusUrl::bitrate() const { return options.value(QStringLiteral("bitrate")).toInt(); }
int BusUrl::dataBitrate() const { return options.value(QStringLiteral("data-bitrate")).toInt(); }
bool BusUrl::canFd() const { return parseBool(options.value(QStringLiteral("fd")), false); }
bool BusUrl::listenOnly() const { return parseBool(options.value(QStringLiteral("listen-only")), false); }
bool BusUrl::demo() const { return parseBool(options.value(QStringLiteral("demo")), false); }
bool BusUrl::loop() const { return parseBool(options.value(QStringLiteral("loop")), false); }
double BusUrl::speed() const {
    bool ok = false;
    const double s = options.value(QStringLiteral("speed")).toDouble(&ok);
    return ok ? s : 1.0;
}

bool BusUrl::isQtPlugin() const { return !kOwnSchemes.contains(scheme); }

QString BusUrl::toString() const {
    QString s = scheme + QStringLiteral("://") + target;
    bool first = true;
    for (auto it = options.cbegin(); it != options.cend(); ++it) {
        s += first ? u'?' : u'&';
        first = false;
        s += it.key();
        if (!it.value().isNull()) s += u'=' + it.value();
    }
    return s;
}

std::optional<BusUrl> BusUrl::parse(const QString& text, QString* error) {
    auto fail = [&](const QString& why) -> std::optional<BusUrl> {
        if (error) *error = why;
        return std::nullopt;
    };
    const QString t = text.trimmed();
    const qsizetype sep = t.indexOf(QStringLiteral("://"));
    if (sep <= 0)
        return fail(QStringLiteral("invalid bus URL '%1': expected SCHEME://TARGET, e.g. socketcan://can0 or sim://")
                        .arg(text));
    BusUrl url;
    url.scheme = t.left(sep).toLower();
    const QStringList known = knownBusSchemes();
    if (!known.contains(url.scheme))
        return fail(QStringLiteral("unknown scheme '%1'; known: %2").arg(url.scheme, known.join(QStringLiteral(", "))));

    QString rest = t.mid(sep + 3);
    const qsizetype q = rest.indexOf(u'?');
    QString query;
    if (q >= 0) {
        query = rest.mid(q + 1);
        rest = rest.left(q);
    }
    url.target = QUrl::fromPercentEncoding(rest.toUtf8());
    for (const QString& pair : query.split(u'&', Qt::SkipEmptyParts)) {
        const qsizetype eq = pair.indexOf(u'=');
        const QString key = (eq < 0 ? pair : pair.left(eq)).toLower();
        const QString value = eq < 0 ? QString() : QUrl::fromPercentEncoding(pair.mid(eq + 1).toUtf8());
        if (!kKnownOptions.contains(key))
            return fail(QStringLiteral("unknown option '%1' in '%2'; known: %3")
                            .arg(key, text, kKnownOptions.join(QStringLiteral(", "))));
        url.options.insert(key, value.isNull() ? QStringLiteral("1") : value);
    }
    for (const QString& key : {QStringLiteral("bitrate"), QStringLiteral("data-bitrate")}) {
        if (!url.options.contains(key)) continue;
        bool ok = false;
        const int v = url.options.value(key).toInt(&ok);
        if (!ok || v <= 0)
            return fail(QStringLiteral("option %1 must be a positive number of bit/s, not '%2'")
                            .arg(key, url.options.value(key)));
    }
    if (url.options.contains(QStringLiteral("speed"))) {
        bool ok = false;
        const double v = url.options.value(QStringLiteral("speed")).toDouble(&ok);
        if (!ok || v < 0)
            return fail(QStringLiteral("option speed must be a number >= 0 (0 = as fast as possible), not '%1'")
                            .arg(url.options.value(QStringLiteral("speed"))));
    }

    if (url.scheme == u"socketcand") {
        // socketcand://HOST:PORT/CHANNEL (port optional, default 29536)
        const qsizetype slash = url.target.indexOf(u'/');
        if (slash < 0 || slash == url.target.size() - 1)
            return fail(
                QStringLiteral("socketcand URL needs a channel: socketcand://HOST:PORT/CHANNEL, e.g. "
                               "socketcand://127.0.0.1:29536/can0"));
        QString hostPort = url.target.left(slash);
        url.channel = url.target.mid(slash + 1);
        url.port = kSocketcandDefaultPort;
        // [v6addr]:port or host:port
        if (hostPort.startsWith(u'[')) {
            const qsizetype close = hostPort.indexOf(u']');
            if (close < 0) return fail(QStringLiteral("socketcand URL has an unclosed '[' in the host"));
            url.host = hostPort.mid(1, close - 1);
            hostPort = hostPort.mid(close + 1);
            if (hostPort.startsWith(u':')) hostPort = QStringLiteral("x") + hostPort;  // keep port parsing below
            else hostPort.clear();
        }
        const qsizetype colon = hostPort.lastIndexOf(u':');
        if (colon >= 0) {
            bool ok = false;
            const uint p = hostPort.mid(colon + 1).toUInt(&ok);
            if (!ok || p == 0 || p > 65535)
                return fail(QStringLiteral("socketcand port '%1' is not a port number").arg(hostPort.mid(colon + 1)));
            url.port = static_cast<quint16>(p);
            if (url.host.isEmpty()) url.host = hostPort.left(colon);
        } else if (url.host.isEmpty()) {
            url.host = hostPort;
        }
        if (url.host.isEmpty())
            return fail(QStringLiteral("socketcand URL needs a host: socketcand://HOST:PORT/CHANNEL"));
    } else if (url.scheme == u"replay") {
        if (url.target.isEmpty()) return fail(QStringLiteral("replay URL needs a file: replay://PATH?speed=1.0"));
    } else if (url.scheme == u"sim") {
        // target is ignored; nodes=... selects the virtual drives
    } else if (url.target.isEmpty()) {
        return fail(QStringLiteral("%1 URL needs a device name, e.g. %1://can0").arg(url.scheme));
    }
    return url;
}

bool pluginProbesHardware(const QString& plugin) {
    // qtserialbus tinycan backend: interfaces() returns a constant list without asking the driver.
    return plugin != u"tinycan";
}

}  // namespace coscope
