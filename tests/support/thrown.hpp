// The message of the std::invalid_argument a call throws ("" if it throws
// none): how the tests read a checked entry point's refusal.
#pragma once

#include <functional>
#include <stdexcept>
#include <string>

namespace dpgen_test {

inline std::string thrown(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

} // namespace dpgen_test
