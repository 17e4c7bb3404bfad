#pragma once
// Rules shared by the NC programs Metrofit writes (core/setup/export.h, core/machine/controller_frame.h).
#include <string>

namespace metrofit {

/// FANUC program numbers Metrofit writes: 1..7999. O8000-O8999 and O9000-O9999 are the machine
/// tool builder's macro ranges: with parameter 3202 bit 0 NE8 = 1 (bit 4 NE9 = 1) programs in them
/// can neither be edited nor REGISTERED, so a file with such a number does not load; O9000-O9029 are
/// moreover the programs that T, M and G codes call as macros (parameters 6050-6089), so a correction
/// program there could run in place of a macro. `why` says which parameter a number in those ranges
/// needs (FANUC Series 0i / 30i parameter manuals, parameter 3202).
bool fanucProgramNumberOk(int number, std::string* why);

}  // namespace metrofit
