#pragma once
// The bad-input catalogue: malformed inputs for every reader and every subcommand
// of metrofit-cli. Each case names the files it writes (content generated here: UTF-16, binary,
// a 1 MB line, deep JSON nesting), the command line, the output files that must not appear (or stay
// unchanged when they existed), and substrings the one-line message must contain (the file name and
// the line/column or the field). bad_input_catalogue_test runs them through the CLI,
// bad_input_gui_test feeds a subset to the GUI and compares the messages.
#include <sys/wait.h>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "testsupport.h"

namespace metrofit::test::bad {

struct InputFile {
  std::string name;
  std::string content;
};

struct Case {
  std::string id;
  std::string reader;       ///< the reader or option family under test
  std::string description;  ///< what is wrong with the input
  std::string args;         ///< metrofit-cli arguments (shell words, relative to the case folder)
  std::vector<InputFile> files;
  std::vector<std::string> expect;  ///< substrings of the one-line message
  std::vector<std::string> outs;    ///< output files that must not be written
  bool preexistingOut = false;      ///< outs exist before the run and must stay unchanged
};

// ---- content generators ------------------------------------------------------------------------

/// UTF-16 LE with a byte-order mark (what Excel's "Unicode text" and Notepad write).
inline std::string utf16le(const std::string& ascii) {
  std::string out = "\xFF\xFE";
  for (char c : ascii) {
    out += c;
    out += '\0';
  }
  return out;
}

/// Bytes of a binary file (a PNG signature, NULs and high bytes).
inline std::string binary() {
  std::string out = "\x89PNG\r\n\x1A\n";
  for (int i = 0; i < 512; ++i) out += static_cast<char>((i * 37 + 11) % 256);
  return out;
}

inline std::string deepJson(int depth) {
  return std::string(static_cast<std::size_t>(depth), '[') +
         std::string(static_cast<std::size_t>(depth), ']');
}

/// Replaces the first occurrence of `from` (which must exist) by `to`.
inline std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  if (at == std::string::npos) return "replaced(): '" + from + "' not found";
  return text.replace(at, from.size(), to);
}

// ---- good inputs, made bad one defect at a time ------------------------------------------------

inline const std::string kLog =
    "time_min,T1,T2,T_amb,disp_z_um\n"
    "0,20.0,20.0,20.0,0.0\n"
    "1,21.0,20.5,20.0,-1.0\n"
    "2,22.5,21.0,20.1,-2.5\n"
    "3,24.0,22.0,20.1,-3.8\n"
    "4,25.0,23.0,20.2,-5.0\n"
    "5,26.0,23.5,20.2,-6.0\n"
    "6,26.5,24.0,20.2,-6.6\n"
    "7,27.0,24.4,20.3,-7.1\n"
    "8,27.2,24.9,20.3,-7.4\n"
    "9,27.4,25.2,20.3,-7.6\n";

inline const std::string kProbe =
    "id,surface,qx,qy,qz,nx,ny,nz,px,py,pz\n"
    "P1,top,0,0,60,0,0,1,0.010,0.002,60.021\n"
    "P2,top,100,0,60,0,0,1,100.012,0.004,60.018\n"
    "P3,top,0,100,60,0,0,1,0.008,100.003,60.025\n"
    "P4,left,0,50,30,-1,0,0,0.011,50.002,30.020\n"
    "P5,right,200,50,30,1,0,0,200.009,50.001,30.019\n"
    "P6,front,100,0,30,0,-1,0,100.010,0.003,30.022\n";

inline const std::string kHoles =
    "Plug Plate: 8131\n"
    "Date: 2014-10-14\n"
    "\n"
    "    Meas X    Meas Y     Nom X     Nom Y     Err X     Err Y  Meas D   Nom D   Round\n"
    "    11.610   -10.090    11.650   -10.184    -0.040     0.094   3.265   2.845   0.006\n"
    "    31.605   -10.150    31.650   -10.184    -0.045     0.034   3.262   2.845   0.004\n"
    "    11.700   -30.120    11.650   -30.184     0.050     0.064   3.270   2.845   0.005\n"
    "    31.640   -30.200    31.650   -30.184    -0.010    -0.016   3.266   2.845   0.007\n";

inline const std::string kModel = R"({
  "name": "small", "axis": "Z", "step_mm": 0.001, "bounds_mm": [-0.1, 0.1],
  "setup": [{"id": "W1", "kind": "wks"}, {"id": "T5", "kind": "tool"}],
  "features": [{"id": "F1"}, {"id": "F2"}],
  "dimensions": [{"id": "D1", "nominal": 42.0, "lower": -0.02, "upper": 0.02, "label": "POS_D1"},
                 {"id": "D2", "nominal": 18.5, "lower": -0.05, "upper": 0.03}],
  "arcs": [{"from": "W1", "to": "F1", "weight": 1}, {"from": "T5", "to": "F1", "weight": 1},
           {"from": "W1", "to": "F2", "weight": -1},
           {"from": "F1", "to": "D1", "weight": 1}, {"from": "F1", "to": "D2", "weight": 1},
           {"from": "F2", "to": "D2", "weight": -1}]}
)";

inline const std::string kReport =
    "part,time_min,dimension,nominal_mm,measured_mm,lower_tol_mm,upper_tol_mm\n"
    "1,10,D1,42,42.010,-0.02,0.02\n"
    "1,10,D2,18.5,18.49,-0.05,0.03\n"
    "2,20,D1,42,42.004,-0.02,0.02\n"
    "2,20,D2,18.5,18.5,-0.05,0.03\n";

inline const std::string kDmis =
    "DMISMN/'bad input test',05.0\n"
    "UNITS/MM,ANGDEG\n"
    "F(POS_D1)=FEAT/PLANE,CART,10,20,42.000,0,0,1\n"
    "FA(POS_D1)=FEAT/PLANE,CART,10.004,19.998,42.013,0,0,1\n"
    "T(D2)=TOL/DISTB,NOMINL,18.5,-0.05,0.03,ZAXIS\n"
    "TA(D2)=TOL/DISTB,-0.021,INTOL\n"
    "ENDFIL\n";

// A PC-DMIS standard text report against kModel (layout from the PC-DMIS help, "Dimension Command
// Format"): POS_D1 on the model's axis Z, D2 the diameter row.
inline const std::string kPcDmis =
    "PART NAME  : BAD INPUT TEST\n"
    "DIM POS_D1= LOCATION OF PLANE PLN1  UNITS=MM ,$\n"
    "GRAPH=OFF  TEXT=OFF  MULT=10.00  OUTPUT=BOTH  HALF ANGLE=NO\n"
    "AX    NOMINAL       +TOL       -TOL       MEAS        DEV     OUTTOL\n"
    "Z      42.000      0.020      0.020     42.013      0.013      0.000 ----#----\n"
    "END OF DIMENSION POS_D1\n"
    "DIM D2= LOCATION OF CIRCLE CIR2  UNITS=MM ,$\n"
    "GRAPH=OFF  TEXT=OFF  MULT=10.00  OUTPUT=BOTH  HALF ANGLE=NO\n"
    "AX    NOMINAL       +TOL       -TOL       MEAS        DEV     OUTTOL\n"
    "D      18.500      0.030      0.050     18.479     -0.021      0.000 --#------\n"
    "END OF DIMENSION D2\n";

// An OGP summary report of two runs (the layout of OGP's "Nominal Actual Tolerances Deviation"
// report; locations print sign(nominal) * (actual - nominal)).
inline const std::string kOgpSummary =
    "Machine Serial Number: 0000000           Page:    1\n"
    "Routine Name           Run #       Date & Time\n"
    "bracket.RTN                1 Mon Jan 05 08:00:00 2015\n"
    "Feature      Unit   Nominal     Actual      Tolerances      Deviation   Exceeded\n"
    "Step 1 - Ball A\n"
    "Y Location     -00050.000 -00050.003        +00000.003\n"
    "Machine Serial Number: 0000000           Page:    1\n"
    "Routine Name           Run #       Date & Time\n"
    "bracket.RTN                2 Mon Jan 05 09:00:00 2015\n"
    "Feature      Unit   Nominal     Actual      Tolerances      Deviation   Exceeded\n"
    "Step 1 - Ball A\n"
    "Y Location     -00050.000 -00049.998        -00000.002\n";

/// A DFQ file written from the AQDEF field list: two characteristics, three measured parts.
inline const std::string kDfq =
    "K0100 2\r\nK2001/1 1\r\nK2110/1 12.49\r\nK2111/1 12.51\r\nK2101/1 12.5\r\nK2001/2 2\r\n"
    "K0001/1 12.501\r\nK0001/2 0.01\r\nK0001/1 12.498\r\nK0001/2 0.02\r\nK0001/1 12.502\r\n"
    "K0001/2 0.015\r\nK0001/1 12.5\r\nK0001/2 0.012\r\n";
/// A Calypso _chr table for kModel's D1 (label POS_D1) and D2.
inline const std::string kChr =
    "planid\tpartnb\tid\tactual\tnominal\tdeviation\tuppertol\tlowertol\r\n"
    "P\t1\tPOS_D1\t42,0120\t42,0000\t0,0120\t0,0200\t-0,0200\r\n"
    "P\t1\tD2\t18,5100\t18,5000\t0,0100\t0,0300\t-0,0500\r\n";
/// A Calypso _fet table of three points.
inline const std::string kFet =
    "planid\tpartnb\tid\tx\ty\tz\tx_nom\ty_nom\tz_nom\r\n"
    "B\t1\tP1\t10,0100\t0\t0\t10\t0\t0\r\n"
    "B\t1\tP2\t0\t10,0100\t0\t0\t10\t0\r\n"
    "B\t1\tP3\t0\t0\t10,0100\t0\t0\t10\r\n";

/// A QIF 3 Results file written from the schema's element names: three probed points on three faces,
/// measured on two parts (lines 18-20 and 23-25).
inline const std::string kQif =
    "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
    "<QIFDocument xmlns=\"http://qifstandards.org/xsd/qif3\" versionQIF=\"3.0.0\">\n"
    "<FileUnits><PrimaryUnits><LinearUnit><SIUnitName>millimeter</SIUnitName><UnitName>mm</UnitName>"
    "</LinearUnit></PrimaryUnits></FileUnits>\n"
    "<Features>\n"
    "<FeatureNominals n=\"3\">\n"
    "<PointFeatureNominal id=\"1\"><Location>10 0 0</Location><Normal>1 0 0</Normal></PointFeatureNominal>\n"
    "<PointFeatureNominal id=\"2\"><Location>0 10 0</Location><Normal>0 1 0</Normal></PointFeatureNominal>\n"
    "<PointFeatureNominal id=\"3\"><Location>0 0 10</Location><Normal>0 0 1</Normal></PointFeatureNominal>\n"
    "</FeatureNominals>\n"
    "<FeatureItems n=\"3\">\n"
    "<PointFeatureItem id=\"4\"><FeatureNominalId>1</FeatureNominalId><FeatureName>P1</FeatureName>"
    "</PointFeatureItem>\n"
    "<PointFeatureItem id=\"5\"><FeatureNominalId>2</FeatureNominalId><FeatureName>P2</FeatureName>"
    "</PointFeatureItem>\n"
    "<PointFeatureItem id=\"6\"><FeatureNominalId>3</FeatureNominalId><FeatureName>P3</FeatureName>"
    "</PointFeatureItem>\n"
    "</FeatureItems>\n"
    "</Features>\n"
    "<Results><MeasurementResultsSet>\n"
    "<MeasurementResults id=\"7\"><MeasuredFeatures>\n"
    "<PointFeatureMeasurement id=\"8\"><FeatureItemId>4</FeatureItemId><Location>10.01 0 0</Location>"
    "</PointFeatureMeasurement>\n"
    "<PointFeatureMeasurement id=\"9\"><FeatureItemId>5</FeatureItemId><Location>0 10.01 0</Location>"
    "</PointFeatureMeasurement>\n"
    "<PointFeatureMeasurement id=\"10\"><FeatureItemId>6</FeatureItemId><Location>0 0 10.01</Location>"
    "</PointFeatureMeasurement>\n"
    "</MeasuredFeatures></MeasurementResults>\n"
    "<MeasurementResults id=\"11\"><MeasuredFeatures>\n"
    "<PointFeatureMeasurement id=\"12\"><FeatureItemId>4</FeatureItemId><Location>10.02 0 0</Location>"
    "</PointFeatureMeasurement>\n"
    "<PointFeatureMeasurement id=\"13\"><FeatureItemId>5</FeatureItemId><Location>0 10.02 0</Location>"
    "</PointFeatureMeasurement>\n"
    "<PointFeatureMeasurement id=\"14\"><FeatureItemId>6</FeatureItemId><Location>0 0 10.02</Location>"
    "</PointFeatureMeasurement>\n"
    "</MeasuredFeatures></MeasurementResults>\n"
    "</MeasurementResultsSet></Results>\n"
    "</QIFDocument>\n";

/// An SHDR adapter log (MTConnect): a temperature, a displacement and a condition, every 10 s.
inline const std::string kShdr =
    "* shdrVersion: 2.0\n"
    "2024-03-01T08:00:00.0000000Z|T1|20.0|disp|0.0\n"
    "2024-03-01T08:00:00.0000000Z|system|NORMAL||||\n"
    "2024-03-01T08:00:10.0000000Z|T1|20.5|disp|0.3\n"
    "2024-03-01T08:00:20.0000000Z|T1|21.1|disp|0.5\n"
    "2024-03-01T08:00:30.0000000Z|T1|21.4|disp|0.8\n"
    "2024-03-01T08:00:40.0000000Z|T1|22.0|disp|1.1\n"
    "2024-03-01T08:00:50.0000000Z|T1|22.3|disp|1.2\n";

inline std::string circle() {
  // 16 points CCW then 16 CW on a 50 mm circle with a small, smooth deviation.
  std::string s = "x_cmd_mm,y_cmd_mm,x_meas_mm,y_meas_mm\n";
  const double pi = 3.14159265358979323846;
  for (int loop = 0; loop < 2; ++loop) {
    for (int i = 0; i < 16; ++i) {
      const double a = (loop == 0 ? 1.0 : -1.0) * 2.0 * pi * i / 16.0;
      const double x = 50.0 * std::cos(a), y = 50.0 * std::sin(a);
      s += std::to_string(x) + "," + std::to_string(y) + "," + std::to_string(x + 0.004 + 1e-4 * y) + "," +
           std::to_string(y - 0.003) + "\n";
    }
  }
  return s;
}

/// circle() with the columns of the plane (u, v) ("y", "z" for YZ; "z", "x" for ZX).
inline std::string planeCircle(const std::string& u, const std::string& v) {
  std::string s = circle();
  s.replace(0, s.find('\n'), u + "_cmd_mm," + v + "_cmd_mm," + u + "_meas_mm," + v + "_meas_mm");
  return s;
}

/// A plane test whose measured points are all (1, 2).
inline std::string frozenPlane(const std::string& u, const std::string& v) {
  std::string s = u + "_cmd_mm," + v + "_cmd_mm," + u + "_meas_mm," + v + "_meas_mm\n";
  for (int i = 0; i < 16; ++i) {
    const double a = 2.0 * 3.14159265358979323846 * i / 16.0;
    s += std::to_string(50.0 * std::cos(a)) + "," + std::to_string(50.0 * std::sin(a)) + ",1,2\n";
  }
  return s;
}

/// An edge along an axis (position_mm,deviation_mm), tilted by 1e-4 with a little scatter.
inline const std::string kEdge =
    "position_mm,deviation_mm\n-100,-0.0101\n-60,-0.0059\n-20,-0.0021\n20,0.0019\n60,0.0061\n100,0.0099\n";

inline const std::string kErrors =
    R"({"origin_mm": [0.004, -0.003], "x_axis_angle_deg": 0.01, "y_axis_angle_deg": -0.02, "rmse_mm": 0.0005})"
    "\n";
inline const std::string kNominal = "x_mm,y_mm\n0,0\n10,0\n10,10\n0,10\n";

inline const std::string kBores =
    "part,diameter_mm\n1,100.001\n2,100.003\n3,99.998\n4,100.002\n5,100.000\n"
    "6,100.004\n7,99.999\n8,100.001\n9,100.002\n10,100.000\n";

inline const std::string kProject = R"({
  "format": "metrofit-project",
  "version": 1,
  "name": "bad input test",
  "datasets": [
    {"id": "log", "kind": "thermal_log", "path": "log.csv"},
    {"id": "points", "kind": "probe_points", "path": "pts.csv"}
  ],
  "studies": {"matching": {"dataset": "points", "tolerance_mm": 0.05,
                           "machine": {"topology": "xfyzba", "rotary_travel_deg": [[-120, 120], [-360, 360]]}}}
}
)";

inline std::string thermalModelJson() {
  return R"({"format": "metrofit-thermal-model", "version": 1, "model": "gmc", "target": "disp_z_um",
  "inputs": ["T1"], "time_unit_min": 1.0, "grey": {"b": [0.2], "b1": 0.5, "u": 0.0}})";
}

inline std::string oneMegabyteLine() {
  return "0," + std::string(1 << 20, '7') + ",20,20,0\n";
}

/// An STL part for `match --cad`: the square [0, 10]^2 at z = 0 as two facets, ASCII (the first vertex
/// lines are "vertex 0 0 0", "vertex 10 0 0", "vertex 0 10 0" on lines 4-6) and binary (184 bytes).
inline const std::string kStlAscii =
    "solid plate\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 10 0 0\nvertex 0 10 0\nendloop\n"
    "endfacet\nfacet normal 0 0 1\nouter loop\nvertex 10 0 0\nvertex 10 10 0\nvertex 0 10 0\nendloop\n"
    "endfacet\nendsolid plate\n";
inline std::string stlBinary() {
  std::string s = "binary plate";
  s.resize(80, ' ');
  auto u32 = [&](std::uint32_t v) {
    for (int k = 0; k < 4; ++k) s += static_cast<char>((v >> (8 * k)) & 0xFF);
  };
  auto f32 = [&](float f) {
    std::uint32_t u = 0;
    std::memcpy(&u, &f, 4);
    u32(u);
  };
  u32(2);
  const float facets[2][12] = {{0, 0, 1, 0, 0, 0, 10, 0, 0, 0, 10, 0},
                               {0, 0, 1, 10, 0, 0, 10, 10, 0, 0, 10, 0}};
  for (const auto& f : facets) {
    for (float v : f) f32(v);
    s += std::string(2, '\0');
  }
  return s;
}
inline const std::string kStlBinary = stlBinary();
/// Measured points for `match --cad` (all near the plate).
inline const std::string kMeasured =
    "id,px,py,pz\nA,1,1,0.01\nB,9,1,0.02\nC,1,9,0\nD,9,9,-0.01\nE,5,5,0.01\nF,3,7,0\nG,7,3,0.01\n";

inline std::vector<Case> cases() {
  const std::string matchCad = "match --cad part.stl --data m.csv --out out.json";
  const std::string fit = "thermal fit --data log.csv --target disp_z_um --inputs T1,T2 --out out.json";
  const std::string match = "match --data pts.csv --out out.json";
  const std::string setup = "setup --model m.json --data r.csv --out out.json";
  const std::string identify = "kinematic identify --data c.csv --out out.json";
  const std::string compensate = "kinematic compensate --errors e.json --path n.csv --out cmd.csv";
  const std::string spc = "spc --data b.csv --column diameter_mm --subgroup 5 --out out.json";
  const std::string report = "report --project p.metrofit --out r.pdf";
  const std::vector<std::string> json{"out.json"};
  const std::string constLog =
      "time_min,T1,T2,T_amb,disp_z_um\n0,20,20,20,0\n1,20,20,20,-1\n2,20,20,20,-2\n3,20,20,20,-3\n"
      "4,20,20,20,-4\n5,20,20,20,-5\n";

  std::vector<Case> c = {
      // ---- thermal log (CSV) -------------------------------------------------------------------
      {"TL01",
       "thermal log",
       "empty file (0 bytes)",
       fit,
       {{"log.csv", ""}},
       {"log.csv: ", "the file is empty"},
       json},
      {"TL02",
       "thermal log",
       "header row only",
       fit,
       {{"log.csv", "time_min,T1,T2,T_amb,disp_z_um\n"}},
       {"log.csv", "has 0 data rows"},
       json,
       true},
      {"TL03",
       "thermal log",
       "no time column (t instead of time_min)",
       fit,
       {{"log.csv", replaced(kLog, "time_min", "t")}},
       {"log.csv", "field 'time_s|time_min|time_h'"},
       json},
      {"TL04",
       "thermal log",
       "--target names a column the log does not have",
       "thermal fit --data log.csv --target disp_x_um --inputs T1 --out out.json",
       {{"log.csv", kLog}},
       {"log.csv", "field 'disp_x_um'", "no such column"},
       json},
      {"TL05",
       "thermal log",
       "text in a number (T1 = abc)",
       fit,
       {{"log.csv", replaced(kLog, "22.5,", "abc,")}},
       {"log.csv:4:2", "field 'T1'", "'abc' is not a number"},
       json,
       true},
      {"TL06",
       "thermal log",
       "NaN in a sensor column",
       fit,
       {{"log.csv", replaced(kLog, "20.5,", "NaN,")}},
       {"log.csv:3:3", "field 'T2'", "finite"},
       json},
      {"TL07",
       "thermal log",
       "inf in the target column",
       fit,
       {{"log.csv", replaced(kLog, "-5.0", "inf")}},
       {"log.csv:6:5", "field 'disp_z_um'", "finite"},
       json},
      {"TL08",
       "thermal log",
       "ragged row (4 fields, header has 5)",
       fit,
       {{"log.csv", replaced(kLog, "2,22.5,21.0,20.1,-2.5", "2,22.5,21.0,-2.5")}},
       {"log.csv:4", "row has 4 fields"},
       json},
      {"TL09",
       "thermal log",
       "UTF-16 LE with BOM",
       fit,
       {{"log.csv", utf16le(kLog)}},
       {"log.csv:1", "UTF-16"},
       json,
       true},
      {"TL10",
       "thermal log",
       "binary file (PNG bytes)",
       fit,
       {{"log.csv", binary()}},
       {"log.csv:1:1", "binary"},
       json},
      {"TL11",
       "thermal log",
       "a 1 MB line (one 1 MiB field)",
       fit,
       {{"log.csv", "time_min,T1,T2,T_amb,disp_z_um\n" + oneMegabyteLine()}},
       {"log.csv:2:2", "KiB"},
       json},
      {"TL12",
       "thermal log",
       "semicolon separated (European Excel) with one decimal point among decimal commas",
       fit,
       {{"log.csv",
         "time_min;T1;T2;T_amb;disp_z_um\n0;20,0;20,0;20,0;0,0\n1;20,5;20.5;20,0;0,5\n"
         "2;21,0;21,0;20,0;1,0\n3;21,5;21,5;20,0;1,5\n"}},
       {"log.csv:3:3", "decimal separator is ','"},
       json},
      {"TL13",
       "thermal log",
       "non-increasing time (5 after 5)",
       fit,
       {{"log.csv", replaced(kLog, "6,26.5", "5,26.5")}},
       {"log.csv:8", "time_min"},
       json,
       true},
      {"TL14",
       "thermal log",
       "decimal comma in a quoted field (\"20,5\")",
       fit,
       {{"log.csv", replaced(kLog, "20.5,", "\"20,5\",")}},
       {"log.csv:3:3", "decimal point"},
       json},
      {"TL15",
       "thermal log",
       "duplicate column name T1",
       fit,
       {{"log.csv", replaced(kLog, "T1,T2", "T1,T1")}},
       {"log.csv:1:3", "duplicate column name 'T1'"},
       json},
      {"TL16",
       "thermal log",
       "unterminated quote",
       fit,
       {{"log.csv", replaced(kLog, "3,24.0", "3,\"24.0")}},
       {"log.csv:5", "unterminated"},
       json},
      {"TL17",
       "thermal log",
       "Latin-1 byte in the header (invalid UTF-8)",
       fit,
       {{"log.csv", replaced(kLog, "T_amb", "T_amb\xB0")}},
       {"log.csv:1", "UTF-8"},
       json},
      {"TL18",
       "thermal log",
       "constant inputs (T1 and T2 never change)",
       fit,
       {{"log.csv", constLog}},
       {"log.csv", "field 'T1'", "constant"},
       json,
       true},
      {"TL19",
       "thermal log",
       "constant target in thermal hysteresis",
       "thermal hysteresis --data log.csv --target disp_z_um --inputs T1 --out out.json",
       {{"log.csv", "time_min,T1,disp_z_um\n0,20,1\n1,21,1\n2,22,1\n3,23,1\n4,22,1\n5,21,1\n6,20.5,1\n"}},
       {"log.csv", "field 'disp_z_um'", "constant"},
       json},
      {"TL20",
       "thermal log",
       "thermal modular: second training log lacks an input column",
       "thermal modular --train a.csv --train b.csv --test c.csv --target disp_z_um --inputs T1,T2 --out "
       "out.json",
       {{"a.csv", kLog}, {"b.csv", replaced(kLog, "T1,T2", "T1,TX")}, {"c.csv", kLog}},
       {"b.csv", "field 'T2'", "no such column"},
       json},
      {"TL21",
       "thermal log",
       "diagnose thermal: NaN in an input",
       "diagnose thermal --data log.csv --target disp_z_um --inputs T1,T2 --out out.json",
       {{"log.csv", replaced(kLog, "20.5,", "nan,")}},
       {"log.csv:3:3", "field 'T2'", "finite"},
       json},
      {"TL22",
       "thermal log",
       "thermal predict: log lacks the model's input",
       "thermal predict --model-file model.json --data log.csv --out out.csv",
       {{"model.json", thermalModelJson()}, {"log.csv", replaced(kLog, "T1,", "TX,")}},
       {"log.csv", "field 'T1'"},
       {"out.csv"}},
      // ---- thermal model (JSON) ----------------------------------------------------------------
      {"TM01",
       "thermal model JSON",
       "syntax error (missing comma)",
       "thermal predict --model-file model.json --data log.csv --out out.csv",
       {{"model.json", "{\"format\": \"metrofit-thermal-model\"\n \"version\": 1}\n"}, {"log.csv", kLog}},
       {"model.json:2:", "invalid JSON"},
       {"out.csv"},
       true},
      {"TM02",
       "thermal model JSON",
       "not a thermal model (format field)",
       "thermal predict --model-file model.json --data log.csv --out out.csv",
       {{"model.json", "{\"format\": \"something-else\", \"version\": 1}\n"}, {"log.csv", kLog}},
       {"model.json", "field 'format'"},
       {"out.csv"}},
      {"TM03",
       "thermal model JSON",
       "thermal export: a grey model (GMC(1,N)) as a SINUMERIK form",
       "thermal export --model model.json --format siemens --out comp.ini",
       {{"model.json", thermalModelJson()}},
       {"model.json", "field 'model'", "cannot be exported as siemens"},
       {"comp.ini"},
       true},
      {"TM04",
       "thermal model JSON",
       "thermal export: a model without its regression terms",
       "thermal export --model model.json --format st --out fb.st",
       {{"model.json", replaced(thermalModelJson(), "\"model\": \"gmc\"", "\"model\": \"lag\"")}},
       {"model.json", "field 'regression'"},
       {"fb.st"}},
      // ---- probe points (CSV) -------------------------------------------------------------------
      {"PP01",
       "probe points",
       "zero normal",
       match,
       {{"pts.csv", replaced(kProbe, "0,0,1,0.008", "0,0,0,0.008")}},
       {"pts.csv:4", "normal"},
       json,
       true},
      {"PP02",
       "probe points",
       "non-unit normal (0,0,2)",
       match,
       {{"pts.csv", replaced(kProbe, "0,0,1,100.012", "0,0,2,100.012")}},
       {"pts.csv:3", "normal"},
       json},
      {"PP03",
       "probe points",
       "duplicate point id",
       match,
       {{"pts.csv", replaced(kProbe, "P5,", "P2,")}},
       {"pts.csv:6", "P2"},
       json},
      {"PP04",
       "probe points",
       "missing column pz",
       match,
       {{"pts.csv", "id,surface,qx,qy,qz,nx,ny,nz,px,py\nP1,top,0,0,60,0,0,1,0,0\n"}},
       {"pts.csv", "'pz'"},
       json},
      {"PP05",
       "probe points",
       "unknown columns only (a,b,c)",
       match,
       {{"pts.csv", "a,b,c\n1,2,3\n4,5,6\n"}},
       {"pts.csv", "field 'id'"},
       json,
       true},
      {"PP06",
       "probe points",
       "NaN in a measured coordinate",
       match,
       {{"pts.csv", replaced(kProbe, "60.018", "NaN")}},
       {"pts.csv:3:11", "field 'pz'"},
       json},
      {"PP07",
       "probe points",
       "degenerate geometry: all nominal points coincide",
       match,
       {{"pts.csv",
         "id,surface,qx,qy,qz,px,py,pz\nP1,a,1,2,3,1.01,2,3\nP2,a,1,2,3,1,2.01,3\nP3,a,1,2,3,1,2,3.01\n"}},
       {"pts.csv", "coincide"},
       json},
      {"PP08",
       "probe points",
       "degenerate geometry: all nominal points collinear",
       match,
       {{"pts.csv",
         "id,surface,qx,qy,qz,px,py,pz\nP1,a,0,0,0,0.01,0,0\nP2,a,10,0,0,10,0.01,0\nP3,a,20,0,0,20,0,0.01\n"
         "P4,a,30,0,0,30.01,0,0\n"}},
       {"pts.csv", "collinear"},
       json,
       true},
      {"PP09",
       "probe points",
       "only 2 points",
       match,
       {{"pts.csv", kProbe.substr(0, kProbe.find("P3,"))}},
       {"pts.csv", "at least 3"},
       json},
      {"PP10",
       "probe points",
       "diagnose matching: zero normal",
       "diagnose matching --data pts.csv --out out.json",
       {{"pts.csv", replaced(kProbe, "0,0,1,0.008", "0,0,0,0.008")}},
       {"pts.csv:4", "normal"},
       json},
      {"PP11",
       "probe points",
       "match --reference names an unknown point",
       "match --data pts.csv --reference P1,P2,P9 --out out.json",
       {{"pts.csv", kProbe}},
       {"pts.csv", "field 'reference'", "P9"},
       json},
      // ---- controller files (setup --export, match --frame) ------------------------------------
      {"CF01",
       "HEIDENHAIN table",
       "setup --export heidenhain-table: the preset table has no row for W1",
       "setup --model m.json --data r.csv --export heidenhain-table --export-table PRESET.PR "
       "--export-out new.pr --out out.json",
       {{"m.json", kModel},
        {"r.csv", kReport},
        {"PRESET.PR", "BEGIN PRESET.PR MM\nNR      DOC      Z\n0       machine  +0\n[END]\n"}},
       {"PRESET.PR:2", "has no row NR 1", "'W1'"},
       {"out.json", "new.pr"}},
      {"CF02",
       "HEIDENHAIN table",
       "setup --export heidenhain-table: a DL cell with a decimal comma",
       "setup --model m.json --data r.csv --export heidenhain-table --export-table TOOL.T "
       "--export-out new.t --out out.json",
       {{"m.json", kModel},
        {"r.csv", kReport},
        {"TOOL.T", "BEGIN TOOL.T MM\nT       DL      R\n5       1,5     +1\n[END]\n"}},
       {"TOOL.T:3", "column DL", "'1,5' is not a number"},
       {"out.json", "new.t"}},
      {"CF03",
       "HEIDENHAIN table",
       "setup --export heidenhain-table: a CSV instead of the control's table",
       "setup --model m.json --data r.csv --export heidenhain-table --export-table TOOL.T "
       "--export-out new.t --out out.json",
       {{"m.json", kModel}, {"r.csv", kReport}, {"TOOL.T", "T,DL\n5,0\n"}},
       {"TOOL.T:1", "BEGIN <NAME>.<EXT>"},
       {"out.json", "new.t"}},
      {"CF04",
       "Fanuc program number",
       "setup --export fanuc --program-number 9001 (protected macro range)",
       "setup --model m.json --data r.csv --export fanuc --export-out o.nc --program-number 9001 --out "
       "out.json",
       {{"m.json", kModel}, {"r.csv", kReport}},
       {"field '--program-number'", "parameter 3202 bit 4 (NE9)"},
       {"out.json", "o.nc"}},
      {"CF05",
       "controller frame",
       "match --frame without --frame-out",
       "match --data pts.csv --frame fanuc --out out.json",
       {{"pts.csv", kProbe}},
       {"field '--frame'", "needs --frame-out FILE"},
       json},
      // ---- PC-DMIS hole table ------------------------------------------------------------------
      {"HT01",
       "PC-DMIS hole table",
       "required column Nom Y missing",
       "match --data holes.txt --out out.json",
       {{"holes.txt", replaced(kHoles, "     Nom Y", "     Nom Z")}},
       {"holes.txt:4", "Nom Y"},
       json},
      {"HT02",
       "PC-DMIS hole table",
       "Err X disagrees with Meas X - Nom X",
       "match --data holes.txt --out out.json",
       {{"holes.txt", replaced(kHoles, "-0.045", "-0.145")}},
       {"holes.txt:6", "Err X"},
       json,
       true},
      {"HT03",
       "PC-DMIS hole table",
       "text in a number",
       "match --data holes.txt --out out.json",
       {{"holes.txt", replaced(kHoles, "31.605", "31.6O5")}},
       {"holes.txt:6", "Meas X"},
       json},
      {"HT04",
       "PC-DMIS hole table",
       "negative diameter",
       "match --data holes.txt --out out.json",
       {{"holes.txt", replaced(kHoles, "3.270", "-3.270")}},
       {"holes.txt:7", "Meas D"},
       json},
      {"HT05",
       "PC-DMIS hole table",
       "row with a missing value",
       "match --data holes.txt --out out.json",
       {{"holes.txt", replaced(kHoles, "   0.007\n", "\n")}},
       {"holes.txt:8"},
       json},
      {"HT06",
       "PC-DMIS hole table",
       "UTF-16 LE with BOM",
       "match --data holes.txt --out out.json",
       {{"holes.txt", utf16le(kHoles)}},
       {"holes.txt:1", "UTF-16"},
       json},
      {"PP12",
       "probe points",
       "a 1 MB line",
       match,
       {{"pts.csv", kProbe + "P7,top," + std::string(1 << 20, '1') + ",0,60,0,0,1,0,0,60\n"}},
       {"pts.csv:8:3", "KiB"},
       json},
      {"PP13",
       "probe points",
       "--out names a folder (the result cannot be written)",
       "match --data pts.csv --out outdir",
       {{"pts.csv", kProbe}, {"outdir/keep.txt", "x\n"}},
       {"outdir: is a folder"},
       {}},
      // ---- setup model (JSON) ------------------------------------------------------------------
      {"SM01",
       "setup model JSON",
       "syntax error (missing comma)",
       setup,
       {{"m.json", replaced(kModel, "\"axis\": \"Z\",", "\"axis\": \"Z\"")}, {"r.csv", kReport}},
       {"m.json:2:", "invalid JSON"},
       json},
      {"SM02",
       "setup model JSON",
       "nested 100000 levels deep",
       setup,
       {{"m.json", deepJson(100000)}, {"r.csv", kReport}},
       {"m.json:1:65", "nested deeper"},
       json,
       true},
      {"SM03",
       "setup model JSON",
       "UTF-16 LE with BOM",
       setup,
       {{"m.json", utf16le(kModel)}, {"r.csv", kReport}},
       {"m.json:1", "UTF-16"},
       json},
      {"SM04",
       "setup model JSON",
       "empty file",
       setup,
       {{"m.json", ""}, {"r.csv", kReport}},
       {"m.json:1:1", "the file is empty"},
       json},
      {"SM05",
       "setup model JSON",
       "graph cycle (F1 -> F2 -> F1)",
       setup,
       {{"m.json",
         replaced(kModel, "{\"from\": \"W1\", \"to\": \"F2\", \"weight\": -1}",
                  "{\"from\": \"W1\", \"to\": \"F2\", \"weight\": -1}, {\"from\": \"F1\", \"to\": \"F2\", "
                  "\"weight\": 1}, {\"from\": \"F2\", \"to\": \"F1\", \"weight\": 1}")},
        {"r.csv", kReport}},
       {"m.json", "field 'arcs[", "cycle"},
       json,
       true},
      {"SM06",
       "setup model JSON",
       "arc to an unknown node F9",
       setup,
       {{"m.json", replaced(kModel, "\"T5\", \"to\": \"F1\"", "\"T5\", \"to\": \"F9\"")}, {"r.csv", kReport}},
       {"m.json", "field 'arcs[1].to'", "F9"},
       json},
      {"SM07",
       "setup model JSON",
       "reversed bounds [0.1, -0.1]",
       setup,
       {{"m.json", replaced(kModel, "[-0.1, 0.1]", "[0.1, -0.1]")}, {"r.csv", kReport}},
       {"m.json", "field 'bounds_mm'", "above upper bound"},
       json},
      {"SM08",
       "setup model JSON",
       "zero grid step",
       setup,
       {{"m.json", replaced(kModel, "0.001", "0")}, {"r.csv", kReport}},
       {"m.json", "field 'step_mm'"},
       json},
      {"SM09",
       "setup model JSON",
       "negative tolerance band (lower > upper)",
       setup,
       {{"m.json",
         replaced(kModel, "\"lower\": -0.02, \"upper\": 0.02", "\"lower\": 0.02, \"upper\": -0.02")},
        {"r.csv", kReport}},
       {"m.json", "field 'dimensions[0]"},
       json,
       true},
      {"SM10",
       "setup model JSON",
       "duplicate setup id W1",
       setup,
       {{"m.json",
         replaced(kModel, "{\"id\": \"T5\", \"kind\": \"tool\"}", "{\"id\": \"W1\", \"kind\": \"tool\"}")},
        {"r.csv", kReport}},
       {"m.json", "field 'setup[1].id'", "duplicate id 'W1'"},
       json},
      {"SM11",
       "setup model JSON",
       "top level is an array",
       setup,
       {{"m.json", "[1, 2, 3]\n"}, {"r.csv", kReport}},
       {"m.json", "field '"},
       json},
      {"SM12",
       "setup model JSON",
       "text where a number is expected (step_mm)",
       setup,
       {{"m.json", replaced(kModel, "\"step_mm\": 0.001", "\"step_mm\": \"fine\"")}, {"r.csv", kReport}},
       {"m.json", "field 'step_mm'", "expected a number"},
       json},
      {"SM13",
       "setup model JSON",
       "simulate setup: zero grid step",
       "simulate setup --model m.json --out out.csv",
       {{"m.json", replaced(kModel, "0.001", "0")}},
       {"m.json", "field 'step_mm'"},
       {"out.csv"},
       true},
      {"SM14",
       "setup model JSON",
       "diagnose setup: arc to an unknown node",
       "diagnose setup --model m.json --data r.csv --out out.json",
       {{"m.json", replaced(kModel, "\"T5\", \"to\": \"F1\"", "\"T5\", \"to\": \"F9\"")}, {"r.csv", kReport}},
       {"m.json", "field 'arcs[1].to'"},
       json},
      // ---- CMM report series (CSV) -------------------------------------------------------------
      {"CR01",
       "CMM report CSV",
       "unknown dimension D9",
       setup,
       {{"m.json", kModel}, {"r.csv", replaced(kReport, "2,20,D1", "2,20,D9")}},
       {"r.csv:4:3", "field 'dimension'", "D9"},
       json},
      {"CR02",
       "CMM report CSV",
       "missing column measured_mm",
       setup,
       {{"m.json", kModel}, {"r.csv", "part,time_min,dimension,nominal_mm\n1,10,D1,42\n"}},
       {"r.csv", "field 'measured_mm'"},
       json,
       true},
      {"CR03",
       "CMM report CSV",
       "duplicate (part, dimension) row",
       setup,
       {{"m.json", kModel}, {"r.csv", replaced(kReport, "2,20,D1", "1,20,D1")}},
       {"r.csv:4:3", "duplicate row"},
       json},
      {"CR04",
       "CMM report CSV",
       "NaN measured value",
       setup,
       {{"m.json", kModel}, {"r.csv", replaced(kReport, "42.010", "nan")}},
       {"r.csv:2:5", "field 'measured_mm'"},
       json},
      {"CR05",
       "CMM report CSV",
       "header only",
       setup,
       {{"m.json", kModel}, {"r.csv", kReport.substr(0, kReport.find('\n') + 1)}},
       {"r.csv", "has 0 data rows"},
       json},
      {"CR06",
       "CMM report CSV",
       "reversed tolerance limits",
       setup,
       {{"m.json", kModel}, {"r.csv", replaced(kReport, "42.010,-0.02,0.02", "42.010,0.02,-0.02")}},
       {"r.csv:2:6", "field 'lower_tol_mm'"},
       json,
       true},
      // ---- DMIS output ---------------------------------------------------------------------------
      {"DM01",
       "DMIS report",
       "polar coordinates",
       "setup --model m.json --data p.dmo --out out.json",
       {{"m.json", kModel}, {"p.dmo", replaced(kDmis, "FEAT/PLANE,CART,10.004", "FEAT/PLANE,POL,10.004")}},
       {"p.dmo:4", "field 'FA(POS_D1)'", "POL"},
       json},
      {"DM02",
       "DMIS report",
       "unknown length unit",
       "setup --model m.json --data p.dmo --out out.json",
       {{"m.json", kModel}, {"p.dmo", replaced(kDmis, "UNITS/MM", "UNITS/FURLONG")}},
       {"p.dmo:2", "field 'UNITS'"},
       json},
      {"DM03",
       "DMIS report",
       "file ends inside a continuation ('@')",
       "setup --model m.json --data p.dmo --out out.json",
       {{"m.json", kModel}, {"p.dmo", replaced(kDmis, "ENDFIL\n", "TA(D2)=TOL/DISTB,0.01,@\n")}},
       {"p.dmo:7", "'@'"},
       json,
       true},
      {"DM04",
       "DMIS report",
       "text in a number",
       "setup --model m.json --data p.dmo --out out.json",
       {{"m.json", kModel}, {"p.dmo", replaced(kDmis, "-0.021", "abc")}},
       {"p.dmo:6", "field 'TA(D2)'", "'abc'"},
       json},
      {"DM05",
       "DMIS report",
       "binary after the DMISMN line",
       "setup --model m.json --data p.dmo --out out.json",
       {{"m.json", kModel}, {"p.dmo", "DMISMN/'x',05.0\n" + binary()}},
       {"p.dmo:3:1", "binary"},
       json},
      // ---- CMM text reports ----------------------------------------------------------------------
      {"TR01",
       "PC-DMIS text report",
       "DEV is not MEAS - NOMINAL",
       "setup --model m.json --data r.txt --out out.json",
       {{"m.json", kModel}, {"r.txt", replaced(kPcDmis, "42.013      0.013", "42.013      0.031")}},
       {"r.txt:5", "MEAS - NOMINAL"},
       json},
      {"TR02",
       "PC-DMIS text report",
       "text in a number",
       "setup --model m.json --data r.txt --out out.json",
       {{"m.json", kModel}, {"r.txt", replaced(kPcDmis, "18.479", "18.4T9")}},
       {"r.txt:10", "'18.4T9' is not a number"},
       json},
      {"TR03",
       "PC-DMIS text report",
       "row with a missing value",
       "setup --model m.json --data r.txt --out out.json",
       {{"m.json", kModel}, {"r.txt", replaced(kPcDmis, "      0.000 --#------", " --#------")}},
       {"r.txt:10", "expected 6 values"},
       json},
      {"TR04",
       "OGP summary report",
       "printed deviation does not follow sign(nominal) * (actual - nominal)",
       "spc --data s.txt --column step1.y_location --subgroup 2 --out out.json",
       {{"s.txt", replaced(kOgpSummary, "+00000.003", "-00000.003")}},
       {"s.txt:6", "sign(nominal) * (actual - nominal)"},
       json},
      {"TR05",
       "OGP step report",
       "RTF document cut off (truncated)",
       "setup --model m.json --data r.txt --out out.json",
       {{"m.json", kModel},
        {"r.txt",
         "{\\rtf1\\ansi\\deff0{\\fonttbl{\\f0\\froman\\fprq1 Courier New;}}\r\n\\fs20 "
         "C:\\\\r\\\\bracket.RTN\r\n"
         " Step:  1     MM     Cart  Decimal Degree   Measure\r\nComment:\r\nPOS_D1\r\n"}},
       {"r.txt:6", "truncated"},
       json},
      // ---- circular test / measured path (CSV) --------------------------------------------------
      {"CT01",
       "circular test CSV",
       "missing column y_meas_mm",
       identify,
       {{"c.csv", replaced(circle(), "y_meas_mm", "y_mm")}},
       {"c.csv", "field 'y_meas_mm'"},
       json},
      {"CT02",
       "circular test CSV",
       "constant input: every point the same",
       identify,
       {{"c.csv", "x_cmd_mm,y_cmd_mm,x_meas_mm,y_meas_mm\n" +
                      [] {
                        std::string s;
                        for (int i = 0; i < 20; ++i) s += "10,10,10.001,9.999\n";
                        return s;
                      }()}},
       {"c.csv"},
       json,
       true},
      {"CT03",
       "circular test CSV",
       "NaN coordinate",
       identify,
       {{"c.csv", replaced(circle(), "\n50.000000,0.000000,", "\n50.000000,nan,")}},
       {"c.csv:2:2", "field 'y_cmd_mm'"},
       json},
      {"CT04",
       "circular test CSV",
       "binary file",
       identify,
       {{"c.csv", binary()}},
       {"c.csv:1:1", "binary"},
       json},
      {"CT05",
       "circular test CSV",
       "one row",
       identify,
       {{"c.csv", "x_cmd_mm,y_cmd_mm,x_meas_mm,y_meas_mm\n1,2,1,2\n"}},
       {"c.csv"},
       json},
      {"CT06",
       "circular test CSV",
       "diagnose kinematic: every point the same",
       "diagnose kinematic --data c.csv --out out.json",
       {{"c.csv", "x_cmd_mm,y_cmd_mm,x_meas_mm,y_meas_mm\n" +
                      [] {
                        std::string s;
                        for (int i = 0; i < 20; ++i) s += "10,10,10.001,9.999\n";
                        return s;
                      }()}},
       {"c.csv"},
       json},
      {"CT07",
       "circular test CSV",
       "radial-only (ballbar) test asked for the identification",
       identify,
       {{"c.csv", "angle_deg,deviation_um\n0,1.5\n90,2.0\n180,1.0\n270,0.5\n"}},
       {"c.csv: ", "radial-only circular test", "x_cmd_mm"},
       json},
      {"CT08",
       "circular test CSV",
       "radial-only test: direction neither ccw nor cw",
       "kinematic circular --data c.csv --out out.json",
       {{"c.csv", "angle_deg,deviation_um,direction\n0,1.5,ccw\n90,2.0,up\n180,1.0,ccw\n"}},
       {"c.csv:3:3", "field 'direction'", "not a direction"},
       json},
      {"CT09",
       "circular test CSV",
       "radial-only test: deviation given in um and in mm",
       "kinematic circular --data c.csv --out out.json",
       {{"c.csv", "angle_deg,deviation_um,deviation_mm\n0,1,0.001\n90,2,0.002\n180,1,0.001\n"}},
       {"c.csv", "field 'deviation_mm'", "not both"},
       json},
      // ---- kinematic positioning: ISO 230-2 positioning test (CSV or KEY=value) -----------------
      {"KP01",
       "positioning test CSV",
       "direction neither + nor -",
       "kinematic positioning --data p.csv --out out.json",
       {{"p.csv", "target_mm,direction,cycle,deviation_mm\n0,+,1,0.001\n0,up,2,0.002\n"}},
       {"p.csv:3:2", "field 'direction'", "not a direction"},
       json},
      {"KP02",
       "positioning test CSV",
       "cycle not a whole number",
       "kinematic positioning --data p.csv --out out.json",
       {{"p.csv", "target_mm,direction,cycle,deviation_mm\n0,+,1,0.001\n0,+,2.5,0.002\n"}},
       {"p.csv:3:3", "field 'cycle'", "not a cycle number"},
       json},
      {"KP03",
       "positioning test CSV",
       "the same target, direction and cycle twice",
       "kinematic positioning --data p.csv --out out.json",
       {{"p.csv", "target_mm,direction,cycle,measured_mm\n0,+,1,0.001\n0,+,1,0.002\n"}},
       {"p.csv:3:3", "given twice (first on line 2)"},
       json},
      {"KP04",
       "positioning test CSV",
       "a target approached once from one direction",
       "kinematic positioning --data p.csv --out out.json --compensation csv --out-table t.csv",
       {{"p.csv", "target_mm,direction,cycle,deviation_mm\n0,+,1,0\n0,+,2,0\n0,-,1,0\n"}},
       {"p.csv:2", "field 'direction'", "1 approach in the negative (-) direction"},
       {"out.json", "t.csv"}},
      {"KP05",
       "positioning test KEY=value",
       "a reading that is not a number",
       "kinematic positioning --data p.dat --out out.json",
       {{"p.dat", "UNIT=mm\nCYCLES=2\nPOSITIONS=1\nTGT_DATA[1]=10\nREF_DATA_FWD[1,1]=10.0O1\n"}},
       {"p.dat:5", "field 'REF_DATA_FWD[1,1]'", "not a number"},
       json},
      {"KP06",
       "positioning test KEY=value",
       "a reading missing for a cycle",
       "kinematic positioning --data p.dat --out out.json",
       {{"p.dat",
         "UNIT=mm\nCYCLES=2\nPOSITIONS=1\nTGT_DATA[1]=10\nREF_DATA_FWD[1,1]=10\nREF_DATA_FWD[1,2]=10\n"
         "REF_DATA_BWD[1,1]=10\n"}},
       {"p.dat:2", "field 'REF_DATA_BWD[1,2]'", "missing"},
       json},
      {"KP07",
       "positioning test KEY=value",
       "a line that is not KEY=value",
       "kinematic positioning --data p.dat --out out.json",
       {{"p.dat", "UNIT=mm\nCYCLES=2\nthis is not a key\n"}},
       {"p.dat:3", "not a KEY=value line"},
       json},
      // ---- kinematic compensate: errors JSON and nominal path ----------------------------------
      {"KE01",
       "actuator errors JSON",
       "missing field x_axis_angle_deg",
       compensate,
       {{"e.json", replaced(kErrors, "\"x_axis_angle_deg\": 0.01, ", "")}, {"n.csv", kNominal}},
       {"e.json", "field 'x_axis_angle_deg'", "missing"},
       {"cmd.csv"}},
      {"KE02",
       "actuator errors JSON",
       "orientation error of 90 deg",
       compensate,
       {{"e.json", replaced(kErrors, "-0.02", "90")}, {"n.csv", kNominal}},
       {"e.json", "field 'y_axis_angle_deg'"},
       {"cmd.csv"},
       true},
      {"NP01",
       "nominal path CSV",
       "ragged row (also asks for G-code)",
       "kinematic compensate --errors e.json --path n.csv --out cmd.csv --gcode g.nc",
       {{"e.json", kErrors}, {"n.csv", replaced(kNominal, "10,10\n", "10,10,7\n")}},
       {"n.csv:4", "row has 3"},
       {"cmd.csv", "g.nc"}},
      {"NP02",
       "nominal path CSV",
       "header only",
       compensate,
       {{"e.json", kErrors}, {"n.csv", "x_mm,y_mm\n"}},
       {"n.csv", "has 0 data rows"},
       {"cmd.csv"}},
      // ---- SPC feature series (CSV) --------------------------------------------------------------
      {"SP01",
       "SPC series CSV",
       "--column names a column the file does not have",
       "spc --data b.csv --column diam_mm --subgroup 5 --out out.json",
       {{"b.csv", kBores}},
       {"b.csv", "field 'diam_mm'"},
       json},
      {"SP02",
       "SPC series CSV",
       "text in a number",
       spc,
       {{"b.csv", replaced(kBores, "99.998", "99.99B")}},
       {"b.csv:4:2", "field 'diameter_mm'"},
       json,
       true},
      {"SP03",
       "SPC series CSV",
       "constant values (no variation)",
       spc,
       {{"b.csv",
         "part,diameter_mm\n1,100\n2,100\n3,100\n4,100\n5,100\n6,100\n7,100\n8,100\n9,100\n10,100\n"}},
       {"b.csv", "field 'diameter_mm'", "range of 0"},
       json},
      {"SP04",
       "SPC series CSV",
       "fewer rows than two subgroups",
       spc,
       {{"b.csv", "part,diameter_mm\n1,100.001\n2,100.002\n3,99.999\n"}},
       {"b.csv", "field 'diameter_mm'"},
       json},
      {"SP08",
       "SPC series CSV",
       "--dfq: a timestamp that is not a date-time",
       "spc --data b.csv --column diameter_mm --subgroup 2 --dfq b.dfq --out out.json",
       {{"b.csv",
         "timestamp,diameter_mm\n2024-05-03T10:15:00,100.001\n03/05/2024 10:16,100.003\n"
         "2024-05-03T10:17:00,99.998\n2024-05-03T10:18:00,100.002\n"}},
       {"b.csv:3:1", "field 'timestamp'", "not a date-time"},
       {"out.json", "b.dfq"}},
      {"SP05",
       "spc options",
       "reversed specification limits",
       "spc --data b.csv --column diameter_mm --subgroup 5 --lsl 100.01 --usl 99.99 --out out.json",
       {{"b.csv", kBores}},
       {"--lsl"},
       json,
       true},
      {"SP06",
       "spc options",
       "subgroup size 0",
       "spc --data b.csv --column diameter_mm --subgroup 0 --out out.json",
       {{"b.csv", kBores}},
       {"--subgroup"},
       json},
      {"SP07",
       "spc options",
       "negative coverage factor",
       "spc --data b.csv --column diameter_mm --subgroup 5 --coverage -2 --out out.json",
       {{"b.csv", kBores}},
       {"--coverage"},
       json},
      {"SP09",
       "spc options",
       "--base of 1 subgroup (no range to set limits from)",
       "spc --data b.csv --column diameter_mm --subgroup 5 --base 1 --out out.json",
       {{"b.csv", kBores}},
       {"field '--base'", "at least 2"},
       json},
      {"SP10",
       "spc options",
       "--base more subgroups than the series has",
       "spc --data b.csv --column diameter_mm --subgroup 5 --base 3 --out out.json",
       {{"b.csv", kBores}},
       {"b.csv", "field '--base'", "2 complete subgroups of 5"},
       json},
      // ---- Q-DAS DFQ (AQDEF) --------------------------------------------------------------------
      {"DQ01",
       "DFQ file",
       "a value that is not a number",
       "spc --data w.dfq --characteristic 1 --subgroup 2 --out out.json",
       {{"w.dfq", replaced(kDfq, "K0001/1 12.498", "K0001/1 12.49B")}},
       {"w.dfq:9", "field 'K0001/1'", "not a number"},
       json},
      {"DQ02",
       "DFQ file",
       "a field index above K0100",
       "spc --data w.dfq --characteristic 1 --subgroup 2 --out out.json",
       {{"w.dfq", replaced(kDfq, "K2101/1 12.5", "K2101/3 12.5")}},
       {"w.dfq:5", "field 'K2101/3'", "beyond K0100"},
       json},
      {"DQ03",
       "DFQ file",
       "a value line with more characteristics than K0100",
       "spc --data w.dfq --characteristic 1 --subgroup 2 --out out.json",
       {{"w.dfq", kDfq + "12.5\x0F"
                         "0\x14"
                         "0.01\x14"
                         "7\r\n"}},
       {"w.dfq:15", "value line has 3 characteristics"},
       json},
      {"DQ04",
       "DFQ file",
       "lower limit not below the upper limit",
       "spc --data w.dfq --characteristic 1 --subgroup 2 --out out.json",
       {{"w.dfq", replaced(kDfq, "K2110/1 12.49", "K2110/1 12.52")}},
       {"w.dfq:3", "field 'K2110/1'", "not below the upper limit"},
       json},
      {"DQ05",
       "DFQ file",
       "--characteristic names two characteristics",
       "spc --data w.dfq --characteristic 1 --subgroup 2 --out out.json",
       {{"w.dfq", replaced(kDfq, "K2001/2 2", "K2001/2 1")}},
       {"w.dfq", "field '--characteristic'", "ambiguous"},
       json},
      {"DQ06",
       "DFQ file",
       "--characteristic names none",
       "spc --data w.dfq --characteristic 3 --subgroup 2 --out out.json",
       {{"w.dfq", kDfq}},
       {"w.dfq", "field '--characteristic'", "no characteristic '3'"},
       json},
      {"DQ07",
       "DFQ file",
       "binary content after a DFQ start",
       "spc --data w.dfq --subgroup 2 --out out.json",
       {{"w.dfq", "K0100 1\r\n" + binary()}},
       {"w.dfq", "binary"},
       json},
      // ---- Zeiss Calypso tables -----------------------------------------------------------------
      {"CY01",
       "Calypso _chr table",
       "text in the actual",
       "setup --model m.json --data t_chr.txt --out out.json",
       {{"m.json", kModel}, {"t_chr.txt", replaced(kChr, "42,0120", "42,01x0")}},
       {"t_chr.txt:2:4", "field 'actual'", "not a number"},
       json},
      {"CY02",
       "Calypso _chr table",
       "a deviation that is not actual - nominal",
       "setup --model m.json --data t_chr.txt --out out.json",
       {{"m.json", kModel}, {"t_chr.txt", replaced(kChr, "0,0120", "0,0420")}},
       {"t_chr.txt:2:6", "field 'deviation'"},
       json},
      {"CY03",
       "Calypso _fet table",
       "several measured parts given to match",
       "match --data t_fet.txt --out out.json",
       {{"t_fet.txt", kFet + "B\t2\tP9\t1\t1\t1\t1\t1\t1\r\n"}},
       {"t_fet.txt:5:2", "field 'partnb'", "several measured parts"},
       json},
      {"CY04",
       "Calypso _fet table",
       "a missing coordinate",
       "match --data t_fet.txt --out out.json",
       {{"t_fet.txt", replaced(kFet, "10,0100", "")}},
       {"t_fet.txt:2:4", "field 'x'", "a number is missing"},
       json},
      // ---- QIF 3 Results files --------------------------------------------------------------------
      {"QF01",
       "QIF results file",
       "several measured parts given to match without --part",
       "match --data w.qif --out out.json",
       {{"w.qif", kQif}},
       {"w.qif", "field '--part'", "2 measured parts"},
       json},
      {"QF02",
       "QIF results file",
       "--part beyond the file's parts",
       "match --data w.qif --part 3 --out out.json",
       {{"w.qif", kQif}},
       {"w.qif", "field '--part'", "part 3 asked for"},
       json},
      {"QF03",
       "QIF results file",
       "a measurement of a feature item the file does not have",
       "match --data w.qif --part 1 --out out.json",
       {{"w.qif", replaced(kQif, "<FeatureItemId>5</FeatureItemId>", "<FeatureItemId>55</FeatureItemId>")}},
       {"w.qif:19", "55"},
       json},
      {"QF04",
       "QIF results file",
       "a coordinate that is not a number",
       "match --data w.qif --part 1 --out out.json",
       {{"w.qif", replaced(kQif, "10.01 0 0", "10.O1 0 0")}},
       {"w.qif:18", "10.O1"},
       json},
      {"QF05",
       "QIF results file",
       "a truncated file",
       "match --data w.qif --part 1 --out out.json",
       {{"w.qif", kQif.substr(0, kQif.find("<MeasurementResults id=\"11\">") + 20)}},
       {"w.qif:22"},
       json},
      // ---- MTConnect logs (SHDR, Streams) ---------------------------------------------------------
      {"MT01",
       "MTConnect SHDR log",
       "a timestamp that is not one",
       "thermal fit --data s.txt --target disp --inputs T1 --model linear --sample-interval 10s --out "
       "out.json",
       {{"s.txt", replaced(kShdr, "2024-03-01T08:00:30.0000000Z", "2024-03-01T08:0O:30.0000000Z")}},
       {"s.txt:6:1", "field 'timestamp'", "not an ISO 8601 time"},
       json},
      {"MT02",
       "MTConnect SHDR log",
       "a log without any numeric sample (only a condition and an event)",
       "thermal fit --data s.txt --target disp --inputs T1 --model linear --out out.json",
       {{"s.txt", "2024-03-01T08:00:00Z|system|NORMAL||||\n2024-03-01T08:00:10Z|mode|AUTOMATIC\n"}},
       {"s.txt", "no sample with numbers"},
       json},
      {"MT03",
       "MTConnect SHDR log",
       "an asset block that is not closed",
       "thermal fit --data s.txt --target disp --inputs T1 --model linear --out out.json",
       {{"s.txt",
         kShdr + "2024-03-01T08:01:00Z|@ASSET@|T.1|CuttingTool|--multiline--ABCD\n<CuttingTool/>\n"}},
       {"s.txt:9", "not closed", "--multiline--ABCD"},
       json},
      {"MT04",
       "MTConnect Streams document",
       "XML that is not well formed (a truncated document)",
       "thermal fit --data s.xml --target c1 --inputs c2 --model linear --out out.json",
       {{"s.xml",
         "<?xml version=\"1.0\"?>\n<MTConnectStreams xmlns=\"urn:mtconnect.org:MTConnectStreams:1.8\">\n"
         "<Streams><DeviceStream name=\"d\" uuid=\"1\"><ComponentStream component=\"Rotary\">\n"
         "<Samples><RotaryVelocity dataItemId=\"c1\" timestamp=\"2024-03-01T08:00:00Z\">15</RotaryVelocity>\n"
         "<RotaryVelocity dataItemId=\"c1\" timestamp=\"2024-03-01T08:00:10Z\">16\n"}},
       {"s.xml:"},
       json},
      {"MT05",
       "MTConnect SHDR log",
       "a project add of an MTConnect log with a CSV option",
       "project add P.metrofit mtconnect s.txt --delimiter ';'",
       {{"P.metrofit", "{\"format\": \"metrofit-project\", \"version\": 1}"}, {"s.txt", kShdr}},
       {"field 'KIND'", "not a CSV file"},
       {}},
      // ---- fit-element points (CSV) ---------------------------------------------------------------
      {"FE01",
       "element points CSV",
       "missing column z_mm",
       "fit-element --data p.csv --element sphere --out out.json",
       {{"p.csv", "x_mm,y_mm\n1,0\n0,1\n-1,0\n0,-1\n"}},
       {"p.csv", "'z_mm'"},
       json},
      {"FE02",
       "element points CSV",
       "too few points for the element (3 for a sphere)",
       "fit-element --data p.csv --element sphere --out out.json",
       {{"p.csv", "x_mm,y_mm,z_mm\n1,0,0\n0,1,0\n-1,0,0\n"}},
       {"p.csv", "sphere needs at least 4 points, got 3"},
       json},
      {"FE03",
       "element points CSV",
       "text in a number",
       "fit-element --data p.csv --element circle --out out.json",
       {{"p.csv", "x_mm,y_mm,z_mm\n1,0,0\n0,1,0\n-1,0,O\n0,-1,0\n"}},
       {"p.csv:4:3", "field 'z_mm'"},
       json,
       true},
      {"FE04",
       "fit-element options",
       "--radius for an element without a radius",
       "fit-element --data p.csv --element plane --radius 5 --out out.json",
       {{"p.csv", "x_mm,y_mm,z_mm\n1,0,0\n0,1,0\n-1,0,0\n0,-1,0\n"}},
       {"--radius"},
       json},
      {"FE05",
       "element points CSV",
       "collinear points for a circle",
       "fit-element --data p.csv --element circle --out out.json",
       {{"p.csv", "x_mm,y_mm,z_mm\n0,0,0\n1,1,1\n2,2,2\n3,3,3\n"}},
       {"p.csv", "collinear"},
       json},
      // ---- project file (.metrofit JSON) --------------------------------------------------------
      {"PJ01",
       "project file",
       "syntax error (trailing comma)",
       report,
       {{"p.metrofit", replaced(kProject, "\"version\": 1,", "\"version\": 1,,")}},
       {"p.metrofit:3:", "invalid JSON"},
       {"r.pdf"}},
      {"PJ02",
       "project file",
       "not a Metrofit project (format field)",
       report,
       {{"p.metrofit", replaced(kProject, "metrofit-project", "lathe-project")}},
       {"p.metrofit", "field 'format'"},
       {"r.pdf"},
       true},
      {"PJ03",
       "project file",
       "duplicate dataset id",
       report,
       {{"p.metrofit", replaced(kProject, "\"id\": \"points\"", "\"id\": \"log\"")}},
       {"p.metrofit", "field 'datasets[1].id'", "duplicate"},
       {"r.pdf"}},
      {"PJ04",
       "project file",
       "nested 5000 levels deep",
       report,
       {{"p.metrofit", "{\"format\": " + deepJson(5000) + "}"}},
       {"p.metrofit:1:", "nested deeper"},
       {"r.pdf"}},
      {"PJ05",
       "project file",
       "UTF-16 LE with BOM",
       report,
       {{"p.metrofit", utf16le(kProject)}},
       {"p.metrofit:1", "UTF-16"},
       {"r.pdf"},
       true},
      {"PJ06",
       "project file",
       "empty file",
       report,
       {{"p.metrofit", ""}},
       {"p.metrofit:1:1", "the file is empty"},
       {"r.pdf"}},
      {"PJ07",
       "project file",
       "binary file",
       report,
       {{"p.metrofit", binary()}},
       {"p.metrofit:", "binary"},
       {"r.pdf"}},
      {"PJ08",
       "project file / machine definition",
       "reversed rotary travel [[120, -120], ...]",
       report,
       {{"p.metrofit", replaced(kProject, "[-120, 120]", "[120, -120]")}},
       {"p.metrofit", "field 'studies.matching.machine.rotary_travel_deg[0]'"},
       {"r.pdf"},
       true},
      {"PJ09",
       "project file",
       "future format version 99",
       report,
       {{"p.metrofit", replaced(kProject, "\"version\": 1", "\"version\": 99")}},
       {"p.metrofit", "field 'version'"},
       {"r.pdf"}},
      {"PJ10",
       "project file",
       "missing file",
       "report --project nope.metrofit --out r.pdf",
       {},
       {"nope.metrofit"},
       {"r.pdf"}},
      {"PJ11",
       "project file",
       "unknown DMIS TA meaning of a dataset",
       report,
       {{"p.metrofit", replaced(kProject, "\"path\": \"log.csv\"}",
                                "\"path\": \"log.csv\", \"dmis\": {\"ta_meaning\": \"measured\"}}")}},
       {"p.metrofit", "field 'datasets[0].dmis.ta_meaning'", "dataset 'log'"},
       {"r.pdf"}},
      {"PJ12",
       "project file",
       "negative header line count of a dataset",
       report,
       {{"p.metrofit",
         replaced(kProject, "\"path\": \"log.csv\"}", "\"path\": \"log.csv\", \"header_lines\": -3}")}},
       {"p.metrofit", "field 'datasets[0].header_lines'", "dataset 'log'"},
       {"r.pdf"}},
      {"PJ13",
       "project file / diagnosis study",
       "train fraction 2 (studies.diagnosis.thermal.train_fraction)",
       report,
       {{"p.metrofit",
         replaced(kProject, "\"studies\": {",
                  "\"studies\": {\"diagnosis\": {\"thermal\": {\"dataset\": \"log\", \"target\": "
                  "\"disp_z_um\", \"inputs\": [\"T1\"], \"train_fraction\": 2}}, ")}},
       {"p.metrofit", "field 'studies.diagnosis.thermal.train_fraction'", "between 0.05 and 0.95"},
       {"r.pdf"}},
      {"PA01",
       "project add --embed",
       "the copy data/log.csv exists already",
       "project add e.metrofit thermal-log log.csv --embed",
       {{"e.metrofit", "{\"format\": \"metrofit-project\", \"version\": 1}"},
        {"log.csv", constLog},
        {"data/log.csv", "time_min,T1\n0,20\n"}},
       {"data/log.csv", "already exists"},
       {}},
      {"PA02",
       "project add --ta-meaning",
       "DMIS reading on a CSV file",
       "project add e.metrofit thermal-log log.csv --ta-meaning actual",
       {{"e.metrofit", "{\"format\": \"metrofit-project\", \"version\": 1}"}, {"log.csv", constLog}},
       {"log.csv", "field '--ta-meaning'", "not a DMIS file"},
       {}},
      {"PA03",
       "project add --skip-bad-rows",
       "a row that cannot be read, without --skip-bad-rows",
       "project add e.metrofit thermal-log log.csv",
       {{"e.metrofit", "{\"format\": \"metrofit-project\", \"version\": 1}"},
        {"log.csv", "time_min,T1,disp_z_um\n0,20,0\n1,n/a,1\n2,21,2\n3,21,3\n"}},
       {"log.csv:3:2", "field 'T1'", "not a number"},
       {}},
      // ---- machine definition (JSON, match --machine-def) ----------------------------------------
      {"MD01",
       "machine definition JSON",
       "syntax error",
       "match --data pts.csv --machine-def md.json --out out.json",
       {{"pts.csv", kProbe}, {"md.json", "{\"topology\": \"xfyzba\", \"LZ_mm\": -150.0.0}\n"}},
       {"md.json:1:", "invalid JSON"},
       json},
      {"MD02",
       "machine definition JSON",
       "reversed rotary travel",
       "match --data pts.csv --machine-def md.json --out out.json",
       {{"pts.csv", kProbe},
        {"md.json", "{\"topology\": \"xfyzba\", \"rotary_travel_deg\": [[90, -90], [-360, 360]]}\n"}},
       {"md.json", "field 'rotary_travel_deg[0]'", "min <= max"},
       json,
       true},
      {"MD03",
       "machine definition JSON",
       "unknown topology",
       "match --data pts.csv --machine-def md.json --out out.json",
       {{"pts.csv", kProbe}, {"md.json", "{\"topology\": \"hexapod\"}\n"}},
       {"md.json", "field 'topology'"},
       json},
      {"MD04",
       "machine definition JSON",
       "text where a number is expected",
       "match --data pts.csv --machine-def md.json --out out.json",
       {{"pts.csv", kProbe}, {"md.json", "{\"topology\": \"xfyzba\", \"LZ_mm\": \"long\"}\n"}},
       {"md.json", "field 'LZ_mm'"},
       json},
      // ---- options, files, subcommands -----------------------------------------------------------
      {"OP01", "command line", "unknown subcommand", "frobnicate --out out.json", {}, {"'frobnicate'"}, json},
      {"OP02",
       "command line",
       "unknown option",
       "match --data pts.csv --frobnicate 3 --out out.json",
       {{"pts.csv", kProbe}},
       {"--frobnicate"},
       json,
       true},
      {"OP03",
       "command line",
       "missing input file",
       "thermal fit --data nope.csv --target disp_z_um --inputs T1 --out out.json",
       {},
       {"nope.csv"},
       json},
      {"OP04",
       "command line",
       "negative tolerance",
       "match --data pts.csv --tolerance -0.05 --out out.json",
       {{"pts.csv", kProbe}},
       {"--tolerance: must be a positive number"},
       json},
      {"OP05",
       "command line",
       "unknown method",
       "setup --model m.json --data r.csv --method annealing --out out.json",
       {{"m.json", kModel}, {"r.csv", kReport}},
       {"--method", "annealing"},
       json},
      {"OP06",
       "command line",
       "negative budget",
       "setup --model m.json --data r.csv --method pso --budget -5 --out "
       "out.json",
       {{"m.json", kModel}, {"r.csv", kReport}},
       {"--budget"},
       json,
       true},
      {"OP07",
       "command line",
       "train fraction out of range",
       "thermal fit --data log.csv --target disp_z_um --inputs T1 --train-fraction -0.5 --out out.json",
       {{"log.csv", kLog}},
       {"--train-fraction"},
       json},
      {"OP08",
       "command line",
       "an input is also the target",
       "thermal fit --data log.csv --target disp_z_um --inputs T1,disp_z_um --out out.json",
       {{"log.csv", kLog}},
       {"--inputs", "disp_z_um"},
       json},
      {"OP09",
       "command line",
       "simulate circular with zero points",
       "simulate circular --points 0 --out out.csv",
       {},
       {"--points"},
       {"out.csv"}},
      {"OP10",
       "command line",
       "simulate bores with a negative part count",
       "simulate bores --parts -3 --out out.csv",
       {},
       {"--parts"},
       {"out.csv"},
       true},
      {"OP11",
       "command line",
       "simulate probe with an unknown shape",
       "simulate probe --shape cube --out out.csv",
       {},
       {"--shape"},
       {"out.csv"}},
      {"OP12",
       "command line",
       "thermal simulate with an unknown test",
       "thermal simulate --test q --out out.csv",
       {},
       {"--test"},
       {"out.csv"}},
      {"OP13",
       "command line",
       "simulate thermal into a folder that does not exist",
       "simulate thermal --out no/such/out.csv",
       {},
       {"no/such/out.csv"},
       {}},
      {"OP14",
       "command line",
       "demo --out-dir is a regular file",
       "demo --out-dir taken",
       {{"taken", "a file\n"}},
       {"taken"},
       {}},
      {"OP15",
       "command line",
       "diagnose matching with a negative tolerance",
       "diagnose matching --data pts.csv --tolerance -1 --out out.json",
       {{"pts.csv", kProbe}},
       {"--tolerance"},
       json},
      {"OP16",
       "command line",
       "match --lock with an unknown degree of freedom",
       "match --data pts.csv --lock rx,qq --out out.json",
       {{"pts.csv", kProbe}},
       {"--lock", "qq"},
       json},
      // ---- kinematic from-spc: the two edges (the paper's chain) ---------------------------------------
      {"KS01",
       "edge series",
       "Y edge without the deviation column",
       "kinematic from-spc --x-data ex.csv --y-data ey.csv --out out.json",
       {{"ex.csv", kEdge}, {"ey.csv", "position_mm,dev\n1,0\n2,0\n3,0\n"}},
       {"ey.csv", "deviation_mm", "missing column"},
       json},
      {"KS02",
       "edge series",
       "X edge with 2 points (no regression scatter)",
       "kinematic from-spc --x-data ex.csv --y-data ey.csv --out out.json",
       {{"ex.csv", "position_mm,deviation_mm\n1,0\n2,0.001\n"}, {"ey.csv", kEdge}},
       {"ex.csv", "at least 3"},
       json},
      {"KS03",
       "edge series",
       "a deviation that is not a number",
       "kinematic from-spc --x-data ex.csv --y-data ey.csv --out out.json",
       {{"ex.csv", "position_mm,deviation_mm\n1,0\n2,abc\n3,0\n"}, {"ey.csv", kEdge}},
       {"ex.csv:3", "deviation_mm"},
       json},
      // ---- kinematic identify3: three plane tests ----------------------------------------------------
      {"K301",
       "plane circular test",
       "YZ test with the XY columns",
       "kinematic identify3 --xy xy.csv --yz yz.csv --zx zx.csv --out out.json",
       {{"xy.csv", circle()}, {"yz.csv", circle()}, {"zx.csv", planeCircle("z", "x")}},
       {"yz.csv", "z_cmd_mm", "missing column"},
       json},
      {"K302",
       "command line",
       "identify3 without the ZX test",
       "kinematic identify3 --xy xy.csv --yz yz.csv --out out.json",
       {{"xy.csv", circle()}, {"yz.csv", planeCircle("y", "z")}},
       {"--zx", "required"},
       json},
      {"K303",
       "plane circular test",
       "ZX test whose measured points are all the same",
       "kinematic identify3 --xy xy.csv --yz yz.csv --zx zx.csv --out out.json",
       {{"xy.csv", circle()}, {"yz.csv", planeCircle("y", "z")}, {"zx.csv", frozenPlane("z", "x")}},
       {"zx.csv", "z_meas_mm,x_meas_mm", "(zx test)"},
       json},
      {"OP17",
       "command line",
       "kinematic without its subcommand",
       "kinematic --data c.csv",
       {{"c.csv", circle()}},
       {"kinematic: a subcommand is required", "identify, compensate"},
       {}},
      // ---- match --cad: STL part and measured points ---------------------------------------------------
      {"ST01",
       "STL part",
       "empty file",
       matchCad,
       {{"part.stl", ""}, {"m.csv", kMeasured}},
       {"part.stl", "empty"},
       json},
      {"ST02",
       "STL part",
       "binary file truncated (one byte short)",
       matchCad,
       {{"part.stl", kStlBinary.substr(0, kStlBinary.size() - 1)}, {"m.csv", kMeasured}},
       {"part.stl", "needs 184 bytes, the file has 183"},
       json},
      {"ST03",
       "STL part",
       "ASCII: a vertex coordinate with a decimal comma",
       matchCad,
       {{"part.stl", replaced(kStlAscii, "vertex 10 0 0", "vertex 10 0,5 0")}, {"m.csv", kMeasured}},
       {"part.stl:5", "'0,5' is not a number"},
       json},
      {"ST04",
       "STL part",
       "ASCII: a triangle of zero area (collinear vertices)",
       matchCad,
       {{"part.stl", replaced(kStlAscii, "vertex 0 10 0", "vertex 20 0 0")}, {"m.csv", kMeasured}},
       {"part.stl:2", "triangle 1", "zero area"},
       json},
      {"ST05",
       "STL part",
       "ASCII: NaN in a vertex",
       matchCad,
       {{"part.stl", replaced(kStlAscii, "vertex 0 10 0", "vertex 0 nan 0")}, {"m.csv", kMeasured}},
       {"part.stl:6", "not a finite number"},
       json},
      {"ST06",
       "STL part",
       "ASCII: a missing keyword",
       matchCad,
       {{"part.stl", replaced(kStlAscii, "endloop", "")}, {"m.csv", kMeasured}},
       {"part.stl:8", "expected 'endloop'"},
       json},
      {"ST07",
       "measured points",
       "no coordinate columns",
       matchCad,
       {{"part.stl", kStlAscii}, {"m.csv", "id,a,b,c\nA,1,2,3\n"}},
       {"m.csv:1", "px,py,pz, x_mm,y_mm,z_mm or x,y,z"},
       json},
      {"ST08",
       "measured points",
       "a plane part leaves x, y and rz free (no --lock)",
       matchCad,
       {{"part.stl", kStlAscii}, {"m.csv", kMeasured}},
       {"m.csv", "undetermined", "lock"},
       json},
      {"ST09",
       "command line",
       "match --cad with a point-pair method",
       matchCad + " --method sade",
       {{"part.stl", kStlAscii}, {"m.csv", kMeasured}},
       {"--method", "not sade"},
       json},
  };
  return c;
}

/// Test names and failure messages show the id, not the bytes of the struct.
inline void PrintTo(const Case& c, std::ostream* os) {
  *os << c.id;
}

// ---- running the CLI -----------------------------------------------------------------------------

struct CliResult {
  int code = -1;
  bool timedOut = false;
  double seconds = 0.0;
  std::string out, err;
};

inline constexpr int kTimeoutSeconds = 60;

/// Runs `metrofit-cli <args>` inside `dir` under timeout(1), capturing stdout and stderr.
inline CliResult runCli(const std::string& args, const std::filesystem::path& dir,
                        const std::filesystem::path& captureDir) {
  const std::string out = (captureDir / "stdout.txt").string(), err = (captureDir / "stderr.txt").string();
  const std::string cmd = "cd '" + dir.string() + "' && timeout -k 5 " + std::to_string(kTimeoutSeconds) +
                          " '" + (binDir() / "metrofit-cli").string() + "' " + args + " >'" + out + "' 2>'" +
                          err + "'";
  const auto start = std::chrono::steady_clock::now();
  const int status = std::system(cmd.c_str());
  CliResult r;
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.timedOut = r.code == 124 || r.code == 137;
  r.out = readText(out);
  r.err = readText(err);
  std::filesystem::remove(out);
  std::filesystem::remove(err);
  return r;
}

/// The message of a one-line error without the "metrofit-cli: " prefix and the line end.
inline std::string message(const std::string& err) {
  std::string m = err;
  if (!m.empty() && m.back() == '\n') m.pop_back();
  const std::string prefix = "metrofit-cli: ";
  if (m.rfind(prefix, 0) == 0) m = m.substr(prefix.size());
  return m;
}

}  // namespace metrofit::test::bad
