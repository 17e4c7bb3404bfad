// The import's guesses for files as shops write them (issue 28 item 1): the kind from the content,
// roles by English, German and Polish names ignoring case, units from brackets. The files are written
// here from those conventions; the real Wenzel points (../shared/data/real/cmm-wenzel-lens-points) are
// read in place.
#include "core/project/import_guess.h"

#include <gtest/gtest.h>

#include "core/io/file_io.h"
#include "core/matching/probe_points.h"
#include "testsupport.h"

namespace metrofit {
namespace {

using Roles = std::vector<std::pair<std::string, std::string>>;

TEST(ImportGuess, ColumnNamesSplitIntoWordsAndTheirBracketUnit) {
  const ColumnName a = splitColumnName("Zeit [min]");
  EXPECT_EQ(a.words, (std::vector<std::string>{"zeit"}));
  EXPECT_EQ(a.unit, "min");
  EXPECT_EQ(splitColumnName("Verlagerung K3 [\xC2\xB5m]").unit, "um");
  EXPECT_EQ(splitColumnName("Temperatur T1 [\xC2\xB0"
                            "C]")
                .unit,
            "degC");
  EXPECT_EQ(splitColumnName("Drehzahl [1/min]").unit, "rpm");
  EXPECT_EQ(splitColumnName("Pr\xC4\x98"
                            "DKO\xC5\x9A\xC4\x86 (obr/min)")
                .words,
            (std::vector<std::string>{"predkosc"}));
  const ColumnName s = splitColumnName("Soll-X");
  EXPECT_EQ(s.words, (std::vector<std::string>{"soll", "x"}));
  EXPECT_EQ(splitColumnName("dev_um").unit, "um");
  EXPECT_EQ(splitColumnName("Ma\xC3\x9F").words, (std::vector<std::string>{"mass"}));
}

TEST(ImportGuess, AGermanThermalLogWithATitleLineIsAThermalLogWithTimeAndSpeed) {
  const std::string text =
      "Spindel-W\xC3\xA4rmegang DMU 50, Messung vom 01.05.2024\n"
      "Zeit [min];Temperatur T1 [\xC2\xB0"
      "C];Verlagerung K3 [\xC2\xB5m];Drehzahl [1/min]\n"
      "0;20,5;0,0;0\n0,25;20,7;1,25;1250\n";
  EXPECT_EQ(guessDatasetKind("Spindel_Waermegang.csv", text), "thermal-log");
  const std::vector<std::string> header{"Zeit [min]",
                                        "Temperatur T1 [\xC2\xB0"
                                        "C]",
                                        "Verlagerung K3 [\xC2\xB5m]", "Drehzahl [1/min]"};
  EXPECT_EQ(suggestColumnRoles("thermal-log", header),
            (Roles{{"time_min", "Zeit [min]"}, {"spindle_rpm", "Drehzahl [1/min]"}}));
}

TEST(ImportGuess, APolishThermalLogInSeconds) {
  const std::vector<std::string> header{"Czas [s]",
                                        "Temperatura T1 [\xC2\xB0"
                                        "C]",
                                        "Pr\xC4\x99"
                                        "dko\xC5\x9B\xC4\x87 obrotowa [obr/min]",
                                        "Przemieszczenie Z [\xC2\xB5m]"};
  EXPECT_EQ(suggestColumnRoles("thermal-log", header),
            (Roles{{"time_s", "Czas [s]"}, {"spindle_rpm", header[2]}}));
  // A feed speed is not the spindle speed; a time without a unit is not guessed.
  EXPECT_TRUE(suggestColumnRoles("thermal-log", {"Czas",
                                                 "Pr\xC4\x99"
                                                 "dko\xC5\x9B\xC4\x87 posuwu"})
                  .empty());
}

TEST(ImportGuess, AGermanCmmReportMapsSollIstAndTolerances) {
  const std::string text =
      "Teil;Merkmal;Soll [mm];Ist [mm];Untere Toleranz [mm];Obere Toleranz [mm];Zeit [min]\n"
      "1;D1;10,000;10,012;-0,02;0,02;0\n2;D1;10,000;10,015;-0,02;0,02;12\n";
  EXPECT_EQ(guessDatasetKind("bericht.csv", text), "cmm-report");
  const std::vector<std::string> header{
      "Teil",      "Merkmal", "Soll [mm]", "Ist [mm]", "Untere Toleranz [mm]", "Obere Toleranz [mm]",
      "Zeit [min]"};
  EXPECT_EQ(suggestColumnRoles("cmm-report", header), (Roles{{"part", "Teil"},
                                                             {"dimension", "Merkmal"},
                                                             {"nominal_mm", "Soll [mm]"},
                                                             {"measured_mm", "Ist [mm]"},
                                                             {"lower_tol_mm", "Untere Toleranz [mm]"},
                                                             {"upper_tol_mm", "Obere Toleranz [mm]"},
                                                             {"time_min", "Zeit [min]"}}));
  // Nominal / Aktuell; each role once (the µm column after "Aktuell" is left as it is).
  EXPECT_EQ(suggestColumnRoles("cmm-report", {"Nominal", "Aktuell", "Ist [\xC2\xB5m]"}),
            (Roles{{"nominal_mm", "Nominal"}, {"measured_mm", "Aktuell"}}));
}

// Values in another unit of the role's quantity are suggested and read converted (core/io/units.h);
// a temperature is never a length, a time without a unit is not guessed.
TEST(ImportGuess, ColumnsInOtherUnitsAreReadInTheRolesUnit) {
  const std::vector<std::string> header{"Teil",
                                        "Merkmal",
                                        "Soll [\xC2\xB5m]",
                                        "Ist [\xC2\xB5m]",
                                        "Untere Toleranz [\xC2\xB5m]",
                                        "Obere Toleranz [\xC2\xB5m]",
                                        "Zeit [h]",
                                        "Temperatur [\xC2\xB0"
                                        "C]"};
  const Roles roles = suggestColumnRoles("cmm-report", header);
  EXPECT_EQ(roles, (Roles{{"part", "Teil"},
                          {"dimension", "Merkmal"},
                          {"nominal_mm", header[2]},
                          {"measured_mm", header[3]},
                          {"lower_tol_mm", header[4]},
                          {"upper_tol_mm", header[5]},
                          {"time_min", "Zeit [h]"}}));
  CsvReadOptions o;
  o.columnMap = roles;
  const std::string csv =
      "Teil;Merkmal;Soll [\xC2\xB5m];Ist [\xC2\xB5m];Untere Toleranz [\xC2\xB5m];"
      "Obere Toleranz [\xC2\xB5m];Zeit [h];Temperatur [\xC2\xB0"
      "C]\n"
      "1;D1;10000;10012;-20;20;0,5;21,5\n";
  const CsvTable t = parseCsv(csv, "bericht.csv", o);
  const auto at = [&](const char* role) { return t.number(0, t.requireColumn(role)); };
  EXPECT_DOUBLE_EQ(at("nominal_mm"), 10.0);
  EXPECT_DOUBLE_EQ(at("measured_mm"), 10.012);
  EXPECT_DOUBLE_EQ(at("lower_tol_mm"), -0.02);
  EXPECT_DOUBLE_EQ(at("upper_tol_mm"), 0.02);
  EXPECT_DOUBLE_EQ(at("time_min"), 30.0);
  // Probe points in metres; a circular test's deviation in nm is read in µm, in mm as mm.
  EXPECT_EQ(suggestColumnRoles("probe-points", {"Punkt", "Soll X [m]", "Ist X [m]"}),
            (Roles{{"id", "Punkt"}, {"qx", "Soll X [m]"}, {"px", "Ist X [m]"}}));
  EXPECT_EQ(suggestColumnRoles("circular-test", {"Winkel [rad]", "Abweichung [nm]"}),
            (Roles{{"angle_deg", "Winkel [rad]"}, {"deviation_um", "Abweichung [nm]"}}));
  EXPECT_EQ(suggestColumnRoles("circular-test", {"Abweichung [mm]"}),
            (Roles{{"deviation_mm", "Abweichung [mm]"}}));
  EXPECT_TRUE(suggestColumnRoles("probe-points", {"Soll X [\xC2\xB0"
                                                  "C]"})
                  .empty());
}

TEST(ImportGuess, ProbePointsWithSollIstCoordinatesAndUpperCaseNames) {
  const std::vector<std::string> header{"ID",    "Soll X", "Soll Y", "Soll Z", "Ist X",
                                        "Ist Y", "Ist Z",  "I",      "J",      "K"};
  EXPECT_EQ(suggestColumnRoles("probe-points", header), (Roles{{"id", "ID"},
                                                               {"qx", "Soll X"},
                                                               {"qy", "Soll Y"},
                                                               {"qz", "Soll Z"},
                                                               {"px", "Ist X"},
                                                               {"py", "Ist Y"},
                                                               {"pz", "Ist Z"},
                                                               {"nx", "I"},
                                                               {"ny", "J"},
                                                               {"nz", "K"}}));
  EXPECT_EQ(guessDatasetKind("punkte.txt", "ID;Soll X;Soll Y;Soll Z;Ist X;Ist Y;Ist Z\n1;0;0;0;0,01;0;0\n"),
            "probe-points");
}

TEST(ImportGuess, TheRealWenzelPointsWithoutAnExtensionAreMeasuredProbePoints) {
  const auto path = test::realData("cmm-wenzel-lens-points/SPH1_1");
  METROFIT_REQUIRE_PATH(path);
  const std::string text = readFile(path.string());
  EXPECT_EQ(guessDatasetKind(path.string(), text), "probe-points");
  const std::vector<std::string> header{"ID", "x", "y", "z", "Residues", "\xC3\xB8"};
  EXPECT_EQ(suggestColumnRoles("probe-points", header),
            (Roles{{"id", "ID"}, {"px", "x"}, {"py", "y"}, {"pz", "z"}}));
}

TEST(ImportGuess, CircularTestsAndFilesThatAreNoneOfThese) {
  EXPECT_EQ(suggestColumnRoles("circular-test", {"Winkel [\xC2\xB0]", "Abweichung [\xC2\xB5m]"}),
            (Roles{{"angle_deg", "Winkel [\xC2\xB0]"}, {"deviation_um", "Abweichung [\xC2\xB5m]"}}));
  EXPECT_EQ(guessDatasetKind("kreis.csv", "Winkel [\xC2\xB0];Abweichung [\xC2\xB5m]\n0;1,2\n1;1,3\n"),
            "circular-test");
  EXPECT_EQ(guessDatasetKind("durchmesser.csv", "Durchmesser\n10,01\n10,02\n"), "feature-series");
  EXPECT_EQ(guessDatasetKind("model.json", "{}"), "setup-model");
  // Columns that already are the roles need no mapping.
  EXPECT_TRUE(suggestColumnRoles("thermal-log", {"time_min", "T1", "disp_z_um"}).empty());
}

// Probe points in metres, with the suggested mapping, are points in mm for posture matching.
TEST(ImportGuess, ProbePointsInMetresAreReadInMillimetres) {
  test::TempDir tmp;
  const std::string file = tmp.file("punkte.csv");
  test::writeText(file,
                  "Punkt;Soll X [m];Soll Y [m];Soll Z [m];I;J;K;Ist X [m];Ist Y [m];Ist Z [m]\n"
                  "1;0,1;0;0;1;0;0;0,10002;0;0\n"
                  "2;0;0,1;0;0;1;0;0;0,09999;0\n"
                  "3;0;0;0,1;0;0;1;0;0;0,10001\n");
  CsvReadOptions o;
  o.columnMap = suggestColumnRoles("probe-points", {"Punkt", "Soll X [m]", "Soll Y [m]", "Soll Z [m]", "I",
                                                    "J", "K", "Ist X [m]", "Ist Y [m]", "Ist Z [m]"});
  ASSERT_EQ(o.columnMap.size(), 10u);
  const ProbePointSet set = readProbePoints(file, 3, o);
  ASSERT_EQ(set.points.size(), 3u);
  EXPECT_EQ(set.points[0].id, "1");
  EXPECT_NEAR(set.points[0].nominal.x(), 100.0, 1e-12);
  EXPECT_NEAR(set.points[0].measured.x(), 100.02, 1e-12);
  EXPECT_NEAR(set.points[1].measured.y(), 99.99, 1e-12);
  EXPECT_NEAR(set.points[2].measured.z(), 100.01, 1e-12);
  EXPECT_NEAR(set.points[2].normal.z(), 1.0, 0.0) << "a normal has no unit";
}

TEST(ImportGuess, DfqAndCalypsoFilesByContentWhateverTheirNames) {
  // AQDEF K fields (here as a ".txt"), and Calypso tables by their column names (under other names).
  EXPECT_EQ(guessDatasetKind("messung.txt", "K0100 1\r\nK2001/1 1\r\nK0001/1 12.5\r\n"), "dfq");
  EXPECT_EQ(guessDatasetKind("export.csv", "\xEF\xBB\xBFK0100 2\r\n"), "dfq");
  EXPECT_EQ(guessDatasetKind("werte.txt",
                             "planid\tpartnb\tid\ttype\tidsymbol\tactual\tnominal\tuppertol\tlowertol\n"
                             "P\t1\tD1\tDiameter\t\t12,5\t12,5\t0,1\t-0,1\n"),
            "calypso");
  EXPECT_EQ(guessDatasetKind("punkte.txt",
                             "planid\tpartnb\tid\tx\ty\tz\tx_nom\ty_nom\tz_nom\n"
                             "P\t1\tP1\t1\t2\t3\t1\t2\t3\n"),
            "calypso");
  // A CSV with an "id" and "actual" column but neither planid nor partnb is no Calypso table.
  EXPECT_NE(guessDatasetKind("r.csv", "id,actual,nominal\nD1,1,1\n"), "calypso");
}

}  // namespace
}  // namespace metrofit
