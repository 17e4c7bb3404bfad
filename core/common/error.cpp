#include "core/common/error.h"

namespace metrofit {

std::string ErrorContext::prefix() const {
  std::string out;
  if (!file.empty()) {
    out = file;
    if (line > 0) {
      out += ':' + std::to_string(line);
      if (column > 0) out += ':' + std::to_string(column);
    }
  } else if (line > 0) {
    out = "line " + std::to_string(line);
    if (column > 0) out += ", column " + std::to_string(column);
  }
  if (!field.empty()) {
    if (!out.empty()) out += ": ";
    out += "field '" + field + "'";
  }
  return out;
}

static std::string compose(const ErrorContext& c, const std::string& what) {
  const std::string p = c.prefix();
  return p.empty() ? what : p + ": " + what;
}

Error::Error(ErrorContext context, std::string what)
    : std::runtime_error(compose(context, what)), context_(std::move(context)), detail_(std::move(what)) {}

}  // namespace metrofit
