#pragma once
// How a DMIS output file's TA(label)=TOL/... values are read (core/setup/report.h, "DMIS output
// files"): writers differ on what the value means. A setting of the `setup` command line
// (--ta-meaning, --ta-sign) and of a dataset in the project file ("dmis": {"ta_meaning", "ta_sign"}).
#include <string>

namespace metrofit::setup {

/// What TA(label)=TOL/type,value means when the file has no F and FA to compute the deviation from.
enum class DmisTaMeaning {
  Auto,       ///< nearer the nominal than zero: the actual value; else the deviation
  Deviation,  ///< actual - nominal (DMIS output of CORTOL / PROFP as CMMs write it)
  Actual,     ///< the actual value (the QIF-to-DMIS converter's TOL/DIAM)
};
/// "auto" | "deviation" | "actual"; OptionsError naming `option` otherwise.
DmisTaMeaning parseDmisTaMeaning(const std::string& text, const std::string& option = "TA meaning");
/// The spelling parseDmisTaMeaning reads.
std::string dmisTaMeaningName(DmisTaMeaning meaning);
/// "plain" -> false, "nominal" -> true; OptionsError naming `option` otherwise.
bool parseDmisTaSign(const std::string& text, const std::string& option = "TA sign");

struct DmisOptions {
  DmisTaMeaning taMeaning = DmisTaMeaning::Auto;
  /// The writer reports sign(nominal) * (actual - nominal) (some do for negative nominals); the reader
  /// turns it back into actual - nominal.
  bool signFollowsNominal = false;
  bool operator==(const DmisOptions&) const = default;
};

}  // namespace metrofit::setup
