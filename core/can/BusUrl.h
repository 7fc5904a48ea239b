// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QMap>
#include <QString>
#include <QStringList>

#include <optional>

namespace coscope {

// A bus as the user names it, the same string in the CLI and the GUI (DESIGN.md "Bus URLs"):
//   socketcan://can0, virtualcan://can0, peakcan://usb0 ... (any Qt CAN plugin by its name)
//   socketcand://HOST:PORT/CHANNEL     remote CAN over the socketcand protocol
//   sim://?nodes=1:delta-asda-a2,2:aimotor   in-process virtual network (sim:// = default)
//   replay://PATH?speed=1.0&loop=1     plays a log file with its original timing
// Options are query parameters: bitrate, data-bitrate, fd, listen-only, speed, loop, nodes.
struct BusUrl {
    QString scheme;  // lower case
    QString target;  // text between "scheme://" and "?" (device, host:port/channel or path)
    QMap<QString, QString> options;

    // socketcand:// parts
    QString host;
    quint16 port = 0;
    QString channel;

    // Typed accessors of the common options (defaults when absent).
    int bitrate() const;      // 0 = leave the adapter's setting
    int dataBitrate() const;  // CAN FD data phase, 0 = unset
    bool canFd() const;
    bool listenOnly() const;
    double speed() const;  // replay speed factor, default 1.0
    bool loop() const;     // replay loop
    bool demo() const;     // sim: a virtual PLC runs the network (sim::DemoMaster)
    QString option(const QString& key, const QString& fallback = {}) const { return options.value(key, fallback); }

    bool isQtPlugin() const;
    QString toString() const;

    static std::optional<BusUrl> parse(const QString& text, QString* error);
};

// Schemes CoScope knows: the Qt CAN plugins installed here plus socketcand, sim and replay.
QStringList knownBusSchemes();
// Names of the Qt CAN bus plugins available at run time.
QStringList qtCanPlugins();
// False for plugins whose device list is fixed rather than found (Qt's tinycan plugin names
// can0.0 on a machine with no Tiny-CAN): their devices are shown as unverified.
bool pluginProbesHardware(const QString& plugin);

inline constexpr quint16 kSocketcandDefaultPort = 29536;

}  // namespace coscope
