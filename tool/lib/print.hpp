// Printing IR expressions as C++ source (fmt based, precedence aware). The
// golden files depend on this printer only, never on Clang's.
#pragma once

#include "affine.hpp"
#include "ir.hpp"

#include <string>

namespace dpgen {

std::string print(const ExprP& e);
/// The subscript of an array element with this flat index: "[i + 1]", or for
/// a row-pointer array (the index mentions its row symbol R: j * R + i)
/// "[j][i]".
std::string subscript(const ExprP& index);
std::string subscript(const Poly& index);
/// max(lo...) / min(hi...) of a bound set, as C++ ("std::max<int>({a, b})").
std::string print_max(const std::vector<Poly>& set, const std::string& int_type);
std::string print_min(const std::vector<Poly>& set, const std::string& int_type);
/// A real literal of type t ("2.0", "0.5f").
std::string real_literal(double v, Type t);

} // namespace dpgen
