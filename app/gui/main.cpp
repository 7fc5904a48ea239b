// SPDX-License-Identifier: GPL-3.0-or-later
// coscope: the desktop app.
#include "app/gui/MainWindow.h"
#include "core/log/Logging.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QScreen>
#include <QTimer>

#include <cstdio>

using namespace coscope;

int main(int argc, char** argv) {
    const bool haveDisplay = !qEnvironmentVariableIsEmpty("DISPLAY") || !qEnvironmentVariableIsEmpty("WAYLAND_DISPLAY") ||
                             !qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM");
    bool wantsHelpOnly = false;
    for (int i = 1; i < argc; ++i) {
        const QByteArray a(argv[i]);
        if (a == "--help" || a == "-h" || a == "--version" || a == "-v") wantsHelpOnly = true;
    }
    if (!haveDisplay && !wantsHelpOnly) {
        std::fprintf(stderr, "coscope: no display found (DISPLAY/WAYLAND_DISPLAY unset); use the command line instead: coscope-cli --help\n");
        return 1;
    }
    if (!haveDisplay) qputenv("QT_QPA_PLATFORM", "offscreen");

    QApplication app(argc, argv);
    QApplication::setApplicationName(QStringLiteral("CoScope"));
    QApplication::setOrganizationName(QStringLiteral("CoScope"));
    QApplication::setApplicationVersion(QStringLiteral(COSCOPE_VERSION));

    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral("CoScope - CANopen bus analyzer and servo-drive commissioning tool"));
    parser.addHelpOption();
    parser.addVersionOption();
    const QCommandLineOption simulate(QStringLiteral("simulate"), QStringLiteral("Connect to the default virtual drive network (sim://)."));
    const QCommandLineOption connectTo(QStringLiteral("connect"), QStringLiteral("Connect to a bus URL."), QStringLiteral("URL"));
    const QCommandLineOption logLevel(QStringLiteral("log-level"), QStringLiteral("trace, debug, info, warn, error, critical, off."), QStringLiteral("LEVEL"));
    const QCommandLineOption screenshot(QStringLiteral("screenshot"), QStringLiteral("Render the window to a PNG once it has content, then exit."), QStringLiteral("FILE"));
    parser.addOptions({simulate, connectTo, logLevel, screenshot});
    parser.process(app);

    auto level = logging::levelFromEnvironment(spdlog::level::info);
    if (parser.isSet(logLevel)) {
        auto parsed = logging::parseLevel(parser.value(logLevel));
        if (!parsed) {
            std::fprintf(stderr, "coscope: invalid --log-level '%s'\n", qPrintable(parser.value(logLevel)));
            return 2;
        }
        level = *parsed;
    }
    logging::init(QStringLiteral("coscope"), level);

    gui::MainWindow window;
    window.show();
    if (parser.isSet(connectTo)) window.connectBus(parser.value(connectTo));
    else if (parser.isSet(simulate)) window.connectBus(QStringLiteral("sim://"));

    if (parser.isSet(screenshot)) {
        const QString file = parser.value(screenshot);
        QTimer::singleShot(2500, &window, [&window, file] {
            const bool ok = window.grab().save(file);
            std::fprintf(ok ? stdout : stderr, ok ? "screenshot written to %s\n" : "coscope: cannot write screenshot %s\n", qPrintable(file));
            QApplication::exit(ok ? 0 : 1);
        });
    }
    return app.exec();
}
