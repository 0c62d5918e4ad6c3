// r3_rowptr_antidiag (tests/adversary/): double** rows of nx, ny rows (contiguous); sizes in {{1,1},{2,1},{1,3},{3,2},{4,5}}.
#include "adv.hpp"
#include "r3_rowptr_antidiag_adjoint.hpp"
#include "r3_rowptr_antidiag_tangent.hpp"
#include <tuple>
void r3_rowptr_antidiag(double**, double**, int nx, int ny);
template <typename T> static std::vector<T*> r3rows(T* b, size_t ny, size_t nx) {
  std::vector<T*> r(ny); for (size_t j = 0; j < ny; ++j) r[j] = b + j * nx; return r;
}
TEST_CASE("adversary: r3_rowptr_antidiag") {
  for (auto [nx, ny] : std::initializer_list<std::tuple<int, int>>{{1,1},{2,1},{1,3},{3,2},{4,5}}) {
    CAPTURE(nx);
    CAPTURE(ny);
    auto R = [&](auto* b) { return r3rows(const_cast<double*>(b), size_t(ny), size_t(nx)); }; auto RI = [&](auto* b) { return r3rows(const_cast<double*>(b), size_t(nx + ny), size_t(nx)); };
    dpgen_test::Problem<double> p;
    p.in_sizes = {ADV_SZ((nx+ny)*nx)};
    p.out_sizes = {ADV_SZ(nx*ny)};
    p.forward = [&](auto in, auto out) { auto I0 = RI(in[0]); auto O0 = R(out[0]); r3_rowptr_antidiag(I0.data(), O0.data(), nx, ny); };
    p.adjoint = [&](auto in, auto adj, auto seed) { auto I0 = RI(in[0]); auto A0 = RI(adj[0]); auto S0 = R(seed[0]); r3_rowptr_antidiag_adjoint(I0.data(), A0.data(), S0.data(), nx, ny); };
    p.tangent = [&](auto in, auto dir, auto out, auto od) { auto I0 = RI(in[0]); auto D0 = RI(dir[0]); auto O0 = R(out[0]); auto T0 = R(od[0]); r3_rowptr_antidiag_tangent(I0.data(), D0.data(), O0.data(), T0.data(), nx, ny); };
    dpgen_test::check_adjoint(p);
  }
}
