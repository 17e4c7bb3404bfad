#pragma once
// Export of setup corrections in the form the controller takes them (the last link of the
// paper's process chain, Stryczek 2016 Fig. 2: "conveyed to the right registers directly").
//
// SIGN CONVENTION (all formats). A correction x_i (mm) is an INCREMENT to ADD to the register of
// setup datum i along the model's axis (docs/file-formats.md#setup-result: corrections_mm). The relation
// graph's weights (model.h, paper Eq. 3) describe what such an increment does: +1 on an arc means that
// increasing the register moves the feature towards +axis. For a work offset (WKS) the register
// holds the position of the workpiece zero in machine coordinates, so +x moves every feature of
// that WKS by +x. For a tool, the register is the tool length (geometry or wear): +x makes the
// controller take the tool as x longer, so the tool tip and the surface it cuts end x further
// towards +axis (the spindle axis). Machine points (kind "machine", level 0) shift every work
// offset together.
//
// Register numbers: SetupDatum::registerNumber, else the digits that end the id (W7 -> 7,
// T23 -> 23); an id without digits is an error naming setup[i].register.
//
// Formats (one text file each; decimals = those of step_mm, at least 3):
//  * fanuc: an NC program in incremental mode (G91), where G10 ADDS to the offset registers:
//      G10 L2 P1..P6 Z..      work offsets G54..G59 (register 1..6)
//      G10 L20 P1..P300 Z..   extended work offsets G54.1 P1.. (register 7.. -> P = register - 6)
//      G10 L2 P0 Z..          external work offset (machine points)
//      G10 L11 P<tool> R..    tool length wear (L10: geometry, ExportOptions::toolOffset)
//    followed by G90 and M30; the axis word is the model's axis.
//  * heidenhain: the rows of the preset table PRESET.PR (NR = register, DOC = id, the axis column
//    holds the increment: enter it with "Correct", incremental) and of the tool table TOOL.T
//    (T = register, NAME = id, DL = increment of the delta length; L with ToolOffset::Geometry).
//    Machine points have no register: written as a comment.
//  * siemens: SINUMERIK assignments that add to the settable frames' fine offset and to the tool
//    length 1 of cutting edge D (ExportOptions::cuttingEdge):
//      $P_UIFR[n,Z,FI]=$P_UIFR[n,Z,FI]+x    n = 1..4 -> G54..G57, 5..99 -> G505..G599
//      $TC_DP12[t,d]=$TC_DP12[t,d]+x        wear length 1 ($TC_DP3: geometry length 1)
//    then M30; the frame must be reselected (e.g. G54) to take effect. Machine points have no
//    register: written as a comment.
//  * csv: id,kind,register,axis,correction_mm (all setup data; a header comment with the sign
//    convention).
#include <span>
#include <string>

#include "core/setup/model.h"

namespace metrofit::setup {

enum class ControllerFormat { Fanuc, Heidenhain, Siemens, Csv };
enum class ToolOffset { Wear, Geometry };

/// "fanuc", "heidenhain", "siemens", "csv" -> format; OptionsError naming `field` otherwise.
ControllerFormat parseControllerFormat(const std::string& name, const std::string& field = "--export");
const char* toString(ControllerFormat format);

struct ExportOptions {
  ToolOffset toolOffset = ToolOffset::Wear;
  int programNumber = 9001;  ///< Fanuc O-number (1..9999)
  int cuttingEdge = 1;       ///< Siemens D number (1..12)
  std::string title;         ///< first comment line; default: the model name

  bool isValid(std::string* why) const;
};

/// Register number of setup datum i (see above).
int registerOf(const Model& model, std::size_t i);

/// The corrections `x` (mm, one per setup datum of the model) in the given format.
std::string exportCorrections(const Model& model, std::span<const double> x, ControllerFormat format,
                              const ExportOptions& options = {});

}  // namespace metrofit::setup
