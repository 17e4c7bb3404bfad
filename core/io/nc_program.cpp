#include "core/io/nc_program.h"

namespace metrofit {

bool fanucProgramNumberOk(int number, std::string* why) {
  auto no = [&](const std::string& w) {
    if (why) *why = w;
    return false;
  };
  const std::string o = "O" + std::to_string(number);
  if (number >= 8000 && number <= 8999) {
    return no("the Fanuc program number " + o +
              " is in O8000-O8999, which parameter 3202 bit 0 (NE8) = 1 protects from editing and "
              "registration (the file would not load); choose 1..7999, or clear NE8 on the control");
  }
  if (number >= 9000 && number <= 9999) {
    return no("the Fanuc program number " + o +
              " is in O9000-O9999, which parameter 3202 bit 4 (NE9) = 1 protects from editing and "
              "registration (the file would not load; O9000-O9029 are also called by T/M/G codes as "
              "macros); choose 1..7999, or clear NE9 on the control");
  }
  if (number < 1 || number > 9999) return no("the Fanuc program number must be in 1..7999");
  return true;
}

}  // namespace metrofit
