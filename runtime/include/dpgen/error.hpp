// Errors the runtime throws and the helpers that build their messages. Library code never
// prints: every failure is an exception whose message says what went wrong and where.
#pragma once

#include <Eigen/Core>

#include <cmath>
#include <cstdio>
#include <sstream>
#include <stdexcept>
#include <string>

namespace dpgen {

namespace detail {

/// Formats a double compactly for messages ("3.2e-04", "1e-10", "0.5", "nan").
inline std::string format_number(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.3g", value);
  return buffer;
}

inline void append(std::ostringstream& out, double value) { out << format_number(value); }
inline void append(std::ostringstream& out, float value) { out << format_number(value); }
template <typename T> void append(std::ostringstream& out, const T& value) { out << value; }

/// Concatenates the arguments into one message; floating-point values use format_number.
template <typename... Args> std::string message(const Args&... args) {
  std::ostringstream out;
  (append(out, args), ...);
  return out.str();
}

/// Index of the first NaN or Inf entry of `v`, or -1 when every entry is finite.
inline Eigen::Index first_non_finite(const Eigen::Ref<const Eigen::VectorXd>& v) {
  for (Eigen::Index i = 0; i < v.size(); ++i)
    if (!std::isfinite(v[i]))
      return i;
  return -1;
}

/// Throws std::invalid_argument naming `what` when `v` holds a NaN or Inf entry.
inline void require_finite(const Eigen::Ref<const Eigen::VectorXd>& v, const std::string& where,
                           const std::string& what) {
  const Eigen::Index i = first_non_finite(v);
  if (i >= 0)
    throw std::invalid_argument(
        message(where, ": ", what, " contains ", format_number(v[i]), " at index ", i));
}

/// Throws std::invalid_argument when `actual` differs from `expected`.
inline void require_size(Eigen::Index actual, Eigen::Index expected, const std::string& where,
                         const std::string& what) {
  if (actual != expected)
    throw std::invalid_argument(
        message(where, ": ", what, " has size ", actual, ", expected ", expected));
}

} // namespace detail

} // namespace dpgen
