// SPDX-License-Identifier: GPL-3.0-or-later
// coscope: the desktop app.
#include "app/BuildInfo.h"
#include "app/gui/MainWindow.h"
#include "app/gui/Screenshot.h"
#include "app/gui/StartView.h"
#include "app/gui/language/Language.h"
#include "app/gui/session/SimulationDemo.h"
#include "app/gui/wizards/WizardMenu.h"
#include "core/log/Logging.h"
#include "eds/SimulatorDictionaries.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QTimer>

#include <cstdio>

using namespace coscope;

int main(int argc, char** argv) {
    const bool haveDisplay = !qEnvironmentVariableIsEmpty("DISPLAY") ||
                             !qEnvironmentVariableIsEmpty("WAYLAND_DISPLAY") ||
                             !qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM");
    bool wantsHelpOnly = false;
    for (int i = 1; i < argc; ++i) {
        const QByteArray a(argv[i]);
        if (a == "--help" || a == "-h" || a == "--version" || a == "-v") wantsHelpOnly = true;
    }
    if (!haveDisplay && !wantsHelpOnly) {
        std::fprintf(stderr,
                     "coscope: no display found (DISPLAY/WAYLAND_DISPLAY unset); use the command line instead: "
                     "coscope-cli --help\n");
        return 1;
    }
    if (!haveDisplay) qputenv("QT_QPA_PLATFORM", "offscreen");

    QApplication app(argc, argv);
    QApplication::setApplicationName(QStringLiteral("CoScope"));
    QApplication::setOrganizationName(QStringLiteral("CoScope"));
    QApplication::setApplicationVersion(QStringLiteral(COSCOPE_VERSION));
    QGuiApplication::setDesktopFileName(buildinfo::applicationId());  // Wayland: icon and name from the .desktop entry

    QCommandLineParser parser;
    parser.setApplicationDescription(
        QStringLiteral("CoScope - CANopen bus analyzer and servo-drive commissioning tool"));
    parser.addHelpOption();
    const QCommandLineOption version({QStringLiteral("v"), QStringLiteral("version")},
                                     QStringLiteral("Print the version and the source revision."));
    parser.addOption(version);
    const QCommandLineOption simulate(QStringLiteral("simulate"),
                                      QStringLiteral("Connect to the default virtual drive network (sim://)."));
    const QCommandLineOption connectTo(QStringLiteral("connect"), QStringLiteral("Connect to a bus URL."),
                                       QStringLiteral("URL"));
    const QCommandLineOption logLevel(QStringLiteral("log-level"),
                                      QStringLiteral("trace, debug, info, warn, error, critical, off."),
                                      QStringLiteral("LEVEL"));
    const QCommandLineOption screenshot(
        QStringLiteral("screenshot"),
        QStringLiteral("Render the window to a PNG once the view has content, then exit."), QStringLiteral("FILE"));
    const QCommandLineOption view(
        QStringLiteral("view"),
        QStringLiteral("The view to show first: trace, nodes, od, plot, events, console, help (the guide), or "
                       "wizard-ID (a commissioning wizard: pdo, nodeid, ds402, ds402-homing, ds402-position)."),
        QStringLiteral("VIEW"));
    const QCommandLineOption lang(
        QStringLiteral("lang"),
        QStringLiteral(
            "The UI language for this run: en, zh_TW or zh_CN (default: View > Language, else the system's)."),
        QStringLiteral("LANG"));
    parser.addOptions({simulate, connectTo, logLevel, screenshot, view, lang});
    parser.addPositionalArgument(QStringLiteral("FILE"),
                                 QStringLiteral("A CAN log to open (candump, ASC, BLF, TRC, pcap, CSV)."),
                                 QStringLiteral("[FILE]"));
    parser.process(app);
    if (parser.isSet(version)) {
        std::printf("%s\n", qPrintable(buildinfo::versionLine(QStringLiteral("coscope"))));
        return 0;
    }

    auto level = logging::levelFromEnvironment(spdlog::level::info);
    if (parser.isSet(logLevel)) {
        auto parsed = logging::parseLevel(parser.value(logLevel));
        if (!parsed) {
            std::fprintf(stderr, "coscope: invalid --log-level '%s'\n", qPrintable(parser.value(logLevel)));
            return 2;
        }
        level = *parsed;
    }
    const QString viewName = parser.value(view);
    QStringList views{QStringLiteral("trace"),
                      QStringLiteral("nodes"),
                      QStringLiteral("od"),
                      QStringLiteral("plot"),
                      QStringLiteral("events"),
                      QStringLiteral("health"),
                      QStringLiteral("console"),
                      QStringLiteral("transmit"),
                      QStringLiteral("processdata"),
                      QStringLiteral("help"),
                      QStringLiteral("program-download"),  // the program download dialog mid-transfer (Screenshot.cpp)
                      QStringLiteral("project-compare")};
    for (const gui::WizardEntry& w : gui::wizardEntries()) {
        views << QStringLiteral("wizard-") + w.id;
        for (const QString& page : w.pages) views << QStringLiteral("wizard-%1-%2").arg(w.id, page);
    }
    if (!viewName.isEmpty() && !views.contains(viewName)) {
        std::fprintf(stderr, "coscope: invalid --view '%s' (%s)\n", qPrintable(viewName),
                     qPrintable(views.join(QStringLiteral(", "))));
        return 2;
    }
    const QString langCode = parser.value(lang);
    if (!langCode.isEmpty() && !gui::language::available().contains(langCode)) {
        std::fprintf(stderr, "coscope: invalid --lang '%s' (%s)\n", qPrintable(langCode),
                     qPrintable(gui::language::available().join(QStringLiteral(", "))));
        return 2;
    }
    const QStringList files = parser.positionalArguments();
    if (files.size() > 1 || (!files.isEmpty() && (parser.isSet(simulate) || parser.isSet(connectTo)))) {
        std::fprintf(stderr, "coscope: give one log FILE, or --simulate, or --connect URL\n");
        return 2;
    }
    logging::init(QStringLiteral("coscope"), level);
    eds::installSimulatorDictionaries();  // before any sim:// bus is opened

    gui::language::apply(langCode.isEmpty() ? gui::language::saved() : langCode);
    gui::MainWindow window;
    window.setQuiet(parser.isSet(screenshot));
    window.show();
    // A dock at once; a wizard in its own window once the nodes are known (also for --screenshot).
    if (!viewName.isEmpty()) gui::showStartView(&window, viewName);
    if (parser.isSet(connectTo)) window.connectBus(parser.value(connectTo), true);
    else if (parser.isSet(simulate) && window.connectBus(QStringLiteral("sim://")))
        gui::startSimulationDemo(window.workspace());
    else if (!files.isEmpty()) window.openLog(files.first());

    if (parser.isSet(screenshot))
        gui::takeScreenshotWhenReady(&window, parser.value(screenshot),
                                     viewName.isEmpty() ? QStringLiteral("trace") : viewName);
    return app.exec();
}
