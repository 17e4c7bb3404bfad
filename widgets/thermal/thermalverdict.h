#pragma once
// The verdict on a fitted thermal model in the reader's words, for the report and the thermal page.
// The thresholds are core/thermal/model_verdict.h's (the one place they are set).
#include <QLocale>
#include <QString>

#include "core/thermal/model_verdict.h"

namespace metrofit {

/// "usable" or "not usable".
QString thermalVerdictLabel(thermal::ModelVerdict verdict);
/// Why a model is not usable, with the numbers ("E = −0.58 on the held-out rows, below 0: it predicts
/// worse than the mean"); empty for a usable model. Numbers in `locale`: the page's (the UI language)
/// by default; the report, which is written in English, passes QLocale::c().
QString thermalVerdictReason(thermal::ModelVerdict verdict, const thermal::ThermalMetrics& heldout,
                             const QLocale& locale = QLocale());

}  // namespace metrofit
