// dfq and calypso datasets (core/project/datasets.h, dataset_content.h): what `project list` and the
// "Show data" view see of a DFQ file and of Calypso _chr / _fet tables written here from their field lists.
#include <gtest/gtest.h>

#include <string>

#include "core/common/error.h"
#include "core/project/dataset_content.h"
#include "core/project/datasets.h"
#include "testsupport.h"

namespace metrofit {
namespace {

DatasetRef datasetOf(const char* kind, const std::string& path) {
  DatasetRef d;
  d.id = "d";
  d.kind = kind;
  d.path = path;
  return d;
}

// Two characteristics, three value sets; the second value of characteristic 2 removed (attribute 255).
const char* kDfq =
    "K0100 2\r\nK1001/1 4711\r\nK2001/1 1\r\nK2002/1 Durchmesser 12,5\r\nK2101/1 12.5\r\nK2110/1 12.49\r\n"
    "K2111/1 12.51\r\nK2001/2 2\r\nK2002/2 Tiefe\r\nK2101/2 8\r\n"
    "K0001/1 12.503\r\nK0001/2 8.01\r\nK0001/1 12.498\r\nK0001/2 8.02\r\nK0002/2 255\r\n"
    "K0001/1 12.501\r\nK0001/2 7.99\r\n";

TEST(CharacteristicDataset, DfqRowsPerCharacteristicAndPart) {
  test::TempDir tmp;
  const std::string file = tmp.file("w.dfq");
  test::writeText(file, kDfq);
  const DatasetContent c = readDatasetContentFile(file, datasetOf(dataset_kind::kDfq, file));
  EXPECT_EQ(c.shape, DatasetContent::Shape::Features);
  EXPECT_EQ(c.format, "Q-DAS DFQ file");
  ASSERT_EQ(c.features.size(), 5u);  // 3 + 2 valid values
  EXPECT_EQ(c.features[0].feature, "Durchmesser 12,5");
  EXPECT_EQ(c.features[0].part, "4711 #1");  // K1001 and the value set
  EXPECT_TRUE(test::near(*c.features[0].deviation, 0.003, 1e-9));
  EXPECT_TRUE(test::near(*c.features[0].upper, 0.01, 1e-12));
  EXPECT_EQ(c.features[2].feature, "Durchmesser 12,5");  // run 2 has no Tiefe: removed
  EXPECT_EQ(c.features[2].part, "4711 #2");
  const CsvTable t =
      readDatasetTable(tmp.path().string() + "/p.metrofit", datasetOf(dataset_kind::kDfq, file));
  EXPECT_EQ(t.header(), (std::vector<std::string>{"run", "date", "1.actual", "1.actual.dev", "2.actual",
                                                  "2.actual.dev"}));
  EXPECT_EQ(t.cell(1, 4), "");  // the removed value
}

TEST(CharacteristicDataset, CalypsoFeaturesAreProbePointsAlsoAsProbePointsKind) {
  test::TempDir tmp;
  const std::string file = tmp.file("b_fet.txt");
  test::writeText(file,
                  "planid\tpartnb\tid\ttype\tx\ty\tz\tx_nom\ty_nom\tz_nom\r\n"
                  "B\t1\tP1\tPoint\t10,01\t0\t0\t10\t0\t0\r\nB\t1\tP2\tPoint\t0\t10,01\t0\t0\t10\t0\r\n"
                  "B\t1\tP3\tPoint\t0\t0\t10,01\t0\t0\t10\r\n");
  for (const char* kind : {dataset_kind::kCalypso, dataset_kind::kProbePoints}) {
    const DatasetSummary s = summarizeDataset(tmp.path().string() + "/p.metrofit", datasetOf(kind, file));
    EXPECT_EQ(s.rows, 3) << kind;
    EXPECT_EQ(s.columns, (std::vector<std::string>{"id", "surface", "qx", "qy", "qz", "px", "py", "pz"}))
        << kind;
    const DatasetContent c = readDatasetContentFile(file, datasetOf(kind, file));
    EXPECT_EQ(c.shape, DatasetContent::Shape::Columns);
    EXPECT_EQ(c.table.numericColumn("px")[0], 10.01);
  }
  // A calypso dataset that is neither table: refused naming the file.
  test::writeText(tmp.file("x.txt"), "a\tb\n1\t2\n");
  try {
    (void)summarizeDataset(tmp.path().string() + "/p.metrofit",
                           datasetOf(dataset_kind::kCalypso, tmp.file("x.txt")));
    FAIL() << "no error";
  } catch (const ParseError& e) {
    EXPECT_NE(std::string(e.what()).find("x.txt:1: not a Zeiss Calypso table"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace metrofit
