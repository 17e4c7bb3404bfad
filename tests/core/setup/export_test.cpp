// Export of setup corrections for controllers (core/setup/export.h): exact text of every format.
#include <gtest/gtest.h>

#include "core/common/error.h"
#include "core/setup/export.h"
#include "setup_fixtures.h"

namespace metrofit::setup {
namespace {

using nlohmann::json;

/// A machine point, WKS 1 and 7, tools 5 and 23, all acting on one feature.
Model exportModel() {
  json j{{"name", "Export test (fixture A)"}, {"step_mm", 0.001}, {"bounds_mm", {-0.1, 0.1}}};
  j["setup"] = {{{"id", "M1"}, {"kind", "machine"}},
                {{"id", "W1"}, {"kind", "wks"}},
                {{"id", "W7"}, {"kind", "wks"}},
                {{"id", "T5"}, {"kind", "tool"}},
                {{"id", "T23"}, {"kind", "tool"}}};
  j["features"] = {{{"id", "F1"}}};
  j["dimensions"] = {{{"id", "D1"}, {"lower", -0.1}, {"upper", 0.1}}};
  j["arcs"] = json::array();
  for (const char* s : {"M1", "W1", "W7", "T5", "T23"})
    j["arcs"].push_back({{"from", s}, {"to", "F1"}, {"weight", 1}});
  j["arcs"].push_back({{"from", "F1"}, {"to", "D1"}, {"weight", 1}});
  return modelFromJson(j, "export.json");
}

const std::vector<double> kX{0.0, 0.004, -0.010000000000000002, -0.012, -0.0};

TEST(SetupExport, Fanuc) {
  EXPECT_EQ(exportCorrections(exportModel(), kX, ControllerFormat::Fanuc), R"GOLD(%
O9001 (METROFIT SETUP CORRECTIONS)
(EXPORT TEST [FIXTURE A])
(G91: EACH VALUE IS ADDED TO THE OFFSET REGISTER, MM)
(+ MOVES THE WORK ZERO / TOOL TIP TOWARDS +Z)
G21 G91
G10 L2 P0 Z0.000 (M1 EXTERNAL WORK OFFSET)
G10 L2 P1 Z0.004 (W1 G54)
G10 L20 P1 Z-0.010 (W7 G54.1 P1)
G10 L11 P5 R-0.012 (T5 LENGTH WEAR)
G10 L11 P23 R0.000 (T23 LENGTH WEAR)
G90
M30
%
)GOLD");
  ExportOptions o;
  o.toolOffset = ToolOffset::Geometry;
  o.programNumber = 12;
  const std::string g = exportCorrections(exportModel(), kX, ControllerFormat::Fanuc, o);
  EXPECT_NE(g.find("O0012 (METROFIT SETUP CORRECTIONS)\n"), std::string::npos) << g;
  EXPECT_NE(g.find("G10 L10 P5 R-0.012 (T5 LENGTH GEOMETRY)\n"), std::string::npos) << g;
}

TEST(SetupExport, Heidenhain) {
  EXPECT_EQ(exportCorrections(exportModel(), kX, ControllerFormat::Heidenhain),
            R"GOLD(; Metrofit setup corrections for HEIDENHAIN TNC: Export test (fixture A)
; Every value is an INCREMENT in mm: + moves the preset / tool tip towards +Z.
; PRESET.PR: enter each value in column Z of row NR with "Correct" (incremental).
; M1: machine point +0.000 mm has no register here; apply it to every preset by hand
NR      DOC                         Z
1       W1                     +0.004
7       W7                     -0.010
; TOOL.T: add each value to column DL of tool T.
T       NAME                       DL
5       T5                     -0.012
23      T23                    +0.000
)GOLD");
}

TEST(SetupExport, Siemens) {
  EXPECT_EQ(exportCorrections(exportModel(), kX, ControllerFormat::Siemens),
            R"GOLD(; Metrofit setup corrections for SINUMERIK: Export test (fixture A)
; Every value is ADDED to the register, mm: + moves the work zero / tool tip towards +Z.
; Reselect the settable frame (G54 ...) and the tool offset (D) for the values to take effect.
; M1: machine point +0.000 mm has no register here; apply it to every frame by hand
$P_UIFR[1,Z,FI]=$P_UIFR[1,Z,FI]+0.004 ; W1 G54 fine offset
$P_UIFR[7,Z,FI]=$P_UIFR[7,Z,FI]-0.010 ; W7 G507 fine offset
$TC_DP12[5,1]=$TC_DP12[5,1]-0.012 ; T5 D1 wear length 1
$TC_DP12[23,1]=$TC_DP12[23,1]+0.000 ; T23 D1 wear length 1
M30
)GOLD");
  ExportOptions o;
  o.toolOffset = ToolOffset::Geometry;
  o.cuttingEdge = 2;
  const std::string g = exportCorrections(exportModel(), kX, ControllerFormat::Siemens, o);
  EXPECT_NE(g.find("$TC_DP3[5,2]=$TC_DP3[5,2]-0.012 ; T5 D2 geometry length 1\n"), std::string::npos) << g;
}

TEST(SetupExport, Csv) {
  EXPECT_EQ(exportCorrections(exportModel(), kX, ControllerFormat::Csv),
            R"GOLD(# Metrofit setup corrections: Export test (fixture A)
# correction_mm is an increment to ADD to the register; + moves the work zero / tool tip towards +axis
id,kind,register,axis,correction_mm
M1,machine,,Z,0.000
W1,wks,1,Z,0.004
W7,wks,7,Z,-0.010
T5,tool,5,Z,-0.012
T23,tool,23,Z,0.000
)GOLD");
}

TEST(SetupExport, RegistersAndErrors) {
  Model m = exportModel();
  EXPECT_EQ(registerOf(m, 2), 7);
  EXPECT_EQ(registerOf(m, 4), 23);
  m.setup[2].registerNumber = 3;
  EXPECT_EQ(registerOf(m, 2), 3);
  EXPECT_NE(exportCorrections(m, kX, ControllerFormat::Fanuc).find("G10 L2 P3 Z-0.010 (W7 G56)\n"),
            std::string::npos);
  m.setup[3].id = "TX";
  try {
    (void)exportCorrections(m, kX, ControllerFormat::Siemens);
    FAIL() << "no error";
  } catch (const ValidationError& e) {
    EXPECT_STREQ(e.what(),
                 "export.json: field 'setup[3].register': cannot derive a register number from id 'TX'; add "
                 "\"register\"");
  }
  // The CSV needs no register.
  EXPECT_NE(exportCorrections(m, kX, ControllerFormat::Csv).find("TX,tool,,Z,-0.012\n"), std::string::npos);
  EXPECT_THROW((void)exportCorrections(m, std::vector<double>{0.0}, ControllerFormat::Csv), ValidationError);
  EXPECT_EQ(parseControllerFormat("heidenhain"), ControllerFormat::Heidenhain);
  try {
    (void)parseControllerFormat("haas");
    FAIL() << "no error";
  } catch (const OptionsError& e) {
    EXPECT_STREQ(e.what(),
                 "field '--export': unknown format 'haas' (one of fanuc, heidenhain, siemens, csv)");
  }
  ExportOptions bad;
  bad.programNumber = 0;
  EXPECT_THROW((void)exportCorrections(exportModel(), kX, ControllerFormat::Fanuc, bad), OptionsError);
}

TEST(SetupExport, DecimalsFollowTheStep) {
  Model m = exportModel();
  m.stepMm = 0.0001;
  const std::vector<double> x{0.0, 0.0042, 0.0, 0.0, 0.0};
  EXPECT_NE(exportCorrections(m, x, ControllerFormat::Fanuc).find("G10 L2 P1 Z0.0042 (W1 G54)\n"),
            std::string::npos);
}

}  // namespace
}  // namespace metrofit::setup
