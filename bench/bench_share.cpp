// The pass `share` side by side with `dpgen --no-share` (scripts/bench_share.sh): the adjoint
// of the upwind step (u[i] / dx at three shifts: one division per cell instead of three), of a
// tanh limiter (tanh(d / w) at three shifts: one tanh per cell instead of three) and of a flux
// form that spells the speed per neighbour and branches on the face speeds (u[i - 1] / dx,
// u[i] / dx, u[i + 1] / dx in guarded terms too: one division per cell instead of 15), each
// generated both ways and linked into this one program under two names, called alternately
// on the same arrays; nanoseconds per cell, the fastest and the median of 31 alternating
// trials, on the threads OpenMP gives (OMP_NUM_THREADS).
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <vector>

void upwind_step_adjoint_share(const double*, double*, const double*, double*, const double*, int,
                               double, double);
void upwind_step_adjoint_noshare(const double*, double*, const double*, double*, const double*, int,
                                 double, double);
void limit_rho_adjoint_share(const double*, double*, const double*, int, double);
void limit_rho_adjoint_noshare(const double*, double*, const double*, int, double);
void flux_form_upwind_adjoint_share(const double*, double*, const double*, double*, const double*,
                                    int, double, double);
void flux_form_upwind_adjoint_noshare(const double*, double*, const double*, double*, const double*,
                                      int, double, double);

namespace {

// Fastest and median ns per cell of `a` and `b`, called alternately (trials of `cells`
// cells in all).
void side_by_side(const char* name, int n, const std::function<void(bool)>& call) {
  const int reps = std::max(1, (1 << 23) / n);
  std::vector<double> t[2];
  for (int trial = 0; trial < 31; ++trial)
    for (int v = 0; v < 2; ++v) {
      const auto t0 = std::chrono::steady_clock::now();
      for (int r = 0; r < reps; ++r)
        call(v == 0);
      const std::chrono::duration<double, std::nano> dt = std::chrono::steady_clock::now() - t0;
      t[v].push_back(dt.count() / (double(reps) * n));
    }
  for (auto& x : t)
    std::sort(x.begin(), x.end());
  std::printf("| %s | %d | %.2f / %.2f | %.2f / %.2f | %.2f |\n", name, n, t[1][0], t[1][15],
              t[0][0], t[0][15], t[0][15] / t[1][15]);
}

} // namespace

int main() {
  std::printf("threads: %d\n\n", omp_get_max_threads());
  std::printf("| adjoint | cells | --no-share ns/cell, fastest / median | share | share / "
              "no-share (medians) |\n|---|---|---|---|---|\n");
  for (int n : {4096, 65536, 1 << 20}) {
    std::vector<double> d(n), u(n), seed(n), d_adj(n, 0.0), u_adj(n, 0.0);
    for (int i = 0; i < n; ++i) {
      d[i] = std::sin(0.7 * i);
      u[i] = std::cos(1.3 * i) - 0.1;
      seed[i] = std::sin(0.31 * i + 1.0);
    }
    side_by_side("upwind_step", n, [&](bool share) {
      (share ? upwind_step_adjoint_share : upwind_step_adjoint_noshare)(
          d.data(), d_adj.data(), u.data(), u_adj.data(), seed.data(), n, 0.1, 0.3);
    });
    side_by_side("limit_rho (tanh)", n, [&](bool share) {
      (share ? limit_rho_adjoint_share : limit_rho_adjoint_noshare)(d.data(), d_adj.data(),
                                                                    seed.data(), n, 0.5);
    });
    side_by_side("flux_form_upwind", n, [&](bool share) {
      (share ? flux_form_upwind_adjoint_share : flux_form_upwind_adjoint_noshare)(
          d.data(), d_adj.data(), u.data(), u_adj.data(), seed.data(), n, 0.1, 0.3);
    });
  }
  return 0;
}
