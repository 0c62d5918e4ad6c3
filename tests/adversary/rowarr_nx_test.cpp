// rowarr_nx (tests/adversary/): `double (*a)[8]` with the row length nx a
// parameter. nx <= 8: a correct adjoint, no exception. nx > 8 reaches into the
// next row: the arrays are then sized so the forward stays in bounds (flat
// semantics) and the adjoint must either throw std::invalid_argument or be
// right; nx = 11 makes two iterations write one element: it must throw.
#include "adv.hpp"
#include "rowarr_nx_adjoint.hpp"
#include "rowarr_nx_tangent.hpp"
void rowarr_nx(const double (*a)[8], double (*b)[8], int ny, int nx);
using Row = double[8];
static const Row* cr(const double* p) { return reinterpret_cast<const Row*>(p); }
static Row* mr(double* p) { return reinterpret_cast<Row*>(p); }
static dpgen_test::Problem<double> problem(int ny, int nx) {
  dpgen_test::Problem<double> p;
  size_t sz = size_t(ny * 8 + (nx > 8 ? nx - 8 : 0));
  p.in_sizes = {sz};
  p.out_sizes = {sz};
  p.forward = [=](auto in, auto out) { rowarr_nx(cr(in[0]), mr(out[0]), ny, nx); };
  p.adjoint = [=](auto in, auto adj, auto seed) { rowarr_nx_adjoint(cr(in[0]), mr(adj[0]), cr(seed[0]), ny, nx); };
  p.tangent = [=](auto in, auto dir, auto out, auto od) { rowarr_nx_tangent(cr(in[0]), cr(dir[0]), mr(out[0]), mr(od[0]), ny, nx); };
  return p;
}
TEST_CASE("adversary: rowarr_nx valid") {
  for (int ny : {0, 1, 2, 3})
    for (int nx : {0, 1, 2, 3, 7, 8}) {
      CAPTURE(ny); CAPTURE(nx);
      dpgen_test::check_adjoint(problem(ny, nx));
    }
}
TEST_CASE("adversary: rowarr_nx past the row (right or throws)") {
  for (int ny : {1, 2, 3})
    for (int nx : {9, 10}) {
      CAPTURE(ny); CAPTURE(nx);
      std::vector<double> a(64, 0.5), adj(64, 0.0), seed(64, 1.0);
      bool threw = false;
      try { rowarr_nx_adjoint(cr(a.data()), mr(adj.data()), cr(seed.data()), ny, nx); }
      catch (const std::invalid_argument&) { threw = true; }
      if (!threw) dpgen_test::check_adjoint(problem(ny, nx));
    }
}
TEST_CASE("adversary: rowarr_nx throws when rows overlap") {
  for (int ny : {2, 3}) {
    CAPTURE(ny);
    std::vector<double> a(64, 0.5), adj(64, 0.0), seed(64, 1.0), b(64), bd(64);
    CHECK_THROWS_AS(rowarr_nx_adjoint(cr(a.data()), mr(adj.data()), cr(seed.data()), ny, 11), std::invalid_argument);
    CHECK_THROWS_AS(rowarr_nx_tangent(cr(a.data()), cr(a.data()), mr(b.data()), mr(bd.data()), ny, 11), std::invalid_argument);
  }
}
