// scatter_reads (tests/styles/): scatter-form adjoints. On small sizes each against
// differences and the dot-product test (support/adjoint_check.hpp); on sizes of 8192
// iterations and more (where the gathers go parallel) the adjoint on 1, 2 and 3 threads
// bit for bit, accumulated into nonzero adjoints, and the dot-product test against the
// tangent. The inputs send many iterations to the same elements.
#include "dpgen/annotate.hpp"
#include "scatter_reads_adjoint.hpp"
#include "scatter_reads_kernels.hpp"
#include "scatter_reads_tangent.hpp"
#include "support/adjoint_check.hpp"

#include "same_bits.hpp"

#include <omp.h>

#include <cmath>
#include <cstring>
#include <functional>
#include <numeric>
#include <vector>

namespace {

using dpgen_test::wavy;

template <typename T> std::vector<T> cast(const std::vector<double>& v) {
  return std::vector<T>(v.begin(), v.end());
}

template <typename T> double dot(const std::vector<T>& a, const std::vector<T>& b) {
  double s = 0.0;
  for (size_t i = 0; i < a.size(); ++i)
    s += double(a[i]) * double(b[i]);
  return s;
}

// A kernel's adjoint and tangent at fixed inputs: adjoint(adj, seed) adds into adj (one
// vector per input), tangent(dir, out_dot) fills the output's tangent.
template <typename T> struct Large {
  std::vector<size_t> in_sizes;
  size_t out_size = 0;
  std::function<void(std::vector<std::vector<T>>&, const std::vector<T>&)> adjoint;
  std::function<void(const std::vector<std::vector<T>>&, std::vector<T>&)> tangent;
};

template <typename T> void check_large(const Large<T>& c, double tolerance) {
  const std::vector<T> seed = cast<T>(wavy(c.out_size, 0.4, 3.0));
  const int saved = omp_get_max_threads();
  std::vector<std::vector<T>> first;
  for (int threads : {1, 2, 3}) {
    CAPTURE(threads);
    omp_set_num_threads(threads);
    std::vector<std::vector<T>> adj;
    for (size_t i = 0; i < c.in_sizes.size(); ++i) // nonzero: the adjoints accumulate
      adj.push_back(cast<T>(wavy(c.in_sizes[i], 2.0 + double(i))));
    c.adjoint(adj, seed);
    if (threads == 1) {
      first = adj;
      continue;
    }
    for (size_t i = 0; i < adj.size(); ++i)
      CHECK(std::memcmp(adj[i].data(), first[i].data(), sizeof(T) * adj[i].size()) == 0);
  }
  omp_set_num_threads(saved);
  // <seed, J dir> = <J^T seed, dir>, the adjoints from zero
  std::vector<std::vector<T>> dir, adj;
  for (size_t i = 0; i < c.in_sizes.size(); ++i) {
    dir.push_back(cast<T>(wavy(c.in_sizes[i], 0.9 + double(i))));
    adj.emplace_back(c.in_sizes[i], T(0));
  }
  c.adjoint(adj, seed);
  std::vector<T> out_dot(c.out_size);
  c.tangent(dir, out_dot);
  double lhs = dot(seed, out_dot), rhs = 0.0, scale = 0.0;
  for (size_t i = 0; i < dir.size(); ++i) {
    rhs += dot(adj[i], dir[i]);
    for (size_t e = 0; e < dir[i].size(); ++e)
      scale += std::fabs(double(adj[i][e]) * double(dir[i][e]));
  }
  CHECK(std::fabs(lhs - rhs) <= tolerance * scale);
}

// A kernel of inputs `in_sizes` (values drawn in `ranges`) and one output: on a small size
// the checker (differences, dot-product test, tangent), else check_large. fwd, adj and tan
// take vectors of pointers, as dpgen_test::Problem's functions do.
template <typename T, typename F, typename A, typename G>
void check_kernel(bool small, std::vector<size_t> in_sizes, size_t out_size, F fwd, A adj, G tan,
                  std::vector<std::pair<double, double>> ranges) {
  if (small) {
    dpgen_test::Problem<T> p;
    p.in_sizes = in_sizes;
    p.out_sizes = {out_size};
    p.in_ranges = ranges;
    p.forward = fwd;
    p.adjoint = adj;
    p.tangent = tan;
    dpgen_test::check_adjoint(p);
    return;
  }
  std::vector<std::vector<T>> in;
  std::vector<const T*> in_ptrs;
  for (size_t i = 0; i < in_sizes.size(); ++i) {
    std::vector<double> v = wavy(in_sizes[i], 0.2 + 0.5 * double(i), 1.0);
    for (double& x : v) // into [lo, hi]
      x = ranges[i].first + (ranges[i].second - ranges[i].first) * (0.5 + x / 14.0);
    in.push_back(cast<T>(v));
  }
  for (const auto& v : in)
    in_ptrs.push_back(v.data());
  Large<T> c;
  c.in_sizes = in_sizes;
  c.out_size = out_size;
  c.adjoint = [&](std::vector<std::vector<T>>& a, const std::vector<T>& seed) {
    std::vector<T*> ap;
    for (auto& v : a)
      ap.push_back(v.data());
    adj(in_ptrs, ap, std::vector<const T*>{seed.data()});
  };
  c.tangent = [&](const std::vector<std::vector<T>>& dir, std::vector<T>& out_dot) {
    std::vector<const T*> dp;
    for (const auto& v : dir)
      dp.push_back(v.data());
    std::vector<T> out(out_size);
    tan(in_ptrs, dp, std::vector<T*>{out.data()}, std::vector<T*>{out_dot.data()});
  };
  check_large(c, sizeof(T) == 4 ? 1e-5 : 1e-12);
}

// Velocities that trace far: past the clamped edges (many cells to the same corner cells).
std::vector<double> far(size_t n, double phase, double reach) {
  std::vector<double> v = wavy(n, phase, 1.0);
  for (double& x : v)
    x *= reach;
  return v;
}

} // namespace

TEST_CASE("styles: scatter adjoints, bilinear trace back (2D flat, clamped)") {
  for (auto [nx, ny] : {std::pair{3, 2}, std::pair{5, 4}, std::pair{160, 120}}) {
    CAPTURE(nx);
    CAPTURE(ny);
    const size_t n = size_t(nx) * ny;
    const double dt = 0.9;
    if (n < 100) {
      dpgen_test::Problem<double> p;
      p.in_sizes = {n, n, n};
      p.out_sizes = {n};
      p.in_ranges = {{-1.0, 1.0}, {-2.0, 2.0}, {-2.0, 2.0}};
      p.forward = [&](auto in, auto out) {
        trace_bilinear(in[0], in[1], in[2], out[0], nx, ny, dt);
      };
      p.adjoint = [&](auto in, auto adj, auto seed) {
        trace_bilinear_adjoint(in[0], adj[0], in[1], adj[1], in[2], adj[2], seed[0], nx, ny, dt);
      };
      p.tangent = [&](auto in, auto dir, auto out, auto outd) {
        trace_bilinear_tangent(in[0], dir[0], in[1], dir[1], in[2], dir[2], out[0], outd[0], nx, ny,
                               dt);
      };
      dpgen_test::check_adjoint(p);
      continue;
    }
    const std::vector<double> s = wavy(n, 0.1, 2.0), u = far(n, 0.3, 40.0), v = far(n, 0.7, 30.0);
    Large<double> c;
    c.in_sizes = {n, n, n};
    c.out_size = n;
    c.adjoint = [&](auto& adj, const auto& seed) {
      trace_bilinear_adjoint(s.data(), adj[0].data(), u.data(), adj[1].data(), v.data(),
                             adj[2].data(), seed.data(), nx, ny, dt);
    };
    c.tangent = [&](const auto& dir, auto& out_dot) {
      std::vector<double> out(n);
      trace_bilinear_tangent(s.data(), dir[0].data(), u.data(), dir[1].data(), v.data(),
                             dir[2].data(), out.data(), out_dot.data(), nx, ny, dt);
    };
    check_large(c, 1e-12);
  }
}

// The other kernels: n inputs of one kind, the same checks. `small` and `large`: sizes of the
// checker and of check_large.
TEST_CASE("styles: scatter adjoints, lookups, C89, branches, 3D, lambda") {
  const int m = 37; // table sizes: many iterations per element
  std::vector<int> idx(40000);
  for (size_t i = 0; i < idx.size(); ++i)
    idx[i] = int((i * 7919) % m);
  for (int n : {1, 6, 40000}) {
    CAPTURE(n);
    const size_t N = size_t(n), M = size_t(m);
    const bool small = n < 100;
    {
      INFO("lookup_index");
      const auto fwd = [&](auto in, auto out) {
        lookup_index(in[0], in[1], idx.data(), out[0], n);
      };
      const auto adj = [&](auto in, auto a, auto seed) {
        lookup_index_adjoint(in[0], a[0], in[1], a[1], idx.data(), seed[0], n);
      };
      const auto tan = [&](auto in, auto dir, auto out, auto outd) {
        lookup_index_tangent(in[0], dir[0], in[1], dir[1], idx.data(), out[0], outd[0], n);
      };
      check_kernel<double>(small, {M + 1, N}, N, fwd, adj, tan, {{-1.0, 1.0}, {-1.0, 1.0}});
    }
    {
      INFO("table_float");
      // (the checker's differences step by 1e-2 in float: bins of width 1 in x)
      const float scale = 1.0f;
      const auto fwd = [&](auto in, auto out) { table_float(in[0], in[1], out[0], n, m, scale); };
      const auto adj = [&](auto in, auto a, auto seed) {
        table_float_adjoint(in[0], a[0], in[1], a[1], seed[0], n, m, scale);
      };
      const auto tan = [&](auto in, auto dir, auto out, auto outd) {
        table_float_tangent(in[0], dir[0], in[1], dir[1], out[0], outd[0], n, m, scale);
      };
      check_kernel<float>(small, {M + 1, N}, N, fwd, adj, tan, {{-1.0, 1.0}, {-3.0, 40.0}});
    }
    {
      INFO("gather_c89");
      const unsigned np = unsigned(n), nc = unsigned(m);
      const auto fwd = [&](auto in, auto out) { gather_c89(in[0], in[1], out[0], np, nc); };
      const auto adj = [&](auto in, auto a, auto seed) {
        gather_c89_adjoint(in[0], a[0], in[1], a[1], seed[0], np, nc);
      };
      const auto tan = [&](auto in, auto dir, auto out, auto outd) {
        gather_c89_tangent(in[0], dir[0], in[1], dir[1], out[0], outd[0], np, nc);
      };
      check_kernel<double>(small, {M, N}, N, fwd, adj, tan, {{-1.0, 1.0}, {-3.0, 40.0}});
    }
    {
      INFO("lookup_branch");
      const auto fwd = [&](auto in, auto out) { lookup_branch(in[0], in[1], out[0], n, m); };
      const auto adj = [&](auto in, auto a, auto seed) {
        lookup_branch_adjoint(in[0], a[0], in[1], a[1], seed[0], n, m);
      };
      const auto tan = [&](auto in, auto dir, auto out, auto outd) {
        lookup_branch_tangent(in[0], dir[0], in[1], dir[1], out[0], outd[0], n, m);
      };
      check_kernel<double>(small, {M, N}, N, fwd, adj, tan, {{-1.0, 1.0}, {-1.0, 9.0}});
    }
    {
      INFO("lambda_wrap");
      const double dt = 3.5;
      const auto fwd = [&](auto in, auto out) { lambda_wrap(in[0], in[1], out[0], n, dt); };
      const auto adj = [&](auto in, auto a, auto seed) {
        lambda_wrap_adjoint(in[0], a[0], in[1], a[1], seed[0], n, dt);
      };
      const auto tan = [&](auto in, auto dir, auto out, auto outd) {
        lambda_wrap_tangent(in[0], dir[0], in[1], dir[1], out[0], outd[0], n, dt);
      };
      check_kernel<double>(small, {N, N}, N, fwd, adj, tan, {{-1.0, 1.0}, {-20.0, 20.0}});
    }
    {
      INFO("shift_planes");
      const int nx = n < 100 ? 2 : 40, ny = n < 100 ? 1 : 25, nz = n < 100 ? n : 40;
      const size_t C = size_t(nx) * ny * nz;
      const auto fwd = [&](auto in, auto out) { shift_planes(in[0], in[1], out[0], nx, ny, nz); };
      const auto adj = [&](auto in, auto a, auto seed) {
        shift_planes_adjoint(in[0], a[0], in[1], a[1], seed[0], nx, ny, nz);
      };
      const auto tan = [&](auto in, auto dir, auto out, auto outd) {
        shift_planes_tangent(in[0], dir[0], in[1], dir[1], out[0], outd[0], nx, ny, nz);
      };
      check_kernel<double>(small, {C, C}, C, fwd, adj, tan, {{-1.0, 1.0}, {-30.0, 30.0}});
    }
  }
}
