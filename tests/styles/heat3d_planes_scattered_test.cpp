// heat3d_planes_scattered (tests/styles/): `double***` grids, every row its
// own heap block with guard cells (styles::ScatteredRows per plane), the
// adjoint and tangent taking planes of row pointers of the same shape.
#include "support/adjoint_check.hpp"

#include "dpgen/annotate.hpp"
#include "heat3d_planes_scattered_adjoint.hpp"
#include "heat3d_planes_scattered_tangent.hpp"
#include "styles_support.hpp"

#include <memory>
#include <tuple>
#include <vector>

DPGEN_KERNEL void heat3d_planes_scattered(DPGEN_IN double*** u, DPGEN_IN double*** k,
                                          DPGEN_OUT double*** un, int nx, int ny, int nz,
                                          double dt);

namespace {
// nz planes of ny scattered rows of nx elements, loaded from / saved to a flat buffer.
struct Planes {
  Planes(size_t nz, size_t ny, size_t nx) : ny_(ny), nx_(nx) {
    for (size_t m = nz; m-- > 0;) // last plane first
      rows_.insert(rows_.begin(), std::make_unique<styles::ScatteredRows<double>>(ny, nx));
    for (auto& r : rows_)
      ptrs_.push_back(r->data());
  }
  double*** data() { return ptrs_.data(); }
  void load(const double* flat) {
    for (size_t m = 0; m < rows_.size(); ++m)
      rows_[m]->load(flat + m * ny_ * nx_);
  }
  void save(double* flat) const {
    for (size_t m = 0; m < rows_.size(); ++m)
      rows_[m]->save(flat + m * ny_ * nx_);
  }
  bool guards_intact() const {
    for (const auto& r : rows_)
      if (!r->guards_intact())
        return false;
    return true;
  }
  size_t ny_, nx_;
  std::vector<std::unique_ptr<styles::ScatteredRows<double>>> rows_;
  std::vector<double**> ptrs_;
};
} // namespace

TEST_CASE("styles: heat3d_planes_scattered") {
  for (auto [nx, ny, nz] : {std::tuple{1, 1, 1}, {3, 3, 3}, {4, 3, 5}, {6, 5, 4}}) {
    CAPTURE(nx);
    CAPTURE(ny);
    CAPTURE(nz);
    const size_t n = size_t(nx * ny * nz), X = size_t(nx), Y = size_t(ny), Z = size_t(nz);
    const double dt = 0.05;
    bool guards = true;
    dpgen_test::Problem<double> p;
    p.in_sizes = {n, n};
    p.out_sizes = {n};
    p.forward = [&](auto in, auto out) {
      Planes u(Z, Y, X), k(Z, Y, X), un(Z, Y, X);
      u.load(in[0]), k.load(in[1]), un.load(out[0]);
      heat3d_planes_scattered(u.data(), k.data(), un.data(), nx, ny, nz, dt);
      un.save(out[0]);
      guards = guards && un.guards_intact();
    };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      Planes u(Z, Y, X), k(Z, Y, X), ua(Z, Y, X), ka(Z, Y, X), s(Z, Y, X);
      u.load(in[0]), k.load(in[1]), ua.load(adj[0]), ka.load(adj[1]), s.load(seed[0]);
      heat3d_planes_scattered_adjoint(u.data(), ua.data(), k.data(), ka.data(), s.data(), nx, ny,
                                      nz, dt);
      ua.save(adj[0]), ka.save(adj[1]);
      guards = guards && ua.guards_intact() && ka.guards_intact();
    };
    p.tangent = [&](auto in, auto dir, auto out, auto outd) {
      Planes u(Z, Y, X), k(Z, Y, X), ud(Z, Y, X), kd(Z, Y, X), un(Z, Y, X), und(Z, Y, X);
      u.load(in[0]), k.load(in[1]), ud.load(dir[0]), kd.load(dir[1]), un.load(out[0]),
          und.load(outd[0]);
      heat3d_planes_scattered_tangent(u.data(), ud.data(), k.data(), kd.data(), un.data(),
                                      und.data(), nx, ny, nz, dt);
      un.save(out[0]), und.save(outd[0]);
      guards = guards && un.guards_intact() && und.guards_intact();
    };
    dpgen_test::check_adjoint(p);
    CHECK(guards);
  }
}
