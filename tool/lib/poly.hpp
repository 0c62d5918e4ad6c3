// Polynomials with integer coefficients over loop counters and sizes: the
// index algebra's values (affine.hpp) and the IR's conditions and counts on
// the sizes (ir.hpp: SizeCond, SizeCheck, Extent). Implemented in affine.cpp.
#pragma once

#include <map>
#include <string>
#include <utility>
#include <vector>

namespace dpgen {

/// A symbol of a polynomial: a loop counter, or a size, which is anything
/// fixed while the loops run (a parameter, a kernel-level local, a row or
/// plane symbol, a cell coordinate `c_i`, a cell bound `lo_i`). The kind keeps
/// a counter apart from a size of the same name.
struct Sym {
  enum class Kind : unsigned char { Counter, Size };
  Kind kind = Kind::Size;
  std::string name;

  static Sym counter(std::string name) { return {Kind::Counter, std::move(name)}; }
  static Sym size(std::string name) { return {Kind::Size, std::move(name)}; }
  bool is_counter() const { return kind == Kind::Counter; }
  /// Counters first, then by name. Monomials and the terms of a polynomial
  /// are ordered by it, which fixes the order of terms in generated code.
  bool operator<(const Sym& o) const { return kind != o.kind ? kind < o.kind : name < o.name; }
  bool operator==(const Sym& o) const { return kind == o.kind && name == o.name; }
  bool operator!=(const Sym& o) const { return !(*this == o); }
};

/// A polynomial with integer coefficients over symbols (sizes and loop
/// counters). A monomial is the sorted list of its symbols.
class Poly {
public:
  using Monomial = std::vector<Sym>;

  Poly() = default;
  static Poly constant(long long c);
  /// A size (a parameter, a local, ...: see Sym).
  static Poly symbol(const std::string& name) { return of(Sym::size(name)); }
  /// A loop counter.
  static Poly counter(const std::string& name) { return of(Sym::counter(name)); }
  static Poly of(const Sym& s);
  /// c times the product of the symbols of `m`.
  static Poly term(long long c, const Monomial& m);

  Poly operator+(const Poly& o) const;
  Poly operator-(const Poly& o) const;
  Poly operator*(const Poly& o) const;
  Poly operator-() const {
    Poly r = *this; // (the product with -1: every coefficient negated)
    for (auto& [m, c] : r.terms_)
      c = -c;
    return r;
  }
  bool operator==(const Poly& o) const { return terms_ == o.terms_; }
  bool operator<(const Poly& o) const { return terms_ < o.terms_; }

  bool is_constant() const;
  long long constant_term() const;
  bool mentions(const Sym& s) const;
  bool mentions_counter(const std::string& name) const { return mentions(Sym::counter(name)); }
  /// Some symbol is a loop counter.
  bool mentions_any_counter() const;
  /// Coefficient of `s` (which must occur with degree <= 1): a polynomial.
  Poly coefficient(const Sym& s) const;
  /// The polynomial without any term that mentions `s`.
  Poly without(const Sym& s) const;
  /// Highest total degree of any term (0 for constants).
  int degree() const;
  const std::map<Monomial, long long>& terms() const { return terms_; }
  /// C++ source, e.g. "j * nx + i - 1".
  std::string str() const;
  /// C++ source for generated code, where cell coordinates (`c_i`) are
  /// std::ptrdiff_t: each product starts with one of them, or with a
  /// parameter cast to std::ptrdiff_t, so no product of int sizes is computed
  /// in 32 bits.
  std::string code() const;

private:
  Poly plus(const Poly& o, long long sign) const; // *this + sign * o
  std::map<Monomial, long long> terms_; // no zero coefficients
};

} // namespace dpgen
