// The manual pages (packaging/man) against the executables' --help: every subcommand and option that
// `metrofit-cli ... --help` and `metrofit --help` list is documented, the pages have the sections a
// reader looks for, their version is the build's, and groff renders them without a warning.
#include <gtest/gtest.h>

#include <cctype>
#include <cstdio>
#include <filesystem>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "metrofit/version.h"
#include "run_command.h"
#include "testsupport.h"

namespace metrofit {
namespace {

std::string run(const std::string& command, int* exitCode = nullptr) {
  return test::runCommand(command, exitCode);
}

std::string quote(const std::filesystem::path& p) {
  return test::shellQuote(p);
}

std::string cliHelp(const std::string& subcommand) {
  int code = -1;
  const std::string out =
      run(quote(test::binDir() / "metrofit-cli") + " " + subcommand + " --help 2>/dev/null", &code);
  EXPECT_EQ(code, 0) << "metrofit-cli " << subcommand << " --help";
  return out;
}

/// The names listed under "Subcommands:" of a CLI11 help text.
std::vector<std::string> subcommandsOf(const std::string& help) {
  std::vector<std::string> names;
  std::istringstream in(help);
  std::string line;
  bool inList = false;
  while (std::getline(in, line)) {
    if (line == "Subcommands:") {
      inList = true;
      continue;
    }
    if (!inList) continue;
    if (line.rfind("  ", 0) != 0 || line.size() < 3 || line[2] == ' ') break;
    names.push_back(line.substr(2, line.find(' ', 2) - 2));
  }
  return names;
}

/// Long options ("--name") at the start of the option lines of a help text, without --help.
std::set<std::string> optionsOf(const std::string& help) {
  std::set<std::string> options;
  static const std::regex optionLine(R"(^\s+(?:-\S, ?)*(--[a-z0-9][a-z0-9-]*))");
  std::istringstream in(help);
  std::string line;
  while (std::getline(in, line)) {
    std::smatch m;
    if (std::regex_search(line, m, optionLine) && m[1] != "--help" && m[1] != "--help-all")
      options.insert(m[1]);
  }
  return options;
}

/// The roff source as a reader would search it: font changes and break points out, "\-" as "-".
std::string plainRoff(const std::string& roff) {
  std::string s = std::regex_replace(roff, std::regex(R"(\\f[BIRP])"), "");
  s = std::regex_replace(s, std::regex(R"(\\:)"), "");
  s = std::regex_replace(s, std::regex(R"(\\-)"), "-");
  return s;
}

std::string manPage(const std::string& name) {
  const auto path = test::sourceDir() / "packaging" / "man" / (name + ".1");
  const std::string text = test::readText(path.string());
  EXPECT_FALSE(text.empty()) << path;
  return plainRoff(text);
}

/// Text of the `.SS` section whose title is `title` (quoted or not), up to the next .SS/.SH.
std::string subsection(const std::string& page, const std::string& title) {
  for (const std::string& head : {".SS \"" + title + "\"\n", ".SS " + title + "\n"}) {
    const auto start = page.find(head);
    if (start == std::string::npos) continue;
    const auto bodyStart = start + head.size();
    auto end = page.find("\n.S", bodyStart);
    return page.substr(bodyStart, end == std::string::npos ? std::string::npos : end - bodyStart);
  }
  return {};
}

/// True when `text` names `option` as a whole word ("--lang" is not found in "--language").
bool mentions(const std::string& text, const std::string& option) {
  for (auto at = text.find(option); at != std::string::npos; at = text.find(option, at + 1)) {
    const auto next = at + option.size();
    if (next == text.size()) return true;
    const char c = text[next];
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_')) return true;
  }
  return false;
}

void expectSections(const std::string& page, const std::vector<std::string>& sections) {
  for (const auto& s : sections) {
    const bool found = page.find("\n.SH " + s + "\n") != std::string::npos ||
                       page.find("\n.SH \"" + s + "\"\n") != std::string::npos;
    EXPECT_TRUE(found) << "section " << s;
  }
}

TEST(ManPages, HaveTheSectionsAndTheBuildVersion) {
  const std::string cli = manPage("metrofit-cli");
  const std::string gui = manPage("metrofit");
  expectSections(
      cli, {"NAME", "SYNOPSIS", "DESCRIPTION", "COMMANDS", "FILES", "EXIT STATUS", "EXAMPLES", "SEE ALSO"});
  expectSections(
      gui, {"NAME", "SYNOPSIS", "DESCRIPTION", "OPTIONS", "FILES", "EXIT STATUS", "EXAMPLES", "SEE ALSO"});
  const std::string version = std::string("\"metrofit ") + kVersion + "\"";
  EXPECT_NE(cli.find(".TH METROFIT-CLI 1 "), std::string::npos);
  EXPECT_NE(cli.find(version), std::string::npos) << "the .TH line names another version than " << kVersion;
  EXPECT_NE(gui.find(".TH METROFIT 1 "), std::string::npos);
  EXPECT_NE(gui.find(version), std::string::npos) << "the .TH line names another version than " << kVersion;
  // The exit codes (docs/file-formats.md#exit-status-and-output), each with its own tag.
  const std::string exits = cli.substr(cli.find("\n.SH EXIT STATUS"));
  for (const char* code : {"\n.B 0\n", "\n.B 1\n", "\n.B 2\n"})
    EXPECT_NE(exits.find(code), std::string::npos);
}

TEST(ManPages, CliPageDocumentsEverySubcommandAndOptionOfTheHelp) {
  const std::string page = manPage("metrofit-cli");
  const std::string top = cliHelp("");
  const std::vector<std::string> families = subcommandsOf(top);
  ASSERT_GE(families.size(), 9u) << top;  // demo report setup match kinematic spc thermal diagnose simulate
  for (const std::string& option : optionsOf(top)) EXPECT_TRUE(mentions(page, option)) << option;
  int leaves = 0;
  for (const std::string& family : families) {
    const std::string help = cliHelp(family);
    const std::vector<std::string> subs = subcommandsOf(help);
    std::vector<std::string> paths;
    // A family with its own options besides subcommands (setup, setup validate) is checked too.
    if (subs.empty() || !optionsOf(help).empty()) paths.push_back(family);
    for (const std::string& sub : subs) paths.push_back(family + " " + sub);
    for (const std::string& path : paths) {
      ++leaves;
      const std::string section = subsection(page, path);
      EXPECT_FALSE(section.empty()) << "no .SS \"" << path << "\" in metrofit-cli.1";
      // Options common to a family may be documented once, in the family's section
      // (diagnose: "diagnose thermal|kinematic|setup|matching").
      std::string familySection;
      if (!subs.empty()) {
        std::string all = family + " ";
        for (std::size_t i = 0; i < subs.size(); ++i) all += (i ? "|" : "") + subs[i];
        familySection = subsection(page, all);
      }
      for (const std::string& option : optionsOf(cliHelp(path))) {
        EXPECT_TRUE(mentions(section, option) || mentions(familySection, option))
            << "metrofit-cli " << path << " " << option << " is not in its section of metrofit-cli.1";
      }
    }
  }
  EXPECT_GE(leaves, 21);  // 5 single subcommands, kinematic 2, thermal 5, diagnose 4, simulate 5
}

TEST(ManPages, GuiPageDocumentsEveryOptionOfTheHelp) {
  int code = -1;
  const std::string help =
      run("QT_QPA_PLATFORM=offscreen " + quote(test::binDir() / "metrofit") + " --help 2>/dev/null", &code);
  ASSERT_EQ(code, 0);
  const std::set<std::string> options = optionsOf(help);
  EXPECT_TRUE(options.count("--screenshots")) << help;
  EXPECT_TRUE(options.count("--version")) << help;
  const std::string page = manPage("metrofit");
  for (const std::string& option : options)
    EXPECT_TRUE(mentions(page, option)) << option << " is not in metrofit.1";
}

TEST(ManPages, CliHelpPointsToTheManualAndNamesTheExitCodes) {
  for (const std::string& sub : {std::string(), std::string("setup"), std::string("kinematic identify")}) {
    const std::string help = cliHelp(sub);
    EXPECT_NE(help.find("Exit status: 0 success, 2 bad input"), std::string::npos) << sub;
    EXPECT_NE(help.find("man metrofit-cli"), std::string::npos) << sub;
  }
}

TEST(ManPages, GroffPrintsNoWarnings) {
  METROFIT_SKIP_UNLESS(!run("command -v man").empty(),
                       "man (man-db) is not installed: groff warnings not checked");
  for (const char* name : {"metrofit", "metrofit-cli"}) {
    const auto path = test::sourceDir() / "packaging" / "man" / (std::string(name) + ".1");
    int code = -1;
    // stderr only: the rendered page goes to /dev/null.
    const std::string warnings = run(
        "MANWIDTH=80 LC_ALL=C.UTF-8 man -l --warnings -E UTF-8 " + quote(path) + " 2>&1 >/dev/null", &code);
    EXPECT_EQ(code, 0) << name;
    EXPECT_EQ(warnings, "") << name;
    const std::string text =
        run("MANWIDTH=80 LC_ALL=C.UTF-8 man -l -E UTF-8 " + quote(path) + " 2>/dev/null");
    EXPECT_NE(text.find("SYNOPSIS"), std::string::npos) << name;
  }
}

TEST(ManPages, BuildInstallsTheSameTextGzipped) {
  const auto buildMan = test::binDir().parent_path() / "packaging" / "man";
  for (const char* name : {"metrofit.1", "metrofit-cli.1"}) {
    const auto gz = buildMan / (std::string(name) + ".gz");
    ASSERT_TRUE(std::filesystem::exists(gz)) << gz;
    const std::string unpacked = run("gzip -dc " + quote(gz));
    const std::string source = test::readText((test::sourceDir() / "packaging" / "man" / name).string());
    EXPECT_EQ(unpacked, source) << name << ": rebuild (the .gz is made at build time)";
    // gzip -n: no name or time stamp in the header (bytes 4-7 are the mtime), so builds are reproducible.
    const std::string header = test::readText(gz.string()).substr(0, 10);
    ASSERT_EQ(header.size(), 10u);
    EXPECT_EQ(header.substr(4, 4), std::string(4, '\0')) << name;
  }
}

// The package's install rules put the user documentation into share/doc/metrofit, where --help and
// the manual page say it is: the install script of the build is run for the "docs" component into a
// temporary prefix (the .deb is made by cpack from the same rules, with every component).
TEST(Packaging, InstallsTheDocumentationIntoTheDocFolder) {
  const auto script = test::binDir().parent_path() / "packaging" / "cmake_install.cmake";
  ASSERT_TRUE(std::filesystem::exists(script)) << script;
  test::TempDir prefix;
  int code = -1;
  run(quote(METROFIT_CMAKE_COMMAND) + " -DCMAKE_INSTALL_COMPONENT=docs " +
          quote("-DCMAKE_INSTALL_PREFIX=" + prefix.path().string()) + " -P " + quote(script) + " 2>&1",
      &code);
  ASSERT_EQ(code, 0);
  const auto docDir = prefix.path() / "share" / "doc" / "metrofit";
  for (const char* name : {"file-formats.md", "references.md", "README.md", "bad-input-catalogue.md"}) {
    ASSERT_TRUE(std::filesystem::is_regular_file(docDir / name)) << docDir / name;
    EXPECT_EQ(test::readText((docDir / name).string()),
              test::readText((test::sourceDir() / "docs" / name).string()))
        << name;
  }
  // Help › Manual opens the installed README.md: every relative link of the installed documents leads
  // to an installed file (a link into the source tree would be dead there).
  static const std::regex link(R"(\]\(([^)#:]+)(#[^)]*)?\))");
  for (const auto& entry : std::filesystem::directory_iterator(docDir)) {
    if (entry.path().extension() != ".md") continue;
    const std::string text = test::readText(entry.path().string());
    for (auto it = std::sregex_iterator(text.begin(), text.end(), link); it != std::sregex_iterator(); ++it) {
      const std::string target = (*it)[1];
      EXPECT_TRUE(std::filesystem::exists(docDir / target))
          << entry.path().filename() << " links to " << target << ", which is not installed";
    }
  }
  // The manual page and the help name that path.
  const std::string installed = "/usr/share/doc/metrofit/file-formats.md";
  EXPECT_NE(manPage("metrofit-cli").find(installed), std::string::npos);
  EXPECT_NE(cliHelp("").find(installed), std::string::npos);
}

}  // namespace
}  // namespace metrofit
