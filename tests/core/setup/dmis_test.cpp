// DMIS output as CMMs write it (core/setup/report.h). The texts are written from
// the statement syntax of the DMIS standard (ANSI/DMIS 105.2 Part 1, 5.3: FILNAM, DMISMN, UNITS,
// F/FA = FEAT/CIRCLE|CYLNDR|POINT,[INNER|OUTER,]CART,..., T/TA = TOL/DIAM|CORTOL|DISTB|PROFP,
// OUTPUT, ENDFIL), not from Metrofit's own writer; expected deviations are worked out by hand below.
#include <gtest/gtest.h>

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

/// The paper example's CSV series (3 parts x 28 dimensions) written as one DMIS output file per part:
/// even dimensions as nominal and actual points (F / FA along Z), odd ones as a tolerance definition
/// and its actual, the deviation (T / TA = TOL/DISTB). Every file has the same FILNAM (the program),
/// as CMMs write them; `serials` adds PARTSN/'S<part>'. Returns the file paths in part order.
std::vector<std::string> paperSeriesAsDmis(const metrofit::test::TempDir& tmp, const Model& model,
                                           bool serials, const std::string& skipInPart2 = {}) {
  const CsvTable t = readCsvFile(test::paperReportPath());
  std::map<std::string, std::string> files;
  std::vector<std::string> order;
  for (std::size_t r = 0; r < t.rowCount(); ++r) {
    const std::string part = t.cell(r, t.requireColumn("part"));
    const std::string dim = t.cell(r, t.requireColumn("dimension"));
    if (!files.count(part)) {
      order.push_back(part);
      files[part] = "DMISMN/'paper example inspection',05.3\nFILNAM/'PAPER-EXAMPLE',05.3\n" +
                    (serials ? "PARTSN/'S" + part + "'\n" : std::string()) +
                    "UNITS/MM,ANGDEC\nF(DATUM_A)=FEAT/PLANE,CART,0,0,0,0,0,1\n";
    }
    if (part == "2" && dim == skipInPart2) continue;
    const double nominal = t.number(r, t.requireColumn("nominal_mm"));
    const double measured = t.number(r, t.requireColumn("measured_mm"));
    const int q = model.dimensionIndex(dim);
    EXPECT_GE(q, 0) << dim;
    if (q < 0) continue;
    std::string& f = files[part];
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
  for (const std::string& part : order) {
    paths.push_back(tmp.file("part" + part + ".dmo"));
    metrofit::test::writeText(paths.back(), files[part] + "ENDFIL\n");
  }
  return paths;
}

TEST(DmisSeries, OneFilePerPartEqualsTheCsvSeries) {
  const Model model = readModel(test::paperModelPath());
  metrofit::test::TempDir tmp;
  const std::vector<std::string> paths = paperSeriesAsDmis(tmp, model, false);
  const Measurements csv = readMeasurements({test::paperReportPath()}, model);
  const Measurements dmis = readMeasurements(paths, model);
  // The same FILNAM in every file: part k is file k.
  EXPECT_EQ(dmis.parts, (std::vector<std::string>{"part1.dmo", "part2.dmo", "part3.dmo"}));
  EXPECT_EQ(csv.parts.size(), 3u);
  ASSERT_EQ(dmis.deviationMm.size(), csv.deviationMm.size());
  for (std::size_t q = 0; q < csv.deviationMm.size(); ++q) {
    EXPECT_TRUE(near(dmis.deviationMm[q], csv.deviationMm[q], 1e-12)) << model.dimensions[q].id;
    EXPECT_EQ(dmis.samples[q], 3) << model.dimensions[q].id;
  }
  // The setup study gives the same corrections.
  const ExactResult a = solveExact(SetupInstance(model, csv)), b = solveExact(SetupInstance(model, dmis));
  ASSERT_EQ(a.x.size(), b.x.size());
  for (std::size_t i = 0; i < a.x.size(); ++i) EXPECT_TRUE(near(a.x[i], b.x[i], 1e-12)) << i;
  EXPECT_TRUE(near(a.score.f1, b.score.f1, 1e-12));
  // PARTSN names the part.
  metrofit::test::TempDir tmp2;
  const Measurements serial = readMeasurements(paperSeriesAsDmis(tmp2, model, true), model);
  EXPECT_EQ(serial.parts, (std::vector<std::string>{"S1", "S2", "S3"}));
}

TEST(DmisSeries, ADimensionMissingInOneFileNamesTheFileAndTheDimension) {
  const Model model = readModel(test::paperModelPath());
  metrofit::test::TempDir tmp;
  const std::vector<std::string> paths = paperSeriesAsDmis(tmp, model, false, "P2.D1");
  try {
    (void)readMeasurements(paths, model);
    FAIL() << "no error";
  } catch (const ValidationError& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    EXPECT_EQ(what, displayPath(paths[1]) +
                        ": field 'dimension': the report has no measurement of dimension 'P2.D1' of the "
                        "model (" +
                        model.source +
                        "); each DMIS file is one part (here 'PAPER-EXAMPLE') "
                        "and must measure every dimension");
  }
}

}  // namespace
}  // namespace metrofit::setup
