// Printing IR expressions as C++ source (fmt based, precedence aware). The
// golden files depend on this printer only, never on Clang's.
#pragma once

#include "affine.hpp"
#include "ir.hpp"

#include <string>

namespace dpgen {

std::string print(const ExprP& e);
/// `e` as one operand of a `&&` chain: parenthesized where it binds more
/// loosely than `&&` (`(a || b) && c`, never `a || b && c`).
std::string print_conjunct(const ExprP& e);
/// The subscript of an element of an array with `levels` pointer levels
/// (pointer_levels(), ir.hpp) at this flat index: "[i + 1]" for a flat array;
/// for row pointers (levels 1, the flat index j * R + i with R the row symbol)
/// "[j][i]", and "[0][i]" where the row is 0 (no R in the index); planes
/// (levels 2) likewise "[k][j][i]". An array view (shape.view) is called
/// instead: "(k, j, i)", "(i + 1)".
std::string subscript(const ExprP& index, Shape shape);
std::string subscript(const Poly& index, Shape shape);
/// max(lo...) / min(hi...) of a bound set, as C++ ("std::max<int>({a, b})").
std::string print_max(const std::vector<Poly>& set, const std::string& int_type);
std::string print_min(const std::vector<Poly>& set, const std::string& int_type);
/// A real literal of type t ("2.0", "0.5f").
std::string real_literal(double v, Type t);
/// A store statement: "a[i] = v;", "a[i] += v;", or a min/max scan's
/// "a[i] = dpgen_max(a[i], v);" (Store::extremum), `target` the element.
std::string store_statement(const Store& s, const std::string& target, const std::string& value);
/// The store's operator in the textual IR: "=", "+=", "max=", "min=".
const char* store_operator(const Store& s);

} // namespace dpgen
