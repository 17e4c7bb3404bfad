// Desktop integration (issue 28): the launcher passes desktop-file-validate, the AppStream metainfo
// passes `appstreamcli validate --no-net` and shows the README's screenshots, the project file type
// is defined for shared-mime-info (the type the launcher and the metainfo name, the glob of the
// project files), and the install rules put the three where the desktop looks for them. The tools
// come with packaging/install-deps.sh; a test skips, naming the package, only when one is missing.
#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include "core/project/project.h"
#include "run_command.h"
#include "testsupport.h"

namespace metrofit {
namespace {

const std::string kMimeType = "application/x-metrofit-project";

std::filesystem::path packagingFile(const std::string& name) {
  return test::sourceDir() / "packaging" / name;
}

/// Every capture group 1 of `pattern` in `text`, in order.
std::vector<std::string> allMatches(const std::string& text, const std::string& pattern) {
  std::vector<std::string> found;
  const std::regex re(pattern);
  for (auto it = std::sregex_iterator(text.begin(), text.end(), re); it != std::sregex_iterator(); ++it)
    found.push_back((*it)[1]);
  return found;
}

/// The value of `key=` in the [Desktop Entry] group of a desktop file.
std::string desktopValue(const std::string& text, const std::string& key) {
  const std::vector<std::string> values = allMatches(text, "(?:^|\n)" + key + "=([^\n]*)");
  return values.empty() ? std::string() : values.front();
}

/// Width and height from a PNG's IHDR chunk; {0, 0} when the file is no PNG.
std::pair<std::uint32_t, std::uint32_t> pngSize(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  unsigned char header[24] = {};
  if (!in.read(reinterpret_cast<char*>(header), sizeof header)) return {0, 0};
  if (header[1] != 'P' || header[2] != 'N' || header[3] != 'G') return {0, 0};
  const auto be32 = [&](int at) {
    return (std::uint32_t{header[at]} << 24) | (std::uint32_t{header[at + 1]} << 16) |
           (std::uint32_t{header[at + 2]} << 8) | std::uint32_t{header[at + 3]};
  };
  return {be32(16), be32(20)};
}

#define REQUIRE_PROGRAM(program, package)                                   \
  METROFIT_SKIP_UNLESS(test::haveProgram(program),                          \
                       program " is not installed (Debian package " package \
                               ", installed by packaging/install-deps.sh): not checked")

TEST(DesktopFile, PassesDesktopFileValidate) {
  REQUIRE_PROGRAM("desktop-file-validate", "desktop-file-utils");
  int code = -1;
  const std::string out = test::runCommand(
      "desktop-file-validate " + test::shellQuote(packagingFile("metrofit.desktop")) + " 2>&1", &code);
  EXPECT_EQ(code, 0) << out;
  EXPECT_EQ(out, "") << "warnings and hints count too";
}

TEST(DesktopFile, OpensProjectFilesOfTheDefinedType) {
  const std::string desktop = test::readText(packagingFile("metrofit.desktop").string());
  EXPECT_EQ(desktopValue(desktop, "MimeType"), kMimeType + ";");
  // %f: the file a double click opens is passed to metrofit, which opens a project given to it.
  EXPECT_NE(desktopValue(desktop, "Exec").find("%f"), std::string::npos);
}

TEST(Metainfo, PassesAppstreamcliValidate) {
  REQUIRE_PROGRAM("appstreamcli", "appstream");
  int code = -1;
  const std::string out = test::runCommand(
      "appstreamcli validate --no-net " +
          test::shellQuote(packagingFile("io.github.metrofit.Metrofit.metainfo.xml")) + " 2>&1",
      &code);
  EXPECT_EQ(code, 0) << out;
  EXPECT_EQ(out.find("W:"), std::string::npos) << out;
  EXPECT_EQ(out.find("E:"), std::string::npos) << out;
}

TEST(Metainfo, ShowsTheReadmeScreenshotsAndNamesTheProjectType) {
  const std::string xml = test::readText(packagingFile("io.github.metrofit.Metrofit.metainfo.xml").string());
  EXPECT_EQ(allMatches(xml, "<mediatype>([^<]*)</mediatype>"), std::vector<std::string>{kMimeType});
  EXPECT_EQ(allMatches(xml, "<screenshot (type=\"default\")>").size(), 1u) << "one default screenshot";
  // Addresses of the project (the app id's GitHub organisation), not a placeholder domain.
  EXPECT_EQ(xml.find(".invalid"), std::string::npos);
  EXPECT_EQ(allMatches(xml, "<url type=\"homepage\">([^<]*)</url>"),
            std::vector<std::string>{"https://github.com/metrofit/metrofit"});
  const std::regex image(
      R"re(<image type="source" width="(\d+)" height="(\d+)">(https://[^<]*/docs/screenshots/([^/<]+\.png))</image>)re");
  std::set<std::string> shown;
  for (auto it = std::sregex_iterator(xml.begin(), xml.end(), image); it != std::sregex_iterator(); ++it) {
    const std::string name = (*it)[4];
    const auto png = test::sourceDir() / "docs" / "screenshots" / name;
    ASSERT_TRUE(std::filesystem::is_regular_file(png)) << name << " is not in docs/screenshots";
    const auto [width, height] = pngSize(png);
    EXPECT_EQ(std::to_string(width), (*it)[1].str()) << name;
    EXPECT_EQ(std::to_string(height), (*it)[2].str()) << name;
    shown.insert(name);
  }
  // Every picture of the README is offered, and nothing else.
  std::set<std::string> pictures;
  for (const auto& entry : std::filesystem::directory_iterator(test::sourceDir() / "docs" / "screenshots"))
    if (entry.path().extension() == ".png") pictures.insert(entry.path().filename().string());
  EXPECT_EQ(shown, pictures);
  EXPECT_EQ(allMatches(xml, "<caption>([^<]+)</caption>").size(), shown.size()) << "each has a caption";
}

TEST(MimeInfo, IsWellFormedXml) {
  REQUIRE_PROGRAM("xmllint", "libxml2-utils");
  int code = -1;
  const std::string out = test::runCommand(
      "xmllint --noout " + test::shellQuote(packagingFile("metrofit-mime.xml")) + " 2>&1", &code);
  EXPECT_EQ(code, 0) << out;
}

TEST(MimeInfo, DefinesTheTypeOfTheDesktopFileForProjectFiles) {
  const std::string xml = test::readText(packagingFile("metrofit-mime.xml").string());
  EXPECT_NE(xml.find("xmlns=\"http://www.freedesktop.org/standards/shared-mime-info\""), std::string::npos);
  EXPECT_EQ(allMatches(xml, "<mime-type type=\"([^\"]+)\""), std::vector<std::string>{kMimeType});
  EXPECT_EQ(allMatches(xml, "<glob pattern=\"([^\"]+)\""),
            std::vector<std::string>{std::string("*") + Project::kFileSuffix});
  EXPECT_FALSE(allMatches(xml, "<comment>([^<]+)</comment>").empty());
  // The same type as the launcher names.
  const std::string desktop = test::readText(packagingFile("metrofit.desktop").string());
  EXPECT_EQ(desktopValue(desktop, "MimeType"), kMimeType + ";");
}

TEST(MimeInfo, UpdateMimeDatabaseMapsProjectFilesToTheType) {
  REQUIRE_PROGRAM("update-mime-database", "shared-mime-info");
  test::TempDir dir;
  const auto packages = dir.path() / "mime" / "packages";
  std::filesystem::create_directories(packages);
  std::filesystem::copy_file(packagingFile("metrofit-mime.xml"),
                             packages / "io.github.metrofit.Metrofit.xml");
  int code = -1;
  const std::string out =
      test::runCommand("update-mime-database " + test::shellQuote(dir.path() / "mime") + " 2>&1", &code);
  ASSERT_EQ(code, 0) << out;
  EXPECT_EQ(out.find("Failed to parse"), std::string::npos) << out;
  const std::string globs = test::readText((dir.path() / "mime" / "globs2").string());
  EXPECT_NE(globs.find(kMimeType + ":*" + Project::kFileSuffix), std::string::npos) << globs;
}

// The install rules of the "desktop" component: the launcher under its application id (the
// metainfo's launchable), the metainfo, the MIME package; appstreamcli validates the installed tree.
TEST(DesktopIntegration, InstallRulesPutTheFilesWhereTheDesktopLooks) {
  const auto script = test::binDir().parent_path() / "packaging" / "cmake_install.cmake";
  ASSERT_TRUE(std::filesystem::exists(script)) << script;
  test::TempDir prefix;
  int code = -1;
  const std::string log =
      test::runCommand(std::string("'") + METROFIT_CMAKE_COMMAND + "' -DCMAKE_INSTALL_COMPONENT=desktop " +
                           test::shellQuote("-DCMAKE_INSTALL_PREFIX=" + prefix.path().string()) + " -P " +
                           test::shellQuote(script) + " 2>&1",
                       &code);
  ASSERT_EQ(code, 0) << log;
  const auto share = prefix.path() / "share";
  const auto desktop = share / "applications" / "io.github.metrofit.Metrofit.desktop";
  const auto metainfo = share / "metainfo" / "io.github.metrofit.Metrofit.metainfo.xml";
  const auto mime = share / "mime" / "packages" / "io.github.metrofit.Metrofit.xml";
  for (const auto& path : {desktop, metainfo, mime})
    EXPECT_TRUE(std::filesystem::is_regular_file(path)) << path;
  EXPECT_EQ(test::readText(mime.string()), test::readText(packagingFile("metrofit-mime.xml").string()));
  const std::string xml = test::readText(metainfo.string());
  EXPECT_EQ(allMatches(xml, "<launchable type=\"desktop-id\">([^<]+)</launchable>"),
            std::vector<std::string>{desktop.filename().string()});
  REQUIRE_PROGRAM("appstreamcli", "appstream");
  const std::string out = test::runCommand(
      "appstreamcli validate-tree --no-net " + test::shellQuote(prefix.path()) + " 2>&1", &code);
  EXPECT_EQ(code, 0) << out;
  EXPECT_EQ(out.find("E:"), std::string::npos) << out;
}

}  // namespace
}  // namespace metrofit
