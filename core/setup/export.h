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
//    followed by G90 and M30; the axis word is the model's axis. L10/L11 assume tool offset memory
//    C (separate geometry and wear); a tool length change acts at the next G43 H. Program number
//    ExportOptions::programNumber, default O7001: O8000-O9999 are refused with the reason
//    (parameter 3202 NE8 / NE9, core/io/nc_program.h).
//  * heidenhain: a listing for the operator (the file the control loads is heidenhain-table, below):
//    the rows of the preset table PRESET.PR (NR = register, DOC = id, the axis column
//    holds the increment: enter it with "Correct", incremental) and of the tool table TOOL.T
//    (T = register, NAME = id, DL = increment of the delta length; L with ToolOffset::Geometry).
//    Machine points have no register: written as a comment.
//  * siemens: SINUMERIK assignments that add to the settable frames' fine offset and to the tool
//    length 1 of cutting edge D (ExportOptions::cuttingEdge):
//      $P_UIFR[n,Z,FI]=$P_UIFR[n,Z,FI]+x    n = 1..4 -> G54..G57, 5..99 -> G505..G599
//      $TC_DP12[t,d]=$TC_DP12[t,d]+x        wear length 1 ($TC_DP3: geometry length 1)
//    then M30; the frame must be reselected (e.g. G54) to take effect. Machine points have no
//    register: written as a comment. The header names the machine data the file needs:
//    MD18600 $MN_FRAME_FINE_TRANS = 1 (fine offset; SINUMERIK function manual K2, "Frames": else alarm
//    "FRAME: fine offset not possible") and, for frames 5..99, MD28080 $MC_MM_NUM_USER_FRAMES
//    (number of settable frames G500, G54..G57, G505..G599; programming manual, "Settable work offset").
//  * csv: id,kind,register,axis,correction_mm (all setup data; a header comment with the sign
//    convention).
//
// HEIDENHAIN TABLE FILES (updateHeidenhainTable). DECISION: the control's own table file, updated,
// rather than an NC program that writes cells. Reasons: FN 17 SYSWRITE needs an OEM code number on the
// TNC 426/430 (technical manual, "Data transfer NC program -> NC (SYSWRITE)": code number 555 343) and
// its ID/NR numbers differ between control generations; TABDATA and SQL are not on every TNC. The
// table file is what every TNC imports (Tables mode, TNCremo, USB) and its layout is fixed:
//   line 1  "BEGIN <NAME>.<EXT> MM|INCH [Version: ...]"        (e.g. BEGIN PRESET.PR MM, BEGIN TOOL.T MM)
//   line 2  the column names; a column starts where its name starts and ends where the next begins
//   rows    one per line, each cell left-aligned in its column ("+30", "+0.5", text)
//   last    "[END]"
// (layout of the public TOOL.T example and table reader of pyLSV2, github.com/drunsinn/pyLSV2,
// tests/test_files/tool.t and pyLSV2/table_reader.py; preset table columns NO/NR, DOC, X, Y, Z, ...
// from the TNC7 user's manual, "Preset table", whose X/Y/Z are the preset's coordinates in the basic
// coordinate system B-CS). A table file REPLACES the control's table, and the corrections are
// INCREMENTS; so the input is the control's CURRENT table (saved from the control), and the output is
// that table with the increments added to the cells, every other byte unchanged: the same effect as the
// control's "Correct" entry on each cell. Assumptions (stated in the CLI and docs too):
//  * preset table (*.PR): row NO (or NR) = register of each WKS; column = the model's axis; the value is
//    the preset position along that axis in B-CS, so +x moves the workpiece zero by +x. A preset
//    with a basic rotation (SPA/SPB/SPC, ROT) turns B-CS against the machine axes: not checked here.
//  * tool table (*.T): row T = register of each tool; column DL (ToolOffset::Wear) or L (Geometry).
//  * machine points have no row: not written (listed in TableUpdate::notWritten).
//  * INCH tables: the increment is converted (mm / 25.4).
//  * after the import the preset must be activated again and the tool called again (TOOL CALL) for
//    the new values to take effect; import with no NC program running.
#include <span>
#include <string>
#include <vector>

#include "core/setup/model.h"

namespace metrofit::setup {

enum class ControllerFormat { Fanuc, Heidenhain, Siemens, Csv };
enum class ToolOffset { Wear, Geometry };

/// "fanuc", "heidenhain", "siemens", "csv" -> format; OptionsError naming `field` otherwise.
ControllerFormat parseControllerFormat(const std::string& name, const std::string& field = "--export");
const char* toString(ControllerFormat format);

struct ExportOptions {
  ToolOffset toolOffset = ToolOffset::Wear;
  int programNumber = 7001;  ///< Fanuc O-number, 1..7999 (core/io/nc_program.h: O8000-O9999 need
                             ///< parameter 3202 NE8/NE9 cleared)
  int cuttingEdge = 1;       ///< Siemens D number (1..12)
  std::string title;         ///< first comment line; default: the model name

  bool isValid(std::string* why) const;
};

/// Register number of setup datum i (see above).
int registerOf(const Model& model, std::size_t i);

/// The corrections `x` (mm, one per setup datum of the model) in the given format.
std::string exportCorrections(const Model& model, std::span<const double> x, ControllerFormat format,
                              const ExportOptions& options = {});

/// Result of updateHeidenhainTable.
struct TableUpdate {
  std::string text;                     ///< the updated table file
  std::string table;                    ///< "PRESET.PR", "TOOL.T" (name and extension of its BEGIN line)
  std::vector<std::string> written;     ///< ids of the setup data whose cell was updated
  std::vector<std::string> notWritten;  ///< ids with no row in a table of this kind
};

/// The control's current preset table (*.PR) or tool table (*.T), `table` read from `source`, with the
/// corrections `x` added (see above). ValidationError naming `source` and the line for a file that is
/// not such a table, a missing column, a setup datum whose row is missing, a cell that is not a number
/// or a new value that does not fit its column.
TableUpdate updateHeidenhainTable(const Model& model, std::span<const double> x, const std::string& table,
                                  const std::string& source, const ExportOptions& options = {});

}  // namespace metrofit::setup
