// Forced include of tests/core/locale_to_string_check.cmake: every std::to_string of a floating value is
// a compile error at its own call site ("use of deleted function ... mf_checked_to_string(double)").
// std::to_string(double) is printf("%f") in the process locale: "0,050000" under de_DE.UTF-8. Core,
// widgets and app use metrofit::num::toString / fixed / general (core/common/numformat.h) instead.
// Integral arguments pass through to std::to_string unchanged.
#include <string>
namespace std {  // NOLINT: a check-only header, never part of a build
inline string mf_checked_to_string(int v) {
  return to_string(v);
}
inline string mf_checked_to_string(long v) {
  return to_string(v);
}
inline string mf_checked_to_string(long long v) {
  return to_string(v);
}
inline string mf_checked_to_string(unsigned v) {
  return to_string(v);
}
inline string mf_checked_to_string(unsigned long v) {
  return to_string(v);
}
inline string mf_checked_to_string(unsigned long long v) {
  return to_string(v);
}
string mf_checked_to_string(float) = delete;
string mf_checked_to_string(double) = delete;
string mf_checked_to_string(long double) = delete;
}  // namespace std
#define to_string mf_checked_to_string
