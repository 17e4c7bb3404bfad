#pragma once
// Running a shell command from a packaging test: its standard output and exit status.
#include <sys/wait.h>
#include <cstdio>
#include <filesystem>
#include <string>

namespace metrofit::test {

/// Runs `command` with /bin/sh; returns its standard output (standard error is left alone unless the
/// command redirects it). *exitCode: the exit status, -1 when it did not exit normally.
inline std::string runCommand(const std::string& command, int* exitCode = nullptr) {
  std::string out;
  FILE* pipe = ::popen(command.c_str(), "r");
  if (!pipe) return out;
  char buffer[4096];
  std::size_t n = 0;
  while ((n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0) out.append(buffer, n);
  const int status = ::pclose(pipe);
  if (exitCode) *exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return out;
}

/// A path in single quotes for the shell.
inline std::string shellQuote(const std::filesystem::path& p) {
  return "'" + p.string() + "'";
}

/// True when `program` is on the PATH.
inline bool haveProgram(const std::string& program) {
  int code = -1;
  runCommand("command -v '" + program + "' >/dev/null 2>&1", &code);
  return code == 0;
}

}  // namespace metrofit::test
