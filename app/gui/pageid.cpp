#include "app/gui/pageid.h"

#include "core/project/project.h"

namespace metrofit {

Page pageForStudy(const QString& s) {
  if (s == QLatin1String(study::kSetup)) return Page::Setup;
  if (s == QLatin1String(study::kMatching)) return Page::Matching;
  if (s == QLatin1String(study::kKinematics)) return Page::Kinematics;
  if (s == QLatin1String(study::kThermal)) return Page::Thermal;
  if (s == QLatin1String(study::kDiagnosis)) return Page::Diagnosis;
  return Page::Overview;
}

QString studyForPage(Page page) {
  switch (page) {
    case Page::Overview:
      return {};
    case Page::Setup:
      return QString::fromLatin1(study::kSetup);
    case Page::Matching:
      return QString::fromLatin1(study::kMatching);
    case Page::Kinematics:
      return QString::fromLatin1(study::kKinematics);
    case Page::Thermal:
      return QString::fromLatin1(study::kThermal);
    case Page::Diagnosis:
      return QString::fromLatin1(study::kDiagnosis);
  }
  return {};
}

}  // namespace metrofit
