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

}  // namespace metrofit
