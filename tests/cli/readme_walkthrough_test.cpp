// The README's command-line walkthrough, run as a newcomer runs it.
//
// Every ```sh block between "<!-- cli-walkthrough begin" and "<!-- cli-walkthrough end -->" in
// README.md is run as written, in order, in one shell (so `export PATH=...` and `cd` carry over),
// starting in a fresh folder that holds only `build`, a link to the build tree: the README says to
// start at the top of the clone, where `build/bin` is. PATH holds only the system folders, so the
// README's own `export PATH="$PWD/build/bin:$PATH"` is what finds the programs. The test fails on
// a non-zero exit code (naming the command), on a file a command names as its output (--out,
// --out-dir, --export-out, --gcode, --step-nc, > FILE) that is missing or empty afterwards, and on a
// "# columns a,b,c" comment that the header of the written CSV does not match.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "testsupport.h"

namespace metrofit::test {
namespace {

namespace fs = std::filesystem;

struct Command {
  std::string text;                  ///< as written, continuation lines included
  std::vector<std::string> outputs;  ///< files the command writes
  std::string columns;               ///< from "# columns a,b,c", else empty
};

/// The sh blocks between the walkthrough markers, one string per block.
std::vector<std::string> walkthroughBlocks(const std::string& readme) {
  const auto begin = readme.find("<!-- cli-walkthrough begin");
  const auto end = readme.find("<!-- cli-walkthrough end -->");
  std::vector<std::string> blocks;
  if (begin == std::string::npos || end == std::string::npos || end < begin) return blocks;
  const std::string section = readme.substr(begin, end - begin);
  std::size_t pos = 0;
  while ((pos = section.find("```sh\n", pos)) != std::string::npos) {
    const auto from = pos + 6;
    const auto to = section.find("```", from);
    if (to == std::string::npos) break;
    blocks.push_back(section.substr(from, to - from));
    pos = to + 3;
  }
  return blocks;
}

/// Shell words of a command (quotes removed) and its trailing comment (outside quotes).
void splitWords(const std::string& text, std::vector<std::string>* words, std::string* comment) {
  std::string word;
  bool inWord = false;
  char quote = 0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (quote) {
      if (c == quote) {
        quote = 0;
      } else {
        word += c;
      }
      continue;
    }
    if (c == '\'' || c == '"') {
      quote = c;
      inWord = true;
      continue;
    }
    if (c == '\\' && i + 1 < text.size() && text[i + 1] == '\n') {
      ++i;
      continue;
    }
    if (c == '#' && !inWord) {
      *comment = text.substr(i + 1);
      break;
    }
    if (c == ' ' || c == '\t' || c == '\n') {
      if (inWord) words->push_back(word);
      word.clear();
      inWord = false;
      continue;
    }
    if (c == '>' && !inWord) {
      words->push_back(">");
      continue;
    }
    word += c;
    inWord = true;
  }
  if (inWord) words->push_back(word);
}

std::vector<Command> parseCommands(const std::vector<std::string>& blocks) {
  std::vector<Command> commands;
  for (const std::string& block : blocks) {
    std::istringstream in(block);
    std::string line, pending;
    while (std::getline(in, line)) {
      if (pending.empty() && line.find_first_not_of(" \t") == std::string::npos) continue;
      pending += line;
      if (!line.empty() && line.back() == '\\') {
        pending += '\n';
        continue;
      }
      Command c;
      c.text = pending;
      pending.clear();
      std::vector<std::string> words;
      std::string comment;
      splitWords(c.text, &words, &comment);
      for (std::size_t i = 0; i + 1 < words.size(); ++i) {
        const std::string& w = words[i];
        if (w == "--out" || w == "--out-dir" || w == "--export-out" || w == "--gcode" || w == "--step-nc" ||
            w == ">") {
          c.outputs.push_back(words[i + 1]);
        }
      }
      std::istringstream cs(comment);
      std::string key;
      if (cs >> key && key == "columns") cs >> c.columns;
      commands.push_back(c);
    }
  }
  return commands;
}

/// Single-quoted for sh.
std::string shQuote(const std::string& s) {
  std::string out = "'";
  for (char c : s) {
    if (c == '\'') {
      out += "'\\''";
    } else {
      out += c;
    }
  }
  return out + "'";
}

/// Header row of a CSV: the first line that is not a '#' comment.
std::string csvHeader(const fs::path& file) {
  std::ifstream in(file);
  std::string line;
  while (std::getline(in, line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (!line.empty() && line[0] != '#') return line;
  }
  return {};
}

std::string readmeText() {
  return readText((sourceDir() / "README.md").string());
}

TEST(ReadmeWalkthrough, SectionIsMarkedAndParsed) {
  const auto blocks = walkthroughBlocks(readmeText());
  ASSERT_GE(blocks.size(), 3u) << "README.md: the cli-walkthrough markers or their sh blocks are missing";
  const auto commands = parseCommands(blocks);
  ASSERT_GE(commands.size(), 25u);
  EXPECT_EQ(commands.front().text, "export PATH=\"$PWD/build/bin:$PATH\"");
  // The parser itself: outputs and column comments are found (else the checks below check nothing).
  int outputs = 0, columns = 0;
  for (const Command& c : commands) {
    outputs += static_cast<int>(c.outputs.size());
    columns += c.columns.empty() ? 0 : 1;
  }
  EXPECT_GE(outputs, 12);
  EXPECT_GE(columns, 5);
  std::vector<std::string> words;
  std::string comment;
  splitWords("a --out 'x y.csv' > z.csv   # columns p,q", &words, &comment);
  EXPECT_EQ(words, (std::vector<std::string>{"a", "--out", "x y.csv", ">", "z.csv"}));
  EXPECT_EQ(comment, " columns p,q");
}

TEST(ReadmeWalkthrough, RunsAsWrittenFromAFreshFolder) {
  const auto commands = parseCommands(walkthroughBlocks(readmeText()));
  ASSERT_FALSE(commands.empty());

  TempDir tmp;
  const fs::path clone = tmp.path() / "clone";
  fs::create_directories(clone);
  fs::create_directories(tmp.path() / "home");
  fs::create_directory_symlink(fs::absolute(binDir()).parent_path(), clone / "build");
  const std::string steps = tmp.file("steps.txt");
  const std::string log = tmp.file("walkthrough.log");

  std::string script = "exec >" + shQuote(log) + " 2>&1\n";
  for (std::size_t i = 0; i < commands.size(); ++i) {
    script += "echo " + shQuote("+ " + commands[i].text) + "\n";
    script += commands[i].text + "\n";
    script += "__rc=$?; echo \"" + std::to_string(i) + " $__rc $PWD\" >> " + shQuote(steps) +
              "; [ \"$__rc\" -eq 0 ] || exit \"$__rc\"\n";
  }
  writeText(tmp.file("walkthrough.sh"), script);

  const std::string cmd =
      "cd " + shQuote(clone.string()) + " && env -i HOME=" + shQuote((tmp.path() / "home").string()) +
      " PATH=/usr/local/bin:/usr/bin:/bin" + " XDG_RUNTIME_DIR=" + shQuote(env("XDG_RUNTIME_DIR", "/tmp")) +
      " LANG=C.UTF-8 sh " + shQuote(tmp.file("walkthrough.sh"));
  const int status = std::system(cmd.c_str());
  const std::string output = readText(log);
  const std::string tail = output.size() > 4000 ? output.substr(output.size() - 4000) : output;

  // Which steps ran, with their exit code and folder.
  std::ifstream in(steps);
  std::vector<std::string> dirs(commands.size());
  std::size_t ran = 0;
  std::size_t index = 0;
  int rc = 0;
  std::string dir;
  while (in >> index >> rc >> dir) {
    ASSERT_LT(index, commands.size());
    EXPECT_EQ(rc, 0) << "README walkthrough: exit code " << rc << " from\n  " << commands[index].text
                     << "\noutput (end):\n"
                     << tail;
    dirs[index] = dir;
    ++ran;
  }
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0 && ran == commands.size())
      << "README walkthrough stopped after " << ran << " of " << commands.size()
      << " commands\noutput (end):\n"
      << tail;

  for (std::size_t i = 0; i < commands.size(); ++i) {
    for (const std::string& out : commands[i].outputs) {
      const fs::path file = fs::path(dirs[i]) / out;
      EXPECT_TRUE(fs::exists(file)) << file << " missing after\n  " << commands[i].text;
      if (fs::is_regular_file(file)) {
        EXPECT_GT(fs::file_size(file), 0u) << file << " empty after\n  " << commands[i].text;
        if (!commands[i].columns.empty()) {
          EXPECT_EQ(csvHeader(file), commands[i].columns)
              << file << ": the README's column comment does not match the file\n  " << commands[i].text;
        }
      }
    }
    if (!commands[i].columns.empty()) {
      EXPECT_FALSE(commands[i].outputs.empty())
          << "a columns comment without an output file: " << commands[i].text;
    }
  }
}

}  // namespace
}  // namespace metrofit::test
