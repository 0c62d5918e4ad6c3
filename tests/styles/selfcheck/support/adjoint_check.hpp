// Self-check of the style tests (tests/styles/selfcheck.sh, also for tests/adversary): stands in for
// tests/support/adjoint_check.hpp and replaces every Problem's adjoint by a
// finite-difference J^T w built from its forward kernel, so the tests and
// forward kernels are checked without dpgen (sizes, guard cells, ranges).
// The tangent and checked entry points are dropped (stubs).
#pragma once

#define check_adjoint check_adjoint_real
#include "../../../support/adjoint_check.hpp"
#undef check_adjoint

namespace dpgen_test {

template <typename T> Problem<T> with_fd_adjoint(Problem<T> p) {
  auto fwd = p.forward;
  auto ins = p.in_sizes, outs = p.out_sizes;
  const bool lin = p.linear;
  p.adjoint = [fwd, ins, outs, lin](const std::vector<const T*>& in, const std::vector<T*>& adj,
                                    const std::vector<const T*>& seed) {
    const double h = lin ? 1.0 : (sizeof(T) == 4 ? 1e-2 : 1e-6);
    std::vector<std::vector<T>> x(ins.size());
    for (size_t a = 0; a < ins.size(); ++a)
      x[a].assign(in[a], in[a] + ins[a]);
    auto run = [&]() {
      std::vector<std::vector<T>> y(outs.size());
      std::vector<const T*> ip;
      std::vector<T*> op;
      for (auto& v : x)
        ip.push_back(v.data());
      for (size_t k = 0; k < outs.size(); ++k) {
        y[k].assign(outs[k], T(0));
        op.push_back(y[k].data());
      }
      fwd(ip, op);
      double s = 0;
      for (size_t k = 0; k < outs.size(); ++k)
        for (size_t i = 0; i < outs[k]; ++i)
          s += double(y[k][i]) * double(seed[k][i]);
      return s;
    };
    for (size_t a = 0; a < ins.size(); ++a)
      for (size_t i = 0; i < ins[a]; ++i) {
        const T x0 = x[a][i];
        x[a][i] = T(double(x0) + h);
        double fp = run();
        x[a][i] = T(double(x0) - h);
        double fm = run();
        x[a][i] = x0;
        adj[a][i] = T(double(adj[a][i]) + (fp - fm) / (2 * h));
      }
  };
  p.tangent = nullptr;
  p.checked = nullptr;
  return p;
}

template <typename T> void check_adjoint(const Problem<T>& p, uint64_t seed = 20261121) {
  check_adjoint_real(with_fd_adjoint(p), seed);
}

} // namespace dpgen_test
