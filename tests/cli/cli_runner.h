#pragma once
// Runs the built metrofit-cli for end-to-end tests: exit code, stdout and stderr of one call.
#include <sys/wait.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "testsupport.h"

namespace metrofit::test {

struct CliRun {
  int code = -1;
  std::string out, err;
};

/// Runs `metrofit-cli <args>` (shell words) inside `tmp`, capturing stdout and stderr.
inline CliRun cli(const std::string& args, const TempDir& tmp) {
  const std::string out = tmp.file(".stdout"), err = tmp.file(".stderr");
  const std::string cmd = "cd '" + tmp.path().string() + "' && '" + (binDir() / "metrofit-cli").string() +
                          "' " + args + " >'" + out + "' 2>'" + err + "'";
  const int status = std::system(cmd.c_str());
  CliRun r;
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = readText(out);
  r.err = readText(err);
  std::filesystem::remove(out);
  std::filesystem::remove(err);
  return r;
}

/// Number of line ends in s (one-line messages have exactly one).
inline int lines(const std::string& s) {
  return static_cast<int>(std::count(s.begin(), s.end(), '\n'));
}

}  // namespace metrofit::test
