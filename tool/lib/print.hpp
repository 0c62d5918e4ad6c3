// Printing IR expressions as C++ source (fmt based, precedence aware). The
// golden files depend on this printer only, never on Clang's.
#pragma once

#include "affine.hpp"
#include "ir.hpp"

#include <string>

namespace dpgen {

std::string print(const ExprP& e);
/// max(lo...) / min(hi...) of a bound set, as C++ ("std::max<int>({a, b})").
std::string print_max(const std::vector<Poly>& set, const std::string& int_type);
std::string print_min(const std::vector<Poly>& set, const std::string& int_type);
/// A real literal of type t ("2.0", "0.5f").
std::string real_literal(double v, Type t);

} // namespace dpgen
