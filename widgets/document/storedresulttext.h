#pragma once
// How a page names when a stored result (core/project/stored_results.h) was computed.
#include <QString>
#include <string>

namespace metrofit {

/// "2026-11-29 05:40 UTC" (the date and time in the UI language's short format) for the stored
/// "computed" value ("YYYY-MM-DDTHH:MM:SSZ"); "at an unknown time" when it is empty or unreadable.
QString storedTimeText(const std::string& computed);

}  // namespace metrofit
