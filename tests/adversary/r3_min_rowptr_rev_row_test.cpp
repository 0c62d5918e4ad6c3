// r3_min_rowptr_rev_row (tests/adversary/): double** rows of nx, ny rows (contiguous); sizes in {{0,0},{1,1},{2,1},{1,3},{3,2},{4,5}}.
#include "adv.hpp"
#include "r3_min_rowptr_rev_row_adjoint.hpp"
#include "r3_min_rowptr_rev_row_tangent.hpp"
#include <tuple>
void r3_min_rowptr_rev_row(double**, double**, int nx, int ny);
template <typename T> static std::vector<T*> r3rows(T* b, size_t ny, size_t nx) {
  std::vector<T*> r(ny); for (size_t j = 0; j < ny; ++j) r[j] = b + j * nx; return r;
}
TEST_CASE("adversary: r3_min_rowptr_rev_row") {
  for (auto [nx, ny] : std::initializer_list<std::tuple<int, int>>{{0,0},{1,1},{2,1},{1,3},{3,2},{4,5}}) {
    CAPTURE(nx);
    CAPTURE(ny);
    auto R = [&](auto* b) { return r3rows(const_cast<double*>(b), size_t(ny), size_t(nx)); };
    dpgen_test::Problem<double> p;
    p.in_sizes = {ADV_SZ(nx*ny)};
    p.out_sizes = {ADV_SZ(nx*ny)};
    p.forward = [&](auto in, auto out) { auto I0 = R(in[0]); auto O0 = R(out[0]); r3_min_rowptr_rev_row(I0.data(), O0.data(), nx, ny); };
    p.adjoint = [&](auto in, auto adj, auto seed) { auto I0 = R(in[0]); auto A0 = R(adj[0]); auto S0 = R(seed[0]); r3_min_rowptr_rev_row_adjoint(I0.data(), A0.data(), S0.data(), nx, ny); };
    p.tangent = [&](auto in, auto dir, auto out, auto od) { auto I0 = R(in[0]); auto D0 = R(dir[0]); auto O0 = R(out[0]); auto T0 = R(od[0]); r3_min_rowptr_rev_row_tangent(I0.data(), D0.data(), O0.data(), T0.data(), nx, ny); };
    dpgen_test::check_adjoint(p);
  }
}
