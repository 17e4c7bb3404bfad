#pragma once
// The one colour palette of Metrofit's charts, 3D views and report figures. Every view takes the
// colour of a meaning from here, so "measured" or "cooling" looks the same on every page and in the
// PDF report:
//   nominal      grey        the design / nominal geometry or the reference circle
//   measured     blue        what was measured (the first run direction when there are two)
//   measured2    orange      the second run direction of a measurement (clockwise loop)
//   compensated  green       compensated references / values after a correction is applied
//   predicted    purple      what a model expects (e.g. the path after compensation)
//   GNNMCI / GMC / MLP       the three thermal models (red / orange / brown)
//   heating / cooling        warm and cold phase bands (light fills) and their line colours
//   UCL / LCL    red         control limits; centre line green; LSL / USL purple (specification)
//   before / after           grey / dark blue (a correction's error before and after)
//   out of tolerance red, inside-tolerance green (zones, deviation maps)
// Categorical series without a fixed meaning (optimiser runs, sensor channels) use series(i).
#include <QColor>

namespace metrofit::palette {

QColor nominal();
QColor measured();
QColor measuredSecond();
QColor compensated();
QColor predicted();

QColor modelGnnmci();
QColor modelGmc();
QColor modelMlp();

/// Light fills of the heating / cooling phases (chart bands) and the stronger line colours.
QColor heatingFill();
QColor coolingFill();
QColor heatingLine();
QColor coolingLine();

QColor controlLimit();  ///< UCL / LCL
QColor centreLine();    ///< CL
QColor specLimit();     ///< LSL / USL
QColor histogramBars();

QColor before();
QColor after();
QColor outOfTolerance();
QColor inTolerance();    ///< the colour of a point inside the tolerance band (deviation maps)
QColor toleranceZone();  ///< light fill of a tolerance zone
QColor reference();      ///< an exact optimum / reference line (dark, drawn dashed)
QColor grid();           ///< grid lines
QColor axisText();       ///< axis lines, tick labels
QColor goodText();       ///< table text of a value that passes (dark green)
QColor badText();        ///< table text of a value that fails (dark red)

/// Deviation colour map (cool-warm, Moreland 2009): cold end, light cold, light warm, warm end.
QColor coldEnd();
QColor coldLight();
QColor warmLight();
QColor warmEnd();

/// A categorical colour (Tableau 10), index taken modulo 10.
QColor series(int index);

/// Sensor channels of a log, one palette per group, so that no two channels of a group share a
/// colour (the groups differ by line style too: temperatures solid, displacements dashed, speeds
/// dash-dotted). Temperatures: 20 mid-tone hues; displacements and strains: 10 dark hues; speeds:
/// 5 near-black/dark hues. Beyond a palette's length the hues repeat darker (still distinct).
QColor temperatureSeries(int index);
QColor displacementSeries(int index);
QColor speedSeries(int index);

}  // namespace metrofit::palette
