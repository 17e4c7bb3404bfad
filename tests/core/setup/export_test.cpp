// Export of setup corrections for controllers (core/setup/export.h): exact text of every format.
#include <gtest/gtest.h>

#include <map>
#include <regex>
#include <sstream>

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
O7001 (METROFIT SETUP CORRECTIONS)
(EXPORT TEST [FIXTURE A])
(G91: EACH VALUE IS ADDED TO THE OFFSET REGISTER, MM)
(+ MOVES THE WORK ZERO / TOOL TIP TOWARDS +Z)
(TOOL WEAR L11: OFFSET MEMORY C; ACTS AT THE NEXT G43 H)
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
  // O8000-O9999 are the builder's protected macro ranges (parameter 3202 NE8 / NE9).
  ExportOptions macro;
  macro.programNumber = 9001;
  try {
    (void)exportCorrections(exportModel(), kX, ControllerFormat::Fanuc, macro);
    FAIL() << "no error";
  } catch (const OptionsError& e) {
    EXPECT_NE(
        std::string(e.what()).find("O9001 is in O9000-O9999, which parameter 3202 bit 4 (NE9) = 1 protects"),
        std::string::npos)
        << e.what();
  }
  macro.programNumber = 8000;
  EXPECT_THROW((void)exportCorrections(exportModel(), kX, ControllerFormat::Fanuc, macro), OptionsError);
  macro.programNumber = 7999;
  EXPECT_NO_THROW((void)exportCorrections(exportModel(), kX, ControllerFormat::Fanuc, macro));
  const std::string g = exportCorrections(exportModel(), kX, ControllerFormat::Fanuc, o);
  EXPECT_NE(g.find("O0012 (METROFIT SETUP CORRECTIONS)\n"), std::string::npos) << g;
  EXPECT_NE(g.find("G10 L10 P5 R-0.012 (T5 LENGTH GEOMETRY)\n"), std::string::npos) << g;
}

TEST(SetupExport, Heidenhain) {
  EXPECT_EQ(exportCorrections(exportModel(), kX, ControllerFormat::Heidenhain),
            R"GOLD(; Metrofit setup corrections for HEIDENHAIN TNC: Export test (fixture A)
; Every value is an INCREMENT in mm: + moves the preset / tool tip towards +Z.
; PRESET.PR: enter each value in column Z of row NR with "Correct" (incremental).
; Activate the preset again and call the tool again (TOOL CALL) for the values to act.
; A file the control imports instead: --export heidenhain-table with the current table.
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
; Needs MD18600 $MN_FRAME_FINE_TRANS = 1 (fine offset of settable frames; else alarm "FRAME: fine offset not possible").
; Frame 7 (G505..G599) needs MD28080 $MC_MM_NUM_USER_FRAMES >= 8 (settable frames G500, G54..G57, G505..).
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

// ---- HEIDENHAIN table files --------------------------------------------------------------------
// The tables below are written here from the documented layout, not by our writer: a BEGIN line
// "BEGIN <NAME>.<EXT> MM [Version: ...]", a line of column names where each column starts at its name
// and runs to the next name, left-aligned cells, "[END]" (the public TOOL.T example and table reader
// of pyLSV2, github.com/drunsinn/pyLSV2 tests/test_files/tool.t and pyLSV2/table_reader.py; preset
// table columns NR/NO, DOC, X, Y, Z, SPA, SPB, SPC from the TNC7 user's manual, "Preset table").

const char* const kToolTable =
    "BEGIN TOOL.T MM Version: 'Update:110.24'\n"
    "T       NAME                            L           R           R2          DL        DR        DR2     "
    "  TL RT      DOC\n"
    "0       NULLTOOL                        +0          +0          +0          +0        +0        +0      "
    "  0          zero tool\n"
    "5       END_MILL_D10                    +85.125     +5          +0          +0        -0.01     +0      "
    "  0          rough\n"
    "23      BALL_D6                         +70.5       +3          +3          -0.005    +0        +0      "
    "  0          finish\n"
    "500     TOUCH_PROBE                     +200        +2          +0          +0        +0        +0      "
    "  0          probe\n"
    "[END]\n";

const char* const kPresetTable =
    "BEGIN PRESET.PR MM\n"
    "NR      DOC              X              Y              Z              SPA         SPB         SPC\n"
    "0       machine          +0             +0             +0             +0          +0          +0\n"
    "1       vise left        -250.1234      +112.5         -412.8765      +0          +0          +0\n"
    "7       fixture 7        +10            +20            -398.25        +0          +0          +0\n"
    "[END]\n";

std::vector<std::string> textLines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) out.push_back(l);
  return out;
}

/// Cells of a TNC table by the documented rule (as pyLSV2's reader: a name and the blanks after it).
std::map<std::string, std::string> cells(const std::string& header, const std::string& row) {
  std::map<std::string, std::string> out;
  const std::regex name("([A-Za-z0-9_:.\\-]+)\\s*");
  for (auto it = std::sregex_iterator(header.begin(), header.end(), name); it != std::sregex_iterator();
       ++it) {
    const auto start = static_cast<std::size_t>(it->position());
    const auto len = static_cast<std::size_t>(it->length());
    const std::string c = start < row.size() ? row.substr(start, len) : "";
    const auto b = c.find_first_not_of(' ');
    out[(*it)[1]] = b == std::string::npos ? "" : c.substr(b, c.find_last_not_of(' ') - b + 1);
  }
  return out;
}

TEST(SetupExport, HeidenhainToolTableGetsTheIncrementsInColumnDL) {
  const TableUpdate u = updateHeidenhainTable(exportModel(), kX, kToolTable, "TOOL.T");
  EXPECT_EQ(u.table, "TOOL.T");
  EXPECT_EQ(u.written, (std::vector<std::string>{"T5", "T23"}));
  EXPECT_EQ(u.notWritten, (std::vector<std::string>{"M1", "W1", "W7"}));
  const auto in = textLines(kToolTable), out = textLines(u.text);
  ASSERT_EQ(out.size(), in.size()) << u.text;
  // Line by line: BEGIN, the column names, T0 and T500 unchanged; T5 and T23 differ in DL alone.
  EXPECT_EQ(out[0], in[0]);
  EXPECT_EQ(out[1], in[1]);
  EXPECT_EQ(out[2], in[2]);
  EXPECT_EQ(out[5], in[5]);
  EXPECT_EQ(out[6], "[END]");
  for (std::size_t r : {3u, 4u}) {
    ASSERT_EQ(out[r].size(), in[r].size()) << out[r];
    auto a = cells(in[1], in[r]), b = cells(in[1], out[r]);
    const double before = std::stod(a.at("DL")), after = std::stod(b.at("DL"));
    EXPECT_NEAR(after - before, r == 3 ? -0.012 : 0.0, 1e-12) << out[r];
    a.erase("DL");
    b.erase("DL");
    EXPECT_EQ(a, b) << out[r];
  }
  EXPECT_EQ(out[3],
            "5       END_MILL_D10                    +85.125     +5          +0          -0.012    -0.01     "
            "+0        0          rough");
  EXPECT_EQ(out[4],
            "23      BALL_D6                         +70.5       +3          +3          -0.005    +0        "
            "+0        0          finish");
  // Geometry: column L, keeping the cell's own 3 decimals.
  ExportOptions o;
  o.toolOffset = ToolOffset::Geometry;
  const auto g = textLines(updateHeidenhainTable(exportModel(), kX, kToolTable, "TOOL.T", o).text);
  EXPECT_EQ(cells(in[1], g[3]).at("L"), "+85.113");
  EXPECT_EQ(cells(in[1], g[3]).at("DL"), "+0");
}

TEST(SetupExport, HeidenhainPresetTableGetsTheIncrementsInTheAxisColumn) {
  const TableUpdate u = updateHeidenhainTable(exportModel(), kX, kPresetTable, "preset.pr");
  EXPECT_EQ(u.table, "PRESET.PR");
  EXPECT_EQ(u.written, (std::vector<std::string>{"W1", "W7"}));
  EXPECT_EQ(u.notWritten, (std::vector<std::string>{"M1", "T5", "T23"}));
  const auto in = textLines(kPresetTable), out = textLines(u.text);
  ASSERT_EQ(out.size(), in.size());
  for (std::size_t r : {0u, 1u, 2u, 5u}) EXPECT_EQ(out[r], in[r]);
  // W1 (+0.004) in row NR 1, W7 (-0.010) in row NR 7, keeping the 4 decimals of the cell.
  EXPECT_EQ(
      out[3],
      "1       vise left        -250.1234      +112.5         -412.8725      +0          +0          +0");
  EXPECT_EQ(
      out[4],
      "7       fixture 7        +10            +20            -398.260       +0          +0          +0");
  EXPECT_NEAR(std::stod(cells(in[1], out[3]).at("Z")) - std::stod(cells(in[1], in[3]).at("Z")), 0.004, 1e-12);

  // CRLF files stay CRLF; an INCH table takes the increment in inches.
  std::string crlf = kPresetTable;
  for (std::size_t p = 0; (p = crlf.find('\n', p)) != std::string::npos; p += 2) crlf.insert(p, "\r");
  EXPECT_NE(updateHeidenhainTable(exportModel(), kX, crlf, "preset.pr")
                .text.find("-412.8725      +0          +0          +0\r\n"),
            std::string::npos);
  std::string inch = kPresetTable;
  inch.replace(0, 18, "BEGIN PRESET.PR INCH");
  const auto ii = textLines(updateHeidenhainTable(exportModel(), kX, inch, "preset.pr").text);
  EXPECT_NEAR(std::stod(cells(in[1], ii[3]).at("Z")) - (-412.8765), 0.004 / 25.4, 1e-4 / 2 + 1e-12);
}

TEST(SetupExport, HeidenhainTableErrors) {
  auto message = [](const std::string& table, const Model& m = exportModel()) {
    try {
      (void)updateHeidenhainTable(m, kX, table, "t.tab");
    } catch (const ValidationError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message("T  NAME\n"),
            "t.tab:1: is not a HEIDENHAIN table: the first line must start with 'BEGIN <NAME>.<EXT>'");
  EXPECT_EQ(message("BEGIN PALLET.P MM\nNR\n[END]\n"),
            "t.tab:1: 'PALLET.P' is neither a preset table (.PR) nor a tool table (.T)");
  EXPECT_EQ(message("BEGIN TOOL.T\nT  DL\n[END]\n"),
            "t.tab:1: the BEGIN line names no unit (MM or INCH) after 'TOOL.T'");
  EXPECT_EQ(message("BEGIN TOOL.T MM\nT       NAME    L\n5       X       +1\n[END]\n"),
            "t.tab:2: has no column DL");
  EXPECT_EQ(message("BEGIN TOOL.T MM\nT       DL\n5       +0\n"), "t.tab:3: has no '[END]' line");
  EXPECT_EQ(message("BEGIN TOOL.T MM\nT       DL      R\n5       +0      +1\n[END]\n"),
            "t.tab:2: has no row T 23 for setup[4] 'T23'");
  EXPECT_EQ(message("BEGIN TOOL.T MM\nT       DL      R\n5       abc     +1\n23      +0      +1\n[END]\n"),
            "t.tab:3: column DL: 'abc' is not a number");
  EXPECT_EQ(message("BEGIN TOOL.T MM\nT   DL  R\n5   +0  +1\n23  +0  +1\n[END]\n"),
            "t.tab:3: column DL: the new value -0.012 does not fit its 4 characters");
}

}  // namespace
}  // namespace metrofit::setup
