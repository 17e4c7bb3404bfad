#pragma once
// `metrofit --screenshots DIR` (docs/file-formats.md#screenshots): opens the bundled demo project, shows
// every main view in turn and saves one PNG of the window per view into DIR.
#include <QString>
#include <QStringList>

class QTextStream;

namespace metrofit {

/// The one line printed when the screenshot mode has no X server.
inline constexpr const char* kScreenshotsNeedXMessage =
    "metrofit: --screenshots needs an X server for the 3D views; run under xvfb-run -a";

/// True when the process environment promises an X server: QT_QPA_PLATFORM unset or "xcb" (with
/// or without options) and DISPLAY set. Checked before QApplication exists.
bool environmentHasXServer();

/// Runs the screenshot mode in an existing QApplication on the xcb platform. Writes the PNGs and
/// one summary line to `err`; returns the exit code (0 done, 1 when a file cannot be written or the
/// demo cannot be opened).
int runScreenshots(const QString& outDir, QTextStream& err);

}  // namespace metrofit
