#pragma once
// A saved thermal model (thermal_model.h) in a form a machine control runs (issue 31 item 1):
// `metrofit-cli thermal export --model M.json --format st|siemens|heidenhain|isg|csv --out FILE`.
//
// What every form computes: the model's own prediction of the thermal error since a reference, the
// regression models (lag_regression.h) as
//   e = c + sum_t b_t (u_t - r_{j(t)})            [the target's unit, um for a *_um target]
//   u_t = x_j (tau_t = 0)   or   u_t = L_tau_t[x_j] (the sensor through a first-order lag)
// with r_j the sensor values at the reference: the model was fitted on changes since the first row of
// its log, so the reference is the first sample after the control resets the compensation (power-on,
// or a reset when the machine is at its reference state). The compensation is -e.
//
// Discretisation of the lag (the same filter the model was fitted with, lag_regression.h): exact
// zero-order hold with the input held at its new value over the step,
//   s(k) = s(k-1) + (1 - exp(-dt_k / tau)) (x(k) - s(k-1)),   s(reference) = x(reference),
// i.e. s(k) = a s(k-1) + (1 - a) x(k) with a = exp(-dt/tau). For a unit step applied just after the
// reference sample it gives s(k) = 1 - exp(-(t_k - t_0) / tau) at every sample, the continuous lag's
// step response exactly (tests/core/thermal/control_export_test.cpp checks it through the ST block).
//
// The forms (each file starts with a header of its assumptions, in the form's comment syntax):
//   * st: an IEC 61131-3 FUNCTION_BLOCK in Structured Text (REAL arithmetic): inputs the model's
//     sensors, `dt_s` (seconds since the previous call: the sample period) and `reset`; state the
//     reference values and the lag filters; outputs `error_um` (e), `comp_um` (-e, limited to
//     +-limitUm) and `limited`. linear, lag, dlag and mlp (the network written out: mapminmax,
//     logistic hidden layer, linear output).
//   * siemens: SINUMERIK temperature compensation (function manual K3): MD32750 $MA_TEMP_COMP_TYPE
//     bit 0 (position-independent), SD43910 $SA_TEMP_COMP_SLOPE = 0, SD43920
//     $SA_TEMP_COMP_REF_POSITION = 0, and SD43900 $SA_TEMP_COMP_ABS_VALUE (mm) which the PLC writes
//     each cycle from the formula in the header (the value of the error line, K_TCabs).
//   * heidenhain: the TEMPCOMP formula of the kinematics description table (TNC 426/430, iTNC 530
//     technical manuals: "TEMPCOMP = 300 + 3.45e-3 * (W486 - 20)"), in mm, over PLC words that
//     hold the sensors, their reference values and (lag) the filtered sensors.
//   * isg: ISG kernel / Beckhoff TwinCAT CNC axis parameters (P-AXIS-00271..00274):
//     ds(T, s) = offset(T) + coefficient(T) (s - s0), lr_param.temp_comp 1, temp_comp_position_0 = 0,
//     temp_comp_coefficient = 0 and temp_comp_offset_0 [0.1 um] written by the PLC from the formula.
//   * csv: a table of e and -e on a grid of the regressors (the sensor changes since the reference,
//     filtered ones for lag terms) for controls that take tables.
// Vendor forms are linear in PLC values: the MLP (nonlinear) and the grey models are refused with the
// reason; the grey models (GMC(1,N), GNNMCI(1,N)) in every form: their prediction is the inverse
// accumulation of a convolution over the whole log from its first row, with a start transient (grey.h).
//
// Numbers are written locale-independently (core/common/numformat.h): the same model gives the same
// bytes under any locale. Nothing here prints or exits; refusals are ValidationErrors.
#include <string>
#include <vector>

#include "core/thermal/thermal_model.h"

namespace metrofit::thermal {

enum class ControlFormat { St, Siemens, Heidenhain, Isg, Csv };
inline constexpr ControlFormat kAllControlFormats[] = {ControlFormat::St, ControlFormat::Siemens,
                                                       ControlFormat::Heidenhain, ControlFormat::Isg,
                                                       ControlFormat::Csv};
/// "st", "siemens", "heidenhain", "isg", "csv".
const char* toString(ControlFormat format);
/// The format named `name`; OptionsError naming `field` otherwise.
ControlFormat controlFormat(const std::string& name, const std::string& field = "--format");

/// One axis of the csv grid: the regressor `name` (a model input) from `from` to `to` by `step`.
struct ControlGridAxis {
  std::string input;
  double from = 0.0, to = 10.0, step = 2.0;
};

struct ControlExportOptions {
  std::string source = "model.json";  ///< the model file, for messages and the header (its file name)
  char axis = 'Z';                    ///< the compensated axis (siemens, heidenhain, isg)
  double samplePeriodS = 0.0;         ///< the PLC's filter period for the header; 0: the model's time unit
  double limitUm = 100.0;             ///< st: |comp_um| is limited to this (> 0)
  /// csv: grids of some inputs; the others run over kDefaultGrid (regression: 0..10 in the input's
  /// unit, changes since the reference) or the MLP's training range in kDefaultGridPoints points.
  std::vector<ControlGridAxis> grid;
  std::size_t maxTableRows = 200000;  ///< csv: more grid points are refused (coarser --grid)

  bool isValid(std::string* why) const;
};
inline constexpr int kDefaultGridPoints = 6;

/// Empty when `model` can take `format`, else one sentence saying why not (for the GUI's choices).
std::string controlExportRefusal(const ThermalModel& model, ControlFormat format);

/// The file text of `model` in `format` (see the header comment). ValidationError naming the model
/// file and field 'model' when the model cannot take the form; OptionsError for bad options (a grid
/// of an input the model does not have, too many table rows).
std::string exportControl(const ThermalModel& model, ControlFormat format,
                          const ControlExportOptions& options);

/// The name the ST block gives each model input (an IEC 61131-3 identifier, unique without regard to
/// case): the column name with other characters as '_', "in_" before a leading digit or a keyword.
std::vector<std::string> stInputNames(const ThermalModel& model);

}  // namespace metrofit::thermal
