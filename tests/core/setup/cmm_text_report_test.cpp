// CMM text reports (core/io/cmm_text_report.h) and their reading as setup reports
// (core/setup/report.h, 3.).
//
// OGP: the REAL report files of ../shared/data/real/cmm-ogp-hps-svt (JeffersonLab/hps-align, GPL-3.0,
// read in place, never copied into the repository): the test skips when they are not there. The
// counts below were made by hand with grep on those files (commands in the comments), the sign
// rule and the totals are those of the folder's SOURCE.md, and every deviation the files print is
// compared with the one computed from their actual and nominal columns.
//
// PC-DMIS: no real file is available. The example below is written from the format's own
// documentation, not from any Metrofit writer:
//   * Hexagon, PC-DMIS 2019 R1 help, "Dimension Command Format"
//     (https://docs.hexagonmi.com/pcdmis/2019.1/en/helpcenter/mergedProjects/core/19_dimen_topics/Dimension_Command_Format.htm):
//     "dimension_name = TYPE OF DIMENSION,feat_1 UNITS=...,$", "GRAPH=OFF TEXT=OFF MULT=1.00
//     OUTPUT=BOTH", the columns AX NOM +TOL -TOL MEAS MAX MIN DEV OUT-TOL, rows x / y / z / d,
//     "END OF DIMENSION dimension_name (for LOCATION only)";
//   * Hexagon, PC-DMIS 2022.1 help, "Dimension Format" / "Dimension Output Format": FORMAT/TEXT,
//     ...,HEADINGS,...;NOM,TOL,MEAS,DEV,OUTTOL (the column order of the report);
//   * Hexagon, PC-DMIS 2021.2 help, "To Dimension a Feature Using the LOCATION Option": the
//     default axes CIRCLE = X, Y, D; POINT = X, Y, Z, T; PLANE = the axis of the plane.
//   The printed layout "DIM LOC1= LOCATION OF CIRCLE CIR1  UNITS=MM ,$" with the deviation graphic
//   after the OUTTOL column is that of PC-DMIS's standard text report.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <string>

#include "core/common/error.h"
#include "core/io/cmm_text_report.h"
#include "core/setup/exact.h"
#include "core/setup/objective.h"
#include "core/setup/report.h"
#include "samples/pcdmis_reports.h"
#include "setup_fixtures.h"
#include "testsupport.h"

namespace metrofit::setup {
namespace {

namespace fs = std::filesystem;
using metrofit::test::near;

fs::path ogpDir() {
  return metrofit::test::realData("cmm-ogp-hps-svt");
}

#define REQUIRE_OGP() METROFIT_REQUIRE_PATH(ogpDir() / "survey_data")

std::string errorOf(const std::string& text, const std::string& source = "r.txt") {
  try {
    (void)cmmTextReportFromText(text, source);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

std::vector<fs::path> stepFiles() {
  std::vector<fs::path> out;
  for (const char* d : {"meas1", "meas2", "meas3", "fixture/L0"})
    for (const auto& e : fs::directory_iterator(ogpDir() / "survey_data" / d))
      if (e.path().extension() == ".txt") out.push_back(e.path());
  std::sort(out.begin(), out.end());
  return out;
}

// ---- OGP summary report -----------------------------------------------------------------------

TEST(OgpReport, SummaryDeviationsAreThoseTheFilePrints) {
  REQUIRE_OGP();
  const std::string file = (ogpDir() / "survey_data" / "L123_fixture_sho.txt").string();
  const CmmTextReport r = readCmmTextReport(file);
  EXPECT_EQ(r.format, CmmReportFormat::OgpSummary);
  EXPECT_FALSE(r.rtf);
  // grep -c "Routine Name" -> 13 runs; grep -c "^Step [0-9]" -> 169 step blocks.
  ASSERT_EQ(r.runs.size(), 13u);
  std::size_t steps = 0, values = 0, printed = 0, locations = 0, plainSignDiffers = 0, angles = 0;
  for (const CmmRun& run : r.runs) {
    steps += run.features.size();
    for (const CmmFeature& f : run.features) {
      for (const CmmValue& v : f.values) {
        ++values;
        if (!v.printedDeviation) continue;
        ++printed;
        // The printed deviation is OGP's: sign(nominal) (actual - nominal) for locations, within
        // the rounding of three numbers printed to 0.001.
        EXPECT_LE(std::abs(ogpPrintedDeviation(v) - *v.printedDeviation), 0.0015 + 1e-9)
            << file << ":" << v.line;
        const bool location = v.name.find("Location") != std::string::npos;
        locations += location && v.nominal;
        angles += v.angle && v.nominal;
        if (location && v.nominal && std::abs(plainDeviation(v) - *v.printedDeviation) > 0.0015 + 1e-9)
          ++plainSignDiffers;
      }
    }
  }
  EXPECT_EQ(steps, 169u);
  // grep -cE "^(X|Y|Z) Location|^XY Angle|^Elevation|^Flatness|^Sphericity|^Sphere
  // Diame|^Diameter|^Cylindricity"
  // -> 845 value rows; of them 442 print nominal, actual and deviation and 91 (form) actual and
  // deviation: 533 printed deviations.
  EXPECT_EQ(values, 845u);
  EXPECT_EQ(printed, 533u);
  EXPECT_EQ(locations, 273u);  // SOURCE.md: 273 of 273 location rows follow the sign rule
  EXPECT_EQ(angles, 104u);     // SOURCE.md: 104 angle rows, plain actual - nominal
  // SOURCE.md: plain actual - nominal fails on 57 Y, 26 Z and 11 X rows.
  EXPECT_EQ(plainSignDiffers, 57u + 26u + 11u);

  // Run 1 (Run # 4, Wed Oct 01 17:29:15 2014), "Step 5 - Datum plane, hole side, touch":
  //   Y Location  -00113.895 -00113.903  +00000.009  (further from zero = positive)
  const CmmRun& first = r.runs.front();
  EXPECT_EQ(first.routine, "L123_fixture.RTN");
  EXPECT_EQ(first.number, 4);
  EXPECT_EQ(first.dateTime, "Wed Oct 01 17:29:15 2014");
  const CmmFeature* step5 = nullptr;
  for (const CmmFeature& f : first.features)
    if (f.step == 5) step5 = &f;
  ASSERT_NE(step5, nullptr);
  EXPECT_EQ(step5->label, "Datum plane, hole side, touch");
  const CmmValue* y = step5->value("Y Location");
  ASSERT_NE(y, nullptr);
  EXPECT_DOUBLE_EQ(*y->nominal, -113.895);
  EXPECT_DOUBLE_EQ(y->actual, -113.903);
  EXPECT_DOUBLE_EQ(*y->printedDeviation, 0.009);
  EXPECT_TRUE(near(plainDeviation(*y), -0.008, 1e-12));
  EXPECT_EQ(y->line, 31);  // sed -n 31p: "Y Location     -00113.895 -00113.903        +00000.009"
  // Flatness prints no nominal: its deviation is the actual.
  const CmmValue* flat = step5->value("Flatness");
  ASSERT_NE(flat, nullptr);
  EXPECT_FALSE(flat->nominal);
  EXPECT_DOUBLE_EQ(*flat->printedDeviation, 0.005);
}

TEST(OgpReport, SummaryAsFeatureSeriesHasOneRowPerRun) {
  REQUIRE_OGP();
  const CsvTable t = readFeatureTable((ogpDir() / "survey_data" / "L123_fixture_sho.txt").string());
  ASSERT_EQ(t.rowCount(), 13u);
  // "Step 7 - Hole pin, touch", Diameter: nominal 3.182 in the first run, actual 3.177, printed -0.004.
  const auto d = t.numericColumn("step7.diameter");
  const auto dev = t.numericColumn("step7.diameter.dev");
  EXPECT_DOUBLE_EQ(d[0], 3.177);
  EXPECT_TRUE(near(dev[0], -0.005, 1e-12));  // 3.177 - 3.182 (the printed -0.004 comes from finer values)
  for (std::size_t i = 0; i < d.size(); ++i) {
    EXPECT_GT(d[i], 3.17);  // SOURCE.md: hole-pin diameter 3.177 mm
    EXPECT_LT(d[i], 3.19);
  }
  EXPECT_EQ(t.lineOf(0), 5);  // the run line "L123_fixture.RTN           4 Wed Oct 01 ..."
  EXPECT_EQ(t.cell(0, 1), "Wed Oct 01 17:29:15 2014");
}

TEST(OgpReport, SummaryRunsReachTheSetupStudyWithThePlainSign) {
  REQUIRE_OGP();
  nlohmann::json j = test::smallModelJson();
  j["axis"] = "Y";
  // D1: the Y location of the hole-side datum plane (negative nominal: OGP prints the opposite
  // sign); D2: the hole-pin diameter.
  j["dimensions"][0] = {{"id", "D1"}, {"lower", -0.02}, {"upper", 0.02}, {"label", "Step 5"}};
  j["dimensions"][1] = {
      {"id", "D2"}, {"lower", -0.05}, {"upper", 0.03}, {"label", "hole pin, touch:Diameter"}};
  const Model model = modelFromJson(j, "m.json");
  const std::string file = (ogpDir() / "survey_data" / "L123_fixture_sho.txt").string();
  const Measurements m = readMeasurements({file}, model);
  ASSERT_EQ(m.parts.size(), 13u);
  EXPECT_EQ(m.parts.front(), "L123_fixture_sho.txt run 1");
  EXPECT_EQ(m.samples, (std::vector<int>{13, 13}));
  // The mean of the printed deviations, turned back to actual - nominal (Y nominals are negative here).
  const CmmTextReport r = readCmmTextReport(file);
  double y = 0.0, dia = 0.0;
  for (const CmmRun& run : r.runs) {
    for (const CmmFeature& f : run.features) {
      if (f.step == 5) {
        ASSERT_LT(*f.value("Y Location")->nominal, 0.0);
        y += -*f.value("Y Location")->printedDeviation;
      }
      if (f.step == 7) dia += *f.value("Diameter")->printedDeviation;
    }
  }
  EXPECT_TRUE(near(m.deviationMm[0], y / 13.0, 0.0015));
  EXPECT_TRUE(near(m.deviationMm[1], dia / 13.0, 0.0015));
  EXPECT_LT(m.deviationMm[0], 0.0);  // the actuals are more negative than the nominals
}

// ---- OGP step reports (.RTN printouts) ---------------------------------------------------------

TEST(OgpReport, StepReportsCountsAndTruePositions) {
  REQUIRE_OGP();
  const auto files = stepFiles();
  ASSERT_EQ(files.size(), 19u + 19u + 18u + 3u);
  std::size_t steps = 0, rtf = 0, truePositions = 0;
  long points = 0;
  std::map<std::string, int> types;
  for (const fs::path& p : files) {
    const CmmTextReport r = readCmmTextReport(p.string());
    ASSERT_EQ(r.format, CmmReportFormat::OgpSteps) << p;
    ASSERT_EQ(r.runs.size(), 1u);
    rtf += r.rtf;
    for (const CmmFeature& f : r.runs.front().features) {
      ++steps;
      points += f.points;
      ++types[f.type.substr(0, f.type.find(' '))];
      // The printed True Position is the diametral deviation of the location, 2 |actual - nominal|.
      const CmmValue* tp = f.value("True Position");
      const CmmValue *x = f.value("X Location"), *y = f.value("Y Location"), *z = f.value("Z Location");
      if (tp && x && y && z) {
        ++truePositions;
        const double d = 2.0 * std::hypot(plainDeviation(*x), plainDeviation(*y), plainDeviation(*z));
        // Three differences of values printed to 1e-5 and the printed value itself.
        EXPECT_LE(std::abs(d - tp->actual), 2.0 * std::sqrt(3.0) * 1e-5 + 0.5e-5) << p << ":" << tp->line;
      }
    }
  }
  // SOURCE.md (and grep -c "Step:" over the files): 1985 steps; the "Points: n" add up to 19 501.
  EXPECT_EQ(steps, 1985u);
  EXPECT_EQ(points, 19501);
  EXPECT_EQ(rtf, 19u + 19u + 18u);  // the meas* files are RTF, the fixture files plain
  EXPECT_EQ(types["Line"], 1184);
  EXPECT_EQ(types["Sphere"], 195);
  EXPECT_EQ(types["Datum"], 171);
  EXPECT_EQ(types["Plane"], 128);
  EXPECT_EQ(types["Midpoint"], 105);
  EXPECT_EQ(types["Intersect"], 92);
  EXPECT_EQ(types["Circle"], 84);
  EXPECT_EQ(types["Point"], 14);
  EXPECT_EQ(types["Distance"], 12);
  // grep -c "True Position" over the step files: 490, all of them with X, Y and Z Location.
  EXPECT_EQ(truePositions, 490u);
}

TEST(OgpReport, StepReportValuesOfTheOriball) {
  REQUIRE_OGP();
  // SOURCE.md's example (meas1/L0_axial_top_module1_1.txt, step 2 "oriball").
  const CmmTextReport r =
      readCmmTextReport((ogpDir() / "survey_data/meas1/L0_axial_top_module1_1.txt").string());
  EXPECT_TRUE(r.rtf);
  EXPECT_EQ(r.runs.front().routine, "L0_axial_routine.RTN");
  const CmmFeature& f = r.runs.front().features.at(1);
  EXPECT_EQ(f.step, 2);
  EXPECT_EQ(f.label, "oriball");
  EXPECT_EQ(f.type, "Sphere");
  EXPECT_EQ(f.points, 17);
  EXPECT_EQ(f.line, 29);  // the " Step:  2 ..." line of the file
  EXPECT_DOUBLE_EQ(f.value("Diameter")->actual, 6.35386);
  EXPECT_DOUBLE_EQ(*f.value("Diameter")->nominal, 6.35940);
  EXPECT_DOUBLE_EQ(f.value("X Location")->actual, 309.59770);
  EXPECT_DOUBLE_EQ(*f.value("Z Location")->nominal, -32.04627);
  EXPECT_DOUBLE_EQ(*f.value("Z Location")->upper, 0.0);
  EXPECT_DOUBLE_EQ(f.value("True Position")->actual, 0.07075);
  EXPECT_EQ(f.value("X Location")->line, 37);
}

/// The plain text of an Msftedit RTF file, made by hand: the RTF groups before the first text, the
/// closing brace and the NUL removed, doubled backslashes undoubled.
std::string unwrapByHand(std::string raw) {
  const std::string marker = "\\fs20 ";
  const auto start = raw.find(marker);
  // Keep the line breaks of the header lines so the line numbers stay the file's.
  std::string head = raw.substr(0, start);
  std::string breaks;
  for (char c : head)
    if (c == '\n') breaks += "\r\n";
  std::string body = raw.substr(start + marker.size());
  const auto close = body.rfind('}');
  body = body.substr(0, close) + body.substr(close + 1);
  body.erase(std::remove(body.begin(), body.end(), '\0'), body.end());
  std::string out;
  for (std::size_t i = 0; i < body.size(); ++i) {
    out += body[i];
    if (body[i] == '\\' && i + 1 < body.size() && body[i + 1] == '\\') ++i;
  }
  return breaks + out;
}

void expectSameReport(const CmmTextReport& a, const CmmTextReport& b) {
  ASSERT_EQ(a.runs.size(), b.runs.size());
  ASSERT_EQ(a.runs[0].features.size(), b.runs[0].features.size());
  EXPECT_EQ(a.runs[0].routine, b.runs[0].routine);
  for (std::size_t i = 0; i < a.runs[0].features.size(); ++i) {
    const CmmFeature &fa = a.runs[0].features[i], &fb = b.runs[0].features[i];
    EXPECT_EQ(fa.step, fb.step);
    EXPECT_EQ(fa.label, fb.label);
    EXPECT_EQ(fa.type, fb.type);
    EXPECT_EQ(fa.points, fb.points);
    EXPECT_EQ(fa.line, fb.line);
    ASSERT_EQ(fa.values.size(), fb.values.size());
    for (std::size_t k = 0; k < fa.values.size(); ++k) {
      EXPECT_EQ(fa.values[k].name, fb.values[k].name);
      EXPECT_EQ(fa.values[k].actual, fb.values[k].actual);
      EXPECT_EQ(fa.values[k].nominal, fb.values[k].nominal);
      EXPECT_EQ(fa.values[k].line, fb.values[k].line);
    }
  }
}

TEST(OgpReport, RtfAndPlainFormsGiveTheSameValues) {
  REQUIRE_OGP();
  // An RTF file of the survey, unwrapped by hand.
  const std::string rtfFile = (ogpDir() / "survey_data/meas2/L1_stereo_bottom_module5_2.txt").string();
  const std::string raw = metrofit::test::readText(rtfFile);
  ASSERT_EQ(raw.back(), '\0');
  const CmmTextReport fromRtf = cmmTextReportFromText(raw, "a.txt");
  const CmmTextReport fromPlain = cmmTextReportFromText(unwrapByHand(raw), "b.txt");
  EXPECT_TRUE(fromRtf.rtf);
  EXPECT_FALSE(fromPlain.rtf);
  expectSameReport(fromRtf, fromPlain);
  EXPECT_EQ(fromRtf.runs[0].features.size(), 37u);  // grep -c "Step:" on the file

  // A plain file of the survey, wrapped the way Msftedit wraps it.
  const std::string plainFile = (ogpDir() / "survey_data/fixture/L0/empty_fixture0.txt").string();
  std::string plain = metrofit::test::readText(plainFile);
  std::string escaped;
  for (char c : plain) escaped += c == '\\' ? std::string("\\\\") : std::string(1, c);
  const std::string wrapped =
      "{\\rtf1\\ansi\\deff0{\\fonttbl{\\f0\\froman\\fprq1 Courier New;}}{\\colortbl "
      ";\\red255\\green255\\blue255;}"
      "{\\*\\generator Msftedit 5.41.15.1507;}\\viewkind4\\uc1\\lang1033\\f0\\fs20 " +
      escaped + "}\r\n" + std::string(1, '\0');
  const CmmTextReport a = cmmTextReportFromText(plain, "p.txt");
  const CmmTextReport b = cmmTextReportFromText(wrapped, "w.txt");
  expectSameReport(a, b);
  EXPECT_EQ(a.runs[0].features.size(), 6u);  // grep -c "Step:" empty_fixture0.txt
}

TEST(OgpReport, TruncatedOrGarbledFilesGiveOneLineErrors) {
  REQUIRE_OGP();
  const std::string raw =
      metrofit::test::readText((ogpDir() / "survey_data/meas1/L0_axial_top_module1_1.txt").string());
  // Cut in the middle: the RTF document is not closed.
  std::string e = errorOf(raw.substr(0, raw.size() / 2), "cut.txt");
  EXPECT_NE(e.find("cut.txt:"), std::string::npos) << e;
  EXPECT_NE(e.find("truncated"), std::string::npos) << e;
  EXPECT_EQ(e.find('\n'), std::string::npos) << e;

  const std::string plain =
      metrofit::test::readText((ogpDir() / "survey_data/fixture/L0/empty_fixture0.txt").string());
  // Cut after the Z Location row of step 2 (line 37 of the file): the step never closes.
  std::size_t pos = 0;
  for (int n = 0; n < 37; ++n) pos = plain.find('\n', pos) + 1;
  e = errorOf(plain.substr(0, pos), "cut.txt");
  EXPECT_EQ(e, "cut.txt:37: the file ends inside step 2 (line 27); it is truncated") << e;
  // Cut inside the row: its Lower column is missing.
  e = errorOf(plain.substr(0, pos - 12), "cut.txt");
  EXPECT_NE(e.find("cut.txt:37:"), std::string::npos) << e;

  // A garbled digit in a value row (line 15, the X Location of step 1).
  std::string garbled = plain;
  const auto at = garbled.find("+454.74389");
  garbled.replace(at, 10, "+454.7a389");
  e = errorOf(garbled, "g.txt");
  EXPECT_NE(e.find("g.txt:15:"), std::string::npos) << e;
  EXPECT_NE(e.find("'+454.7a389' is not a number"), std::string::npos) << e;
  // A missing column.
  garbled = plain;
  garbled.replace(garbled.find("+454.74389  +454.74389"), 22, "+454.74389");
  e = errorOf(garbled, "g.txt");
  EXPECT_NE(e.find("g.txt:15:"), std::string::npos) << e;
  EXPECT_NE(e.find("expected Actual, Nominal, Upper and Lower (4 numbers), found 3"), std::string::npos) << e;

  // A summary whose printed deviation disagrees with its actual and nominal (line 31: +0.009 -> +0.019).
  std::string sho = metrofit::test::readText((ogpDir() / "survey_data/L123_fixture_sho.txt").string());
  sho.replace(sho.find("-00113.903        +00000.009"), 28, "-00113.903        +00000.019");
  e = errorOf(sho, "s.txt");
  EXPECT_NE(e.find("s.txt:31:"), std::string::npos) << e;
  EXPECT_NE(e.find("sign(nominal) * (actual - nominal)"), std::string::npos) << e;
  EXPECT_EQ(e.find('\n'), std::string::npos) << e;
}

TEST(OgpReport, StepReportReachesTheSetupStudy) {
  REQUIRE_OGP();
  nlohmann::json j = test::smallModelJson();
  j["dimensions"][0] = {{"id", "D1"}, {"lower", -0.02}, {"upper", 0.02}, {"label", "ORIBALL"}};
  j["dimensions"][1] = {{"id", "D2"}, {"lower", -0.05}, {"upper", 0.03}, {"label", "axiball:Diameter"}};
  const Model model = modelFromJson(j, "m.json");
  const std::string file = (ogpDir() / "survey_data/meas1/L0_axial_top_module1_1.txt").string();
  const Measurements m = readMeasurements({file}, model);
  EXPECT_EQ(m.parts, std::vector<std::string>{"L0_axial_top_module1_1.txt"});
  // oriball Z: -032.03676 actual, -032.04627 nominal; axiball Diameter +006.35505 / +006.34291.
  EXPECT_TRUE(near(m.deviationMm[0], -32.03676 + 32.04627, 1e-9));
  EXPECT_TRUE(near(m.deviationMm[1], 6.35505 - 6.34291, 1e-9));
  EXPECT_EQ(m.rows[0].line, 39);

  // The same features in the second and third survey: three parts, the mean of the three.
  const Measurements three =
      readMeasurements({file, (ogpDir() / "survey_data/meas2/L0_axial_top_module1_2.txt").string(),
                        (ogpDir() / "survey_data/meas3/L0_axial_top_module1_3.txt").string()},
                       model);
  EXPECT_EQ(three.parts.size(), 3u);
  EXPECT_EQ(three.samples, (std::vector<int>{3, 3}));

  // A label that names a value the step does not have.
  j["dimensions"][1]["label"] = "axiball:Flatness";
  try {
    (void)readMeasurements({file}, modelFromJson(j, "m.json"));
    FAIL() << "no error";
  } catch (const ValidationError& e) {
    EXPECT_NE(std::string(e.what()).find("step 3 'axiball' has no value 'Flatness'"), std::string::npos)
        << e.what();
  }
}

// ---- PC-DMIS text report -----------------------------------------------------------------------

// Written from the PC-DMIS documentation cited at the top (not from a Metrofit writer).
const char* const kPcDmis = ::metrofit::test::kPcDmisBracketReport;

TEST(PcDmisReport, DevColumnIsMeasMinusNominal) {
  EXPECT_EQ(detectCmmTextReport(kPcDmis), CmmReportFormat::PcDmis);
  const CmmTextReport r = cmmTextReportFromText(kPcDmis, "bracket.txt");
  ASSERT_EQ(r.runs.size(), 1u);
  EXPECT_EQ(r.runs[0].routine, "BRACKET 0042");
  ASSERT_EQ(r.runs[0].features.size(), 2u);
  const CmmFeature& loc1 = r.runs[0].features[0];
  EXPECT_EQ(loc1.label, "LOC1");
  EXPECT_EQ(loc1.featureName, "CIR1");
  EXPECT_EQ(loc1.featureType, "CIRCLE");
  ASSERT_EQ(loc1.values.size(), 3u);
  int rows = 0;
  for (const CmmFeature& f : r.runs[0].features) {
    for (const CmmValue& v : f.values) {
      ++rows;
      EXPECT_TRUE(near(*v.printedDeviation, v.actual - *v.nominal, 1e-12)) << v.name;
    }
  }
  EXPECT_EQ(rows, 4);
  const CmmValue& d = loc1.values[2];
  EXPECT_EQ(d.name, "D");
  EXPECT_DOUBLE_EQ(*d.upper, 0.030);
  EXPECT_DOUBLE_EQ(*d.lower, -0.050);  // -TOL 0.050: the lower limit is 0.050 below the nominal
  EXPECT_EQ(d.line, 11);
  EXPECT_DOUBLE_EQ(*r.runs[0].features[1].values[0].outTol, 0.015);
}

TEST(PcDmisReport, ValuesReachTheSetupFit) {
  nlohmann::json j = test::smallModelJson();
  j["dimensions"][0]["label"] = "LOC2";    // the Z row (the model's axis)
  j["dimensions"][1]["label"] = "CIR1:D";  // by the feature's name, the diameter row
  const Model model = modelFromJson(j, "m.json");
  const std::string path = (metrofit::test::outDir() / "pcdmis_bracket.txt").string();
  metrofit::test::writeText(path, kPcDmis);
  const Measurements m = readMeasurements({path}, model);
  EXPECT_EQ(m.parts, std::vector<std::string>{"pcdmis_bracket.txt"});
  EXPECT_TRUE(near(m.deviationMm[0], 0.035, 1e-12));
  EXPECT_TRUE(near(m.deviationMm[1], 0.020, 1e-12));
  EXPECT_EQ(m.rows[0].line, 17);
  // D1 = W1 + T5 is 0.015 out of tolerance; the exact fit brings both dimensions inside.
  const SetupInstance instance(model, m);
  EXPECT_TRUE(near(instance.deviation(0), 0.035, 1e-12));
  const ExactResult fit = solveExact(instance);
  const Eigen::MatrixXd g = gainMatrix(model);
  for (std::size_t q = 0; q < 2; ++q) {
    double corrected = m.deviationMm[q];
    for (std::size_t i = 0; i < fit.x.size(); ++i)
      corrected += g(static_cast<Eigen::Index>(q), static_cast<Eigen::Index>(i)) * fit.x[i];
    EXPECT_GE(corrected, model.dimensions[q].lower - 1e-9) << q;
    EXPECT_LE(corrected, model.dimensions[q].upper + 1e-9) << q;
  }
  // The report's limits must be the model's: -TOL 0.040 is not the model's -0.05.
  std::string other = kPcDmis;
  other.replace(other.find("18.500      0.030      0.050"), 28, "18.500      0.030      0.040");
  metrofit::test::writeText(path, other);
  try {
    (void)readMeasurements({path}, model);
    FAIL() << "no error";
  } catch (const ValidationError& e) {
    EXPECT_NE(std::string(e.what()).find("pcdmis_bracket.txt:11: field 'D': tolerance -0.04 / 0.03 differs"),
              std::string::npos)
        << e.what();
  }
}

TEST(PcDmisReport, BadRowsGiveOneLineErrorsWithTheLine) {
  auto withRow = [](const std::string& from, const std::string& to) {
    std::string t = kPcDmis;
    t.replace(t.find(from), from.size(), to);
    return t;
  };
  // A garbled number.
  std::string e = errorOf(withRow("39.996     -0.004", "39.9x6     -0.004"));
  EXPECT_NE(e.find("r.txt:10:"), std::string::npos) << e;
  EXPECT_NE(e.find("'39.9x6' is not a number"), std::string::npos) << e;
  // DEV that is not MEAS - NOMINAL.
  e = errorOf(withRow("39.996     -0.004", "39.996     -0.014"));
  EXPECT_NE(e.find("r.txt:10:"), std::string::npos) << e;
  EXPECT_NE(e.find("is not MEAS - NOMINAL"), std::string::npos) << e;
  // A row with a column missing.
  e = errorOf(withRow("42.035      0.035      0.015 --------->", "42.035      0.035 --------->"));
  EXPECT_NE(e.find("r.txt:17:"), std::string::npos) << e;
  EXPECT_NE(e.find("expected 6 values after the axis, found 5"), std::string::npos) << e;
  // A row before the column header.
  e = errorOf(withRow("AX    NOMINAL       +TOL       -TOL       MEAS        DEV     OUTTOL\nZ", "Z"));
  EXPECT_NE(e.find("r.txt:16:"), std::string::npos) << e;
  EXPECT_NE(e.find("before the column header"), std::string::npos) << e;
  for (const std::string& s : {e}) EXPECT_EQ(s.find('\n'), std::string::npos);
}

}  // namespace
}  // namespace metrofit::setup
