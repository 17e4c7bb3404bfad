#pragma once
// Shared by the libFuzzer targets: every reader must either return a value or throw one
// of Metrofit's typed input errors (metrofit::InputError: ParseError, ValidationError, ...). Any
// other exception, a crash, a sanitizer report or a hang is a finding. Built only with
// -DMETROFIT_FUZZ=ON and clang (fuzz/run.sh).
#include <cstddef>
#include <cstdint>
#include <exception>
#include <string_view>

#include "core/common/error.h"

namespace metrofit::fuzz {

/// Runs `read` on the input; typed input errors are the expected "no", everything else aborts.
template <class F>
int expectValueOrInputError(const std::uint8_t* data, std::size_t size, F&& read) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    read(text);
  } catch (const InputError&) {
    // The documented outcome for bad input: one clear message (CLI exit 2).
  }
  return 0;
}

}  // namespace metrofit::fuzz
