#pragma once
// The pages of the main window's central stack, in navigator order (Ctrl+1 .. Ctrl+6).
#include <QString>

namespace metrofit {

enum class Page { Overview = 0, Setup, Matching, Kinematics, Thermal, Diagnosis };
inline constexpr int kPageCount = 6;

/// The page of a study key (metrofit::study); Overview for an unknown key.
Page pageForStudy(const QString& study);
/// The study key of a page; empty for the overview.
QString studyForPage(Page page);

}  // namespace metrofit
