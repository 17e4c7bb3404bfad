#pragma once
// Shared helpers for Metrofit tests: temporary folders, file helpers, fuzzy comparison, and the
// paths ctest passes in (METROFIT_SOURCE_DIR, METROFIT_BIN_DIR, METROFIT_TEST_OUT).
#include <gtest/gtest.h>

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <string_view>

namespace metrofit::test {

/// A number as the files write it ('.' decimal mark), read independently of the test process's locale:
/// the locale matrix (tests/CMakeLists.txt, LOCALES) runs GUI tests with LC_ALL=de_DE.UTF-8 /
/// pl_PL.UTF-8, where std::stod stops at the '.'. Fails the test (and returns NaN) when `text` is not
/// exactly one number.
inline double cnumber(const std::string& text) {
  std::string_view t(text);
  while (!t.empty() && (t.front() == ' ' || t.front() == '\t')) t.remove_prefix(1);
  while (!t.empty() && (t.back() == ' ' || t.back() == '\t' || t.back() == '\r')) t.remove_suffix(1);
  if (!t.empty() && t.front() == '+') t.remove_prefix(1);
  double v = 0.0;
  const auto res = std::from_chars(t.data(), t.data() + t.size(), v);
  if (t.empty() || res.ec != std::errc() || res.ptr != t.data() + t.size()) {
    ADD_FAILURE() << "'" << text << "' is not a '.'-decimal number";
    return std::nan("");
  }
  return v;
}

inline std::string env(const char* name, const char* fallback = "") {
  const char* v = std::getenv(name);
  return v ? v : fallback;
}
inline std::filesystem::path sourceDir() {
  return env("METROFIT_SOURCE_DIR", ".");
}
inline std::filesystem::path binDir() {
  return env("METROFIT_BIN_DIR", "bin");
}
/// A file or folder of the real measured data (../shared/data/real next to the source tree, see its
/// README.md; not in the repository): $METROFIT_REAL_DATA, else <source>/../shared/data/real, else
/// /work/shared/data/real. A test that needs it skips when it is not there (GTEST_SKIP).
inline std::filesystem::path realData(const std::string& relative) {
  const std::string fromEnv = env("METROFIT_REAL_DATA");
  if (!fromEnv.empty()) return std::filesystem::path(fromEnv) / relative;
  const std::filesystem::path beside = sourceDir().parent_path() / "shared" / "data" / "real";
  if (std::filesystem::exists(beside)) return beside / relative;
  return std::filesystem::path("/work/shared/data/real") / relative;
}
/// Where a test cannot run (real data or a checking program absent) it skips with the reason; but
/// when the build was configured with the real data present (METROFIT_STRICT_SKIPS, set by
/// tests/CMakeLists.txt; CI runs packaging/install-deps.sh first, so the programs are there too), the
/// same condition is a failure: a wrong path or a missing package must not turn a check into a
/// silent skip.
inline bool strictSkips() {
  return env("METROFIT_STRICT_SKIPS") == "1";
}

/// Skips (or, under METROFIT_STRICT_SKIPS, fails) the current test when `required` does not exist.
#define METROFIT_REQUIRE_PATH(required)                                              \
  do {                                                                               \
    const std::filesystem::path metrofitRequired_ = (required);                      \
    if (!std::filesystem::exists(metrofitRequired_)) {                               \
      if (::metrofit::test::strictSkips())                                           \
        FAIL() << "not found: " << metrofitRequired_                                 \
               << " (the real data folder was there when the build was configured)"; \
      GTEST_SKIP() << "real data not here: " << metrofitRequired_;                   \
    }                                                                                \
  } while (0)

/// Skips (or, under METROFIT_STRICT_SKIPS, fails) the current test with `why`.
#define METROFIT_SKIP_UNLESS(condition, why)                                                      \
  do {                                                                                            \
    if (!(condition)) {                                                                           \
      if (::metrofit::test::strictSkips()) FAIL() << why << " (strict: METROFIT_STRICT_SKIPS=1)"; \
      GTEST_SKIP() << why;                                                                        \
    }                                                                                             \
  } while (0)

inline std::filesystem::path outDir() {
  std::filesystem::path p = env("METROFIT_TEST_OUT", "test-output");
  std::filesystem::create_directories(p);
  return p;
}

/// A fresh temporary folder, removed with its content when the object dies.
class TempDir {
 public:
  TempDir() {
    std::string tmpl = (std::filesystem::temp_directory_path() / "metrofit-test-XXXXXX").string();
    if (!::mkdtemp(tmpl.data())) throw std::runtime_error("mkdtemp failed");
    path_ = tmpl;
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  const std::filesystem::path& path() const { return path_; }
  std::string file(const std::string& name) const { return (path_ / name).string(); }

 private:
  std::filesystem::path path_;
};

inline void writeText(const std::string& path, const std::string& text) {
  std::ofstream f(path, std::ios::binary);
  f << text;
}

inline std::string readText(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  std::stringstream ss;
  ss << f.rdbuf();
  return ss.str();
}

/// |a - b| <= abs + rel * max(|a|, |b|)
inline ::testing::AssertionResult near(double a, double b, double abs, double rel = 0.0) {
  const double tol = abs + rel * std::max(std::abs(a), std::abs(b));
  if (std::abs(a - b) <= tol) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure()
         << a << " vs " << b << " differ by " << std::abs(a - b) << " > " << tol;
}

/// Files in a folder (names only), for "no file left behind" checks.
inline std::vector<std::string> listFolder(const std::filesystem::path& dir) {
  std::vector<std::string> out;
  for (const auto& e : std::filesystem::directory_iterator(dir)) out.push_back(e.path().filename().string());
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace metrofit::test
