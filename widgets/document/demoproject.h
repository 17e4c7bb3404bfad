#pragma once
// The bundled demo project (resources/demo: ":/demo/demo.metrofit" and ":/demo/data/*", compiled
// into the metrofit_resources object library, which the executable or test must link).
#include <QString>

namespace metrofit {

/// Resource path of the bundled demo project file.
inline constexpr const char* kDemoProjectResource = ":/demo/demo.metrofit";

/// Copies the demo project and its data files into `dir` (created when missing; existing files of
/// the same names are replaced) and returns the absolute path of the project file there. Throws
/// metrofit::FileError naming the file when the resources are missing or a file cannot be written.
QString extractDemoProject(const QString& dir);

/// The folder Help › Open demo project extracts into: `base` when it holds no demo project or one
/// that is still the bundled one byte for byte (so nothing of the user's is replaced), else the
/// first of `base`-2, `base`-3, … that is free or holds an unchanged demo (gui-run F15: a saved,
/// edited demo was silently overwritten).
QString demoFolderFor(const QString& base);

}  // namespace metrofit
