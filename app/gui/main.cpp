// metrofit: the GUI workbench. Thin: command line, surface format, translations, then MainWindow.
#include <QApplication>
#include <QCommandLineParser>
#include <QSettings>
#include <QSurfaceFormat>
#include <QTemporaryDir>
#include <QTextStream>
#include <clocale>
#include <cstdio>

#include "app/gui/language.h"
#include "app/gui/mainwindow.h"
#include "app/gui/screenshots.h"
#include "metrofit/version.h"

namespace {

const QString kScreenshotsOption = QStringLiteral("screenshots");
const QString kLanguageOption = QStringLiteral("lang");

void configureParser(QCommandLineParser& parser) {
  parser.setApplicationDescription(
      QCoreApplication::translate("main", "Metrofit — a workbench for machining error compensation."));
  parser.addHelpOption();
  parser.addVersionOption();
  parser.addOption(
      {kScreenshotsOption,
       QCoreApplication::translate("main",
                                   "Open the bundled demo project, save one PNG per main view into "
                                   "<dir> and exit (needs an X server; Xvfb will do)."),
       QCoreApplication::translate("main", "dir")});
  parser.addOption(
      {kLanguageOption,
       QCoreApplication::translate("main",
                                   "User interface language for this run: en, de or pl (overrides "
                                   "the Preferences; the screenshots are in English without it)."),
       QCoreApplication::translate("main", "language")});
  parser.addPositionalArgument(QCoreApplication::translate("main", "project"),
                               QCoreApplication::translate("main", "A project file (.metrofit) to open."),
                               QCoreApplication::translate("main", "[project]"));
}

void setApplicationNames() {
  QCoreApplication::setOrganizationName(QStringLiteral("Metrofit"));
  QCoreApplication::setApplicationName(QStringLiteral("metrofit"));
  QCoreApplication::setApplicationVersion(QString::fromLatin1(metrofit::kVersion));
}

}  // namespace

int main(int argc, char* argv[]) {
  // The screenshot mode needs X for the VTK views; decide before anything touches a display.
  QStringList arguments;
  for (int i = 0; i < argc; ++i) arguments << QString::fromLocal8Bit(argv[i]);
  QCommandLineParser preParser;
  configureParser(preParser);
  // Qt's own options (-platform, -style, ...) are unknown here: errors are reported by process() below,
  // once QApplication has taken its options out.
  (void)preParser.parse(arguments);
  if (preParser.isSet(QStringLiteral("help")) || preParser.isSet(QStringLiteral("help-all")) ||
      preParser.isSet(QStringLiteral("version"))) {
    // Help and the version need no display.
    QCoreApplication app(argc, argv);
    setApplicationNames();
    metrofit::useLanguage(app, metrofit::effectiveLanguage(metrofit::languageSetting()));
    QCommandLineParser parser;
    configureParser(parser);
    parser.process(app);  // prints and exits
    return 0;
  }
  const bool screenshots = preParser.isSet(kScreenshotsOption);
  if (screenshots) {
    if (!metrofit::environmentHasXServer()) {
      std::fprintf(stderr, "%s\n", metrofit::kScreenshotsNeedXMessage);
      return 2;
    }
    // An unreachable display falls back to offscreen instead of aborting; detected below.
    const QByteArray platform = qgetenv("QT_QPA_PLATFORM");
    qputenv("QT_QPA_PLATFORM", (platform.isEmpty() ? QByteArray("xcb") : platform) + ";offscreen");
  }

  // VTK's OpenGL views need a 3.2 core profile with a depth buffer; set before QApplication.
  QSurfaceFormat format;
  format.setRenderableType(QSurfaceFormat::OpenGL);
  format.setVersion(3, 2);
  format.setProfile(QSurfaceFormat::CoreProfile);
  format.setDepthBufferSize(24);
  format.setStencilBufferSize(8);
  QSurfaceFormat::setDefaultFormat(format);

  QApplication app(argc, argv);
  // QApplication set the whole C locale from the environment (setlocale(LC_ALL, "") on Unix): numbers
  // in files are written by core under an explicit C locale anyway (core/common/numformat.h), and
  // with LC_NUMERIC "C" no library printf in the process writes a decimal comma either. What the
  // user sees follows the UI language through QLocale (app/gui/language.cpp), not LC_NUMERIC.
  std::setlocale(LC_NUMERIC, "C");
  setApplicationNames();
  QApplication::setApplicationDisplayName(QStringLiteral("Metrofit"));

  if (screenshots) {
    if (QGuiApplication::platformName() != QLatin1String("xcb")) {
      std::fprintf(stderr, "%s\n", metrofit::kScreenshotsNeedXMessage);
      return 2;
    }
    // Screenshots are in English (or the --lang language) and leave the user's settings alone.
    QTemporaryDir settingsDir;
    QSettings::setPath(QSettings::NativeFormat, QSettings::UserScope, settingsDir.path());
    QCommandLineParser parser;
    configureParser(parser);
    parser.process(app);
    if (parser.isSet(kLanguageOption) && !metrofit::applyLanguageOption(app, parser.value(kLanguageOption)))
      return 2;
    QTextStream err(stderr);
    return metrofit::runScreenshots(parser.value(kScreenshotsOption), err);
  }

  QCommandLineParser parser;
  configureParser(parser);
  parser.process(app);
  if (parser.isSet(kLanguageOption)) {
    if (!metrofit::applyLanguageOption(app, parser.value(kLanguageOption))) return 2;
  } else {
    metrofit::useLanguage(app, metrofit::effectiveLanguage(metrofit::languageSetting()));
  }

  metrofit::MainWindow window;
  window.restoreLayout();  // size, docks, splitters and page of the last run
  window.show();
  if (!parser.positionalArguments().isEmpty()) {
    window.openProject(parser.positionalArguments().constFirst());  // offers its autosaved copy
  } else {
    window.recoverUntitled();  // an unsaved project left by a crash
  }
  return app.exec();
}
