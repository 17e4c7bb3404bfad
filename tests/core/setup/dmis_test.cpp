// DMIS output as CMMs write it (core/setup/report.h). The texts are written from
// the statement syntax of the DMIS standard (ANSI/DMIS 105.2 Part 1, 5.3: FILNAM, DMISMN, UNITS,
// F/FA = FEAT/CIRCLE|CYLNDR|POINT,[INNER|OUTER,]CART,..., T/TA = TOL/DIAM|CORTOL|DISTB|PROFP,
// OUTPUT, ENDFIL), not from Metrofit's own writer; expected deviations are worked out by hand below.
#include <gtest/gtest.h>

#include <functional>
#include <map>

#include "core/common/error.h"
#include "core/common/numformat.h"
#include "core/io/csv.h"
#include "core/io/file_io.h"
#include "core/setup/exact.h"
#include "core/setup/objective.h"
#include "core/setup/report.h"
#include "setup_fixtures.h"
#include "testsupport.h"

namespace metrofit::setup {
namespace {

using metrofit::test::near;

std::string dmisError(const std::string& text, const DmisOptions& o = {},
                      const Model& model = test::smallModel()) {
  try {
    (void)dmisReportFromText(text, "out.dmi", model, o);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

// The small model: D1 (label POS_D1) nominal 42, limits -0.02 / 0.02; D2 nominal 18.5, -0.05 / 0.03; axis Z.
const char* kCmmOutput =
    "FILNAM/'BRACKET-0042',05.3\n"
    "DMISMN/'Bracket inspection',05.3\n"
    "UNITS/MM,ANGDEC\n"
    "$$ a bore: nominal and actual circle (x,y,z,i,j,k,diam)\n"
    "F(POS_D1)=FEAT/CIRCLE,INNER,CART,25.000,40.000,42.000,0.0,0.0,1.0,12.000\n"
    "FA(POS_D1)=FEAT/CIRCLE,INNER,CART,25.006,39.996,42.011,0.0,0.0,1.0,12.011\n"
    "T(POS_D1)=TOL/CORTOL,ZAXIS,-0.02,0.02\n"
    "TA(POS_D1)=TOL/CORTOL,ZAXIS,0.011,INTOL\n"
    "$$ a diameter reported as the actual value (as the QIF-to-DMIS converter writes TOL/DIAM)\n"
    "T(D2)=TOL/DIAM,-0.05,0.03\n"
    "TA(D2)=TOL/DIAM,18.44,OUTTOL\n"
    "OUTPUT/FA(POS_D1),TA(POS_D1)\n"
    "ENDFIL\n";

TEST(Dmis, CmmOutputStartingWithFilnam) {
  EXPECT_TRUE(looksLikeDmis(kCmmOutput));
  const Measurements m = dmisReportFromText(kCmmOutput, "out.dmi", test::smallModel());
  EXPECT_EQ(m.parts, std::vector<std::string>{"BRACKET-0042"});
  EXPECT_TRUE(near(m.deviationMm[0], 42.011 - 42.000, 1e-12));  // FA - F along Z
  EXPECT_TRUE(near(m.deviationMm[1], 18.44 - 18.5, 1e-12));     // auto: 18.44 is an actual value
  EXPECT_EQ(m.rows[1].line, 11);
}

TEST(Dmis, FeatureValuesWinOverTheToleranceActual) {
  // F and FA cylinders with diameters: a DIAM tolerance takes the diameter difference, whatever TA says.
  const std::string text =
      "DMISMN/'x',05.3\n"
      "F(D2)=FEAT/CYLNDR,INNER,CART,0,0,0,0,0,1,18.500,20\n"
      "FA(D2)=FEAT/CYLNDR,INNER,CART,0.01,0,0,0,0,1,18.480,20\n"
      "T(D2)=TOL/DIAM,-0.05,0.03\n"
      "TA(D2)=TOL/DIAM,18.48,INTOL\n"
      "F(POS_D1)=FEAT/POINT,CART,0,0,42,0,0,1\n"
      "FA(POS_D1)=FEAT/POINT,CART,0,0,42.004,0,0,1\n"
      "TA(POS_D1)=TOL/CORTOL,ZAXIS,0.5,INTOL\n"
      "ENDFIL\n";
  const Measurements m = dmisReportFromText(text, "out.dmi", test::smallModel());
  EXPECT_TRUE(near(m.deviationMm[1], 18.480 - 18.500, 1e-12));
  EXPECT_TRUE(near(m.deviationMm[0], 0.004, 1e-12));
  // RAD: half the diameter difference.
  std::string rad = text;
  rad.replace(rad.find("TOL/DIAM,-0.05"), 8, "TOL/RAD");
  rad.replace(rad.find("TOL/DIAM,18.48"), 8, "TOL/RAD");
  EXPECT_TRUE(near(dmisReportFromText(rad, "out.dmi", test::smallModel()).deviationMm[1], -0.010, 1e-12));
}

TEST(Dmis, ToleranceActualMeaningIsASetting) {
  const std::string text =
      "DMISMN/'x',05.3\n"
      "TA(POS_D1)=TOL/PROFP,0.012,INTOL\n"
      "TA(D2)=TOL/DIAM,0.025,INTOL\n";
  // Auto: values near zero are deviations.
  Measurements m = dmisReportFromText(text, "out.dmi", test::smallModel());
  EXPECT_TRUE(near(m.deviationMm[0], 0.012, 1e-12));
  EXPECT_TRUE(near(m.deviationMm[1], 0.025, 1e-12));
  // Told that TA is the actual value: 0.012 - 42 is far outside, but the file says INTOL.
  DmisOptions actual;
  actual.taMeaning = DmisTaMeaning::Actual;
  EXPECT_EQ(
      dmisError(text, actual),
      "out.dmi:2: field 'TA(POS_D1)': the deviation -41.988 mm is outside the tolerance -0.02 / 0.02 but the "
      "file says INTOL; read the tolerance actual as a deviation or with the other sign convention");
  EXPECT_EQ(parseDmisTaMeaning("actual"), DmisTaMeaning::Actual);
  EXPECT_THROW(parseDmisTaMeaning("mean"), OptionsError);
}

TEST(Dmis, PlausibilityAgainstOutol) {
  // -0.021 is inside -0.05 / 0.03: OUTOL (or OUTTOL) contradicts it.
  const std::string text =
      "DMISMN/'x',05.3\nTA(POS_D1)=TOL/CORTOL,ZAXIS,0.001,INTOL\nTA(D2)=TOL/DISTB,-0.021,OUTOL\n";
  EXPECT_EQ(
      dmisError(text),
      "out.dmi:3: field 'TA(D2)': the deviation -0.021 mm is inside the tolerance -0.05 / 0.03 but the file "
      "says OUTOL; read the tolerance actual as the actual value or with the other sign convention");
  std::string outtol = text;
  outtol.replace(outtol.find("-0.021,OUTOL"), 12, "-0.061,OUTTOL");
  EXPECT_TRUE(near(dmisReportFromText(outtol, "out.dmi", test::smallModel()).deviationMm[1], -0.061, 1e-12));
}

TEST(Dmis, SignFollowsNegativeNominalIsASetting) {
  nlohmann::json j = test::smallModelJson();
  j["dimensions"][1]["nominal"] = -18.5;
  const Model model = modelFromJson(j, "m.json");
  // The writer printed sign(N) * (A - N) = -(A - N) for the negative nominal: A - N = +0.02.
  const std::string text =
      "DMISMN/'x',05.3\nTA(POS_D1)=TOL/CORTOL,ZAXIS,0.001\nT(D2)=TOL/DISTB,NOMINL,-18.5,-0.05,0.03\n"
      "TA(D2)=TOL/DISTB,-0.020,INTOL\n";
  EXPECT_TRUE(near(dmisReportFromText(text, "out.dmi", model).deviationMm[1], -0.020, 1e-12));
  DmisOptions o;
  o.signFollowsNominal = true;
  EXPECT_TRUE(near(dmisReportFromText(text, "out.dmi", model, o).deviationMm[1], 0.020, 1e-12));
}

TEST(Dmis, FeatureSyntaxErrors) {
  EXPECT_EQ(dmisError("DMISMN/'x',05.3\nFA(POS_D1)=FEAT/CIRCLE,INNER,POL,1,2,3\n"),
            "out.dmi:2: field 'FA(POS_D1)': polar (POL) coordinates are not supported; use CART");
  EXPECT_EQ(
      dmisError("DMISMN/'x',05.3\nFA(POS_D1)=FEAT/CIRCLE,OUTER,XYZ,1,2,3\n"),
      "out.dmi:2: field 'FA(POS_D1)': expected CART after the feature type and INNER/OUTER, found 'XYZ'");
  EXPECT_FALSE(looksLikeDmis("part,time_min\n"));
}

TEST(Dmis, ToleranceActualFarOutsideTheBandNamesTheLabel) {
  // No INTOL / OUTOL: the band is the check. D2 (nominal 18.5, -0.05 / 0.03, width 0.08) written as
  // the actual diameter 18.44 by the QIF-to-DMIS converter, but read as a deviation.
  const std::string head = "DMISMN/'x',05.3\nTA(POS_D1)=TOL/CORTOL,ZAXIS,0.011\n";
  DmisOptions deviation;
  deviation.taMeaning = DmisTaMeaning::Deviation;
  EXPECT_EQ(
      dmisError(head + "TA(D2)=TOL/DIAM,18.44\n", deviation),
      "out.dmi:3: field 'TA(D2)': the tolerance actual 18.44 read as a deviation gives the deviation 18.44 "
      "mm, more than 10 tolerance widths outside the tolerance -0.05 / 0.03 of 'D2'; read it as the actual "
      "value or with the other sign convention");
  // Auto reads it as the actual value (nearer the nominal): -0.06, a plausible part.
  const Measurements m = dmisReportFromText(head + "TA(D2)=TOL/DIAM,18.44\n", "out.dmi", test::smallModel());
  EXPECT_TRUE(near(m.deviationMm[1], -0.06, 1e-12));
  // Read as the actual value (42.011 for D1 is fine), a deviation-sized number lands about 18.5 mm off.
  DmisOptions actual;
  actual.taMeaning = DmisTaMeaning::Actual;
  EXPECT_NE(dmisError("DMISMN/'x',05.3\nTA(POS_D1)=TOL/CORTOL,ZAXIS,42.011\nTA(D2)=TOL/DIAM,0.02\n", actual)
                .find("read as the actual value gives the deviation -18.48"),
            std::string::npos);
  // D1 (-0.02 / 0.02, width 0.04): 0.41 is 9.75 widths above the band and kept; 0.43 is 10.25 widths.
  const std::string d2 = "TA(D2)=TOL/DIAM,18.44\n";
  EXPECT_TRUE(near(dmisReportFromText("DMISMN/'x',05.3\nTA(POS_D1)=TOL/CORTOL,ZAXIS,0.41\n" + d2, "out.dmi",
                                      test::smallModel())
                       .deviationMm[0],
                   0.41, 1e-12));
  EXPECT_NE(dmisError("DMISMN/'x',05.3\nTA(POS_D1)=TOL/CORTOL,ZAXIS,0.43\n" + d2)
                .find("out.dmi:2: field 'TA(POS_D1)': the tolerance actual 0.43 read as a deviation"),
            std::string::npos);
}

/// How the paper example's CSV series (3 parts x 28 dimensions, 4 fixture positions P1..P4 of 7 each)
/// is written as DMIS output files.
struct DmisSeriesLayout {
  bool serials = false;      ///< PARTSN/'<CSV part>' in every file (else only FILNAM, the program)
  bool perPosition = false;  ///< one file per fixture position per part (12 files), else per part (3)
  std::function<bool(const std::string& part, const std::string& dim)> skip;  ///< rows left out
};

/// The paper example's CSV series written as DMIS output files: even dimensions as nominal and actual
/// points (F / FA along Z), odd ones as a tolerance definition and its actual, the deviation (T / TA =
/// TOL/DISTB). Every file has the same FILNAM (the program), as CMMs write them. Returns the file paths
/// in the order of the CSV rows.
std::vector<std::string> paperSeriesAsDmis(const metrofit::test::TempDir& tmp, const Model& model,
                                           const DmisSeriesLayout& layout) {
  const CsvTable t = readCsvFile(test::paperReportPath());
  std::map<std::string, std::string> files;
  std::vector<std::string> order;
  for (std::size_t r = 0; r < t.rowCount(); ++r) {
    const std::string part = t.cell(r, t.requireColumn("part"));
    const std::string dim = t.cell(r, t.requireColumn("dimension"));
    const std::string name =
        "part" + part + (layout.perPosition ? "_" + dim.substr(0, dim.find('.')) : std::string()) + ".dmo";
    if (!files.count(name)) {
      order.push_back(name);
      files[name] = "DMISMN/'paper example inspection',05.3\nFILNAM/'PAPER-EXAMPLE',05.3\n" +
                    (layout.serials ? "PARTSN/'" + part + "'\n" : std::string()) +
                    "UNITS/MM,ANGDEC\nF(DATUM_A)=FEAT/PLANE,CART,0,0,0,0,0,1\n";
    }
    if (layout.skip && layout.skip(part, dim)) continue;
    const double nominal = t.number(r, t.requireColumn("nominal_mm"));
    const double measured = t.number(r, t.requireColumn("measured_mm"));
    const int q = model.dimensionIndex(dim);
    EXPECT_GE(q, 0) << dim;
    if (q < 0) continue;
    std::string& f = files[name];
    if (q % 2 == 0) {
      f += "F(" + dim + ")=FEAT/POINT,CART,10,20," + num::general(nominal, 17) + ",0,0,1\n";
      f += "FA(" + dim + ")=FEAT/POINT,CART,10.002,19.999," + num::general(measured, 17) + ",0,0,1\n";
    } else {
      const Dimension& d = model.dimensions[static_cast<std::size_t>(q)];
      f += "T(" + dim + ")=TOL/DISTB,NOMINL," + num::general(nominal, 17) + "," + num::general(d.lower, 17) +
           "," + num::general(d.upper, 17) + "\n";
      f += "TA(" + dim + ")=TOL/DISTB," + num::general(measured - nominal, 17) + "\n";
    }
  }
  std::vector<std::string> paths;
  for (const std::string& name : order) {
    paths.push_back(tmp.file(name));
    metrofit::test::writeText(paths.back(), files[name] + "ENDFIL\n");
  }
  return paths;
}

/// The paper example's CSV series without the rows `skip` names, written to `name` in tmp.
std::string paperCsvWithout(const metrofit::test::TempDir& tmp, const std::string& name,
                            const std::function<bool(const std::string&, const std::string&)>& skip) {
  const std::string text = metrofit::test::readText(test::paperReportPath());
  std::string out;
  std::size_t pos = 0;
  while (pos < text.size()) {
    const auto nl = text.find('\n', pos);
    const std::string line = text.substr(pos, nl == std::string::npos ? std::string::npos : nl - pos + 1);
    pos = nl == std::string::npos ? text.size() : nl + 1;
    const auto c1 = line.find(','), c2 = line.find(',', c1 + 1), c3 = line.find(',', c2 + 1);
    const bool row = !line.empty() && line[0] != '#' && c3 != std::string::npos;
    if (row && skip(line.substr(0, c1), line.substr(c2 + 1, c3 - c2 - 1))) continue;
    out += line;
  }
  metrofit::test::writeText(tmp.file(name), out);
  return tmp.file(name);
}

/// The DMIS series gives the CSV series' deviations, samples, corrections and f1 (1e-12).
void expectSameAsCsv(const Model& model, const Measurements& dmis, const Measurements& csv) {
  EXPECT_EQ(dmis.rows.size(), csv.rows.size());
  ASSERT_EQ(dmis.deviationMm.size(), csv.deviationMm.size());
  for (std::size_t q = 0; q < csv.deviationMm.size(); ++q) {
    EXPECT_TRUE(near(dmis.deviationMm[q], csv.deviationMm[q], 1e-12)) << model.dimensions[q].id;
    EXPECT_EQ(dmis.samples[q], csv.samples[q]) << model.dimensions[q].id;
  }
  const ExactResult a = solveExact(SetupInstance(model, csv)), b = solveExact(SetupInstance(model, dmis));
  ASSERT_EQ(a.x.size(), b.x.size());
  for (std::size_t i = 0; i < a.x.size(); ++i) EXPECT_TRUE(near(a.x[i], b.x[i], 1e-12)) << i;
  EXPECT_TRUE(near(a.score.f1, b.score.f1, 1e-12));
}

TEST(DmisSeries, OneFilePerPartEqualsTheCsvSeries) {
  const Model model = readModel(test::paperModelPath());
  metrofit::test::TempDir tmp;
  const std::vector<std::string> paths = paperSeriesAsDmis(tmp, model, {});
  const Measurements csv = readMeasurements({test::paperReportPath()}, model);
  const Measurements dmis = readMeasurements(paths, model);
  // The same FILNAM in every file: part k is file k.
  EXPECT_EQ(dmis.parts, (std::vector<std::string>{"part1.dmo", "part2.dmo", "part3.dmo"}));
  EXPECT_EQ(csv.parts.size(), 3u);
  for (std::size_t q = 0; q < csv.samples.size(); ++q) EXPECT_EQ(csv.samples[q], 3) << q;
  expectSameAsCsv(model, dmis, csv);
  // PARTSN names the part.
  metrofit::test::TempDir tmp2;
  const Measurements serial = readMeasurements(paperSeriesAsDmis(tmp2, model, {true, false, {}}), model);
  EXPECT_EQ(serial.parts, csv.parts);
}

TEST(DmisSeries, OneFilePerFixturePositionPerPartEqualsTheCsvSeries) {
  // 3 measured fixtures x 4 positions = 12 files, each with only the 7 dimensions P<k>.D* of its
  // workpiece, all with the same FILNAM.
  const Model model = readModel(test::paperModelPath());
  const Measurements csv = readMeasurements({test::paperReportPath()}, model);
  metrofit::test::TempDir tmp;
  const std::vector<std::string> paths = paperSeriesAsDmis(tmp, model, {false, true, {}});
  ASSERT_EQ(paths.size(), 12u);
  const Measurements byFile = readMeasurements(paths, model);
  EXPECT_EQ(byFile.parts.size(), 12u);  // without PARTSN each file is a part, named by its file
  expectSameAsCsv(model, byFile, csv);
  // PARTSN (the CSV's part) groups the files of one measured fixture into one part, as the CSV groups
  // its rows by the part column.
  metrofit::test::TempDir tmp2;
  const Measurements bySerial = readMeasurements(paperSeriesAsDmis(tmp2, model, {true, true, {}}), model);
  EXPECT_EQ(bySerial.parts, csv.parts);
  expectSameAsCsv(model, bySerial, csv);
}

TEST(DmisSeries, ADimensionMissingInOneFileIsMeasuredByTheOthersAsInTheCsv) {
  const Model model = readModel(test::paperModelPath());
  const auto skip = [](const std::string& part, const std::string& dim) {
    return part == "2" && dim == "P2.D1";
  };
  metrofit::test::TempDir tmp;
  const Measurements csv = readMeasurements({paperCsvWithout(tmp, "series.csv", skip)}, model);
  EXPECT_EQ(csv.samples[static_cast<std::size_t>(model.dimensionIndex("P2.D1"))], 2);
  for (const bool perPosition : {false, true}) {
    metrofit::test::TempDir dir;
    const Measurements dmis =
        readMeasurements(paperSeriesAsDmis(dir, model, {true, perPosition, skip}), model);
    EXPECT_EQ(dmis.parts, csv.parts);
    expectSameAsCsv(model, dmis, csv);
  }
}

TEST(DmisSeries, ADimensionMeasuredByNoFileNamesTheDimensionAndTheFiles) {
  const Model model = readModel(test::paperModelPath());
  metrofit::test::TempDir tmp;
  const std::vector<std::string> paths = paperSeriesAsDmis(
      tmp, model, {false, true, [](const std::string&, const std::string& dim) { return dim == "P2.D1"; }});
  std::string files;
  for (const auto& p : paths) files += (files.empty() ? "" : ", ") + displayPath(p);
  try {
    (void)readMeasurements(paths, model);
    FAIL() << "no error";
  } catch (const ValidationError& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    EXPECT_EQ(what, "field 'dimension': no file of the series measures dimension 'P2.D1' of the model (" +
                        model.source + "); files read: " + files);
  }
  // A dimension measured twice within one file stays an error naming the file.
  const std::string twice = tmp.file("twice.dmo");
  metrofit::test::writeText(twice, metrofit::test::readText(paths[0]) + "TA(P1.D2)=TOL/DISTB,0.001\n");
  try {
    (void)readMeasurements({twice, paths[1]}, model);
    FAIL() << "no error";
  } catch (const ValidationError& e) {
    EXPECT_EQ(std::string(e.what()).rfind(displayPath(twice) + ":", 0), 0u) << e.what();
    EXPECT_NE(std::string(e.what()).find("duplicate TA statement for 'P1.D2'"), std::string::npos)
        << e.what();
  }
  // A file that measures no dimension of the model is an error naming the file.
  const std::string none = tmp.file("none.dmo");
  metrofit::test::writeText(none,
                            "FILNAM/'PAPER-EXAMPLE',05.3\nF(DATUM_A)=FEAT/PLANE,CART,0,0,0,0,0,1\nENDFIL\n");
  std::vector<std::string> withNone = paths;
  withNone.push_back(none);
  EXPECT_THROW((void)readMeasurements(withNone, model), ValidationError);
}

}  // namespace
}  // namespace metrofit::setup
