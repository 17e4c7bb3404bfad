#pragma once
// What the kinematics page and the report call the causes of the ballbar breakdown
// (core/kinematics/ballbar.h): a translated name and a one-line definition for each.
#include <QString>

#include <string>

namespace metrofit {

/// "Backlash X", ... for the breakdown's names (backlash_x, ..., "unexplained"); the name itself when
/// unknown.
QString ballbarCauseName(const std::string& name);
/// One line saying what the value is (its physical definition and sign), empty when unknown.
QString ballbarCauseTip(const std::string& name);

}  // namespace metrofit
