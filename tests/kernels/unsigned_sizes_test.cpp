// unsigned_sizes (tests/kernels/unsigned_sizes.cpp): reversed indices with
// unsigned sizes, the i-- > 0 idiom, a size_t local, a vector's size().
#include "support/adjoint_check.hpp"

#include "unsigned_sizes_adjoint.hpp"
#include "unsigned_sizes_kernels.hpp"
#include "unsigned_sizes_tangent.hpp"

#include <vector>

TEST_CASE("unsigned sizes: reversed read with unsigned n") {
  for (unsigned n : {0u, 1u, 2u, 5u, 16u}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {n};
    p.out_sizes = {n};
    p.forward = [&](auto in, auto out) { reverse_unsigned(in[0], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) { reverse_unsigned_adjoint(in[0], adj[0], seed[0], n); };
    p.tangent = [&](auto in, auto dir, auto out, auto od) {
      reverse_unsigned_tangent(in[0], dir[0], out[0], od[0], n);
    };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      reverse_unsigned_adjoint_checked(in[0], in_n[0], adj[0], in_n[0], seed[0], out_n[0], n);
    };
    dpgen_test::check_adjoint(p);
  }
}

TEST_CASE("unsigned sizes: for (i = n; i-- > 0;) with a size_t local") {
  for (std::size_t n : {0u, 1u, 2u, 7u}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {n};
    p.out_sizes = {n};
    p.forward = [&](auto in, auto out) { countdown_size_t(in[0], out[0], n); };
    p.adjoint = [&](auto in, auto adj, auto seed) { countdown_size_t_adjoint(in[0], adj[0], seed[0], n); };
    p.tangent = [&](auto in, auto dir, auto out, auto od) {
      countdown_size_t_tangent(in[0], dir[0], out[0], od[0], n);
    };
    dpgen_test::check_adjoint(p);
  }
}

TEST_CASE("unsigned sizes: std::vector read back to front") {
  for (std::size_t n : {1u, 2u, 9u}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {n};
    p.out_sizes = {n};
    p.forward = [&](auto in, auto out) {
      std::vector<double> a(in[0], in[0] + n), o(out[0], out[0] + n);
      reverse_vector(a, o);
      std::copy(o.begin(), o.end(), out[0]);
    };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      std::vector<double> a(in[0], in[0] + n), aa(adj[0], adj[0] + n), s(seed[0], seed[0] + n);
      reverse_vector_adjoint(a, aa, s);
      std::copy(aa.begin(), aa.end(), adj[0]);
    };
    dpgen_test::check_adjoint(p);
  }
}
