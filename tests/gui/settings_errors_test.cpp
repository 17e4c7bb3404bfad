// A malformed study setting is never quietly replaced by a default: the matching page's status line
// and the kinematics page's message name the field, and a report over a setup model datum without a
// register number fails with the field named. The demo project with one value broken; offscreen.
#include <gtest/gtest.h>

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QLabel>
#include <QTemporaryDir>
#include <QUndoStack>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "app/gui/kinematicspage.h"
#include "app/gui/matchingpage.h"
#include "core/project/project.h"
#include "qtapp.h"
#include "widgets/document/demoproject.h"
#include "widgets/document/projectdocument.h"
#include "widgets/report/report.h"

namespace metrofit {
namespace {

class SettingsErrorsTest : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(dir_.isValid());
    projectPath_ = extractDemoProject(dir_.path());
  }
  /// Writes `value` at `pointer` into the project file (a hand-edited project).
  void breakSetting(const std::string& pointer, const nlohmann::json& value) {
    Project p = loadProject(projectPath_.toStdString());
    p.studies[nlohmann::json::json_pointer(pointer)] = value;
    saveProject(p, projectPath_.toStdString());
  }
  QTemporaryDir dir_;
  QString projectPath_;
};

QString matchingStatus(const MatchingPage& page) {
  const auto* status = page.findChild<QLabel*>(QStringLiteral("matchingStatus"));
  return status ? status->text() : QStringLiteral("(no status label)");
}

TEST_F(SettingsErrorsTest, MatchingPageShowsAMalformedToleranceInItsStatusLine) {
  breakSetting("/matching/tolerance_mm", "tight");
  ProjectDocument doc;
  doc.load(projectPath_);
  MatchingPage page(&doc);
  const QString status = matchingStatus(page);
  EXPECT_TRUE(status.contains(QStringLiteral("studies.matching.tolerance_mm"))) << status.toStdString();
  EXPECT_FALSE(status.contains(QStringLiteral("Not matched yet"))) << status.toStdString();
}

TEST_F(SettingsErrorsTest, MatchingPageShowsASettingBrokenByAnEditAndItsRepair) {
  ProjectDocument doc;
  doc.load(projectPath_);
  MatchingPage page(&doc);
  ASSERT_FALSE(matchingStatus(page).contains(QStringLiteral("studies.matching")));
  doc.setStudyValue(QStringLiteral("matching"), QStringLiteral("/allow_scale"), "sometimes",
                    QStringLiteral("break"));
  EXPECT_TRUE(matchingStatus(page).contains(QStringLiteral("studies.matching.allow_scale")))
      << matchingStatus(page).toStdString();
  doc.undoStack()->undo();
  ASSERT_TRUE(page.runNow());
  EXPECT_FALSE(matchingStatus(page).contains(QStringLiteral("studies.matching")))
      << matchingStatus(page).toStdString();
}

TEST_F(SettingsErrorsTest, KinematicsPageNamesAMalformedSetting) {
  breakSetting("/kinematics/dataset", 5);
  ProjectDocument doc;
  doc.load(projectPath_);
  KinematicsPage page(&doc);
  const auto* message = page.findChild<QLabel*>(QStringLiteral("kinematicsMessage"));
  ASSERT_NE(message, nullptr);
  EXPECT_TRUE(message->text().contains(QStringLiteral("studies.kinematics.dataset")))
      << message->text().toStdString();
  EXPECT_TRUE(page.errorMessage().contains(QStringLiteral("studies.kinematics.dataset")));
  EXPECT_EQ(page.study(), nullptr) << "no study identified with settings that were not read";
}

TEST_F(SettingsErrorsTest, ReportNamesTheFieldOfASetupDatumWithoutARegister) {
  // W1's register comes from its id's digits: without digits (and no "register") there is none.
  Project p = loadProject(projectPath_.toStdString());
  const DatasetRef* model = p.dataset("setup_model");
  ASSERT_NE(model, nullptr);
  const QString modelPath = QFileInfo(projectPath_).dir().filePath(QString::fromStdString(model->path));
  std::string text;
  {
    std::ifstream in(modelPath.toStdString());
    std::stringstream s;
    s << in.rdbuf();
    text = s.str();
  }
  std::string::size_type at = 0;
  int replaced = 0;
  while ((at = text.find("\"W1\"", at)) != std::string::npos) {
    text.replace(at, 4, "\"Wa\"");
    ++replaced;
  }
  ASSERT_GT(replaced, 1) << "the datum and its arcs";
  std::ofstream(modelPath.toStdString()) << text;
  // Only the setup study: the report is quick.
  Project only;
  only.name = p.name;
  for (const DatasetRef& d : p.datasets)
    if (d.id == "setup_model" || d.id == "setup_report") only.datasets.push_back(d);
  only.studies["setup"] = p.studies["setup"];
  saveProject(only, projectPath_.toStdString());

  // The model is checked when it is read: the report stops with the message naming the model's
  // field instead of drawing a table with a made-up register (the section's own error line is for a
  // model that passed that check).
  ReportOptions options;
  options.projectPath = projectPath_;
  options.resolutionDpi = 150;
  const QString pdf = dir_.filePath(QStringLiteral("report.pdf"));
  try {
    writeReport(loadProject(projectPath_.toStdString()), pdf, options);
    ADD_FAILURE() << "the report was written with a datum without a register";
  } catch (const std::exception& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("setup[0].register"), std::string::npos) << what;
    EXPECT_NE(what.find("'Wa'"), std::string::npos) << what;
  }
  EXPECT_FALSE(QFile::exists(pdf));
}

}  // namespace
}  // namespace metrofit
