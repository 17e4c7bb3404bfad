#include "widgets/thermal/thermalverdict.h"

#include <QCoreApplication>

namespace metrofit {
namespace {
struct Text {
  Q_DECLARE_TR_FUNCTIONS(metrofit::ThermalVerdict)
};

QString signedNumber(double v, int decimals, const QLocale& locale) {
  QString s = locale.toString(v, 'f', decimals);
  if (s.startsWith(QLatin1Char('-'))) s.replace(0, 1, QStringLiteral("−"));
  return s;
}
}  // namespace

QString thermalVerdictLabel(thermal::ModelVerdict verdict) {
  return verdict == thermal::ModelVerdict::Usable ? Text::tr("usable") : Text::tr("not usable");
}

QString thermalVerdictReason(thermal::ModelVerdict verdict, const thermal::ThermalMetrics& m,
                             const QLocale& locale) {
  switch (verdict) {
    case thermal::ModelVerdict::Usable:
      return {};
    case thermal::ModelVerdict::Diverges:
      return Text::tr("its prediction diverges on the held-out rows");
    case thermal::ModelVerdict::NegativeEfficiency:
      return Text::tr("E = %1 on the held-out rows, below %2: it predicts worse than the mean of the error")
          .arg(signedNumber(m.e, 2, locale), signedNumber(thermal::kMinEfficiency, 0, locale));
    case thermal::ModelVerdict::LowCorrelation:
      return Text::tr("R = %1 on the held-out rows, below %2: it hardly follows the error")
          .arg(signedNumber(m.r, 2, locale), locale.toString(thermal::kMinCorrelation, 'f', 1));
  }
  return {};
}

}  // namespace metrofit
