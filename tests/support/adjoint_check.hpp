// Checks a forward kernel against its adjoint on random inputs:
//  1. the dot-product test <J v, w> = <v, J^T w>, with J v from central
//     differences (exact for a linear kernel, where h = 1);
//  2. a finite-difference gradient of the scalar loss L = sum(0.5 f^2 + w f),
//     every input component;
//  3. the += contract: adjoints accumulate into what the caller passed;
//  4. no out-of-bounds access: every array sits between guard cells, NaN
//     around what the kernels read and a signaling NaN around the adjoints
//     they write (any arithmetic on it returns a quiet NaN, other bits: even
//     an added empty sum, -0.0, shows, which leaves every number as it was).
// Include after doctest.h.
#pragma once

#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <functional>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace dpgen_test {

template <typename T> struct Problem {
  using Forward = std::function<void(const std::vector<const T*>&, const std::vector<T*>&)>;
  using Adjoint = std::function<void(const std::vector<const T*>&, const std::vector<T*>&,
                                     const std::vector<const T*>&)>;
  std::vector<size_t> in_sizes, out_sizes;
  std::vector<std::pair<double, double>> in_ranges; // default [-1, 1]
  using Tangent = std::function<void(const std::vector<const T*>&, const std::vector<const T*>&,
                                     const std::vector<T*>&, const std::vector<T*>&)>;
  Forward forward;
  Adjoint adjoint; // (inputs, input adjoints (+=), output seeds)
  Tangent tangent; // optional: (inputs, directions, outputs, output tangents)
  /// optional: the checked entry point, called like `adjoint` with the
  /// arrays' sizes (in_sizes, out_sizes) passed along.
  std::function<void(const std::vector<const T*>&, const std::vector<T*>&,
                     const std::vector<const T*>&, const std::vector<size_t>&,
                     const std::vector<size_t>&)>
      checked;
  bool linear = false;
};

// An array with `pad` guard cells on each side.
template <typename T> class Guarded {
public:
  static constexpr size_t pad = 16;
  Guarded(size_t n, T guard) : data_(n + 2 * pad, guard), n_(n), guard_(guard) {}
  T* data() { return data_.data() + pad; }
  const T* data() const { return data_.data() + pad; }
  T& operator[](size_t i) { return data()[i]; }
  T operator[](size_t i) const { return data()[i]; }
  size_t size() const { return n_; }
  bool guards_intact() const {
    for (size_t i = 0; i < pad; ++i)
      if (!same(data_[i]) || !same(data_[pad + n_ + i]))
        return false;
    return true;
  }

private:
  // Bit for bit: a signaling-NaN guard catches even `+= -0.0` (it turns quiet).
  bool same(T v) const { return std::memcmp(&v, &guard_, sizeof(T)) == 0; }
  std::vector<T> data_;
  size_t n_;
  T guard_;
};

template <typename T> struct Tolerances {
  double fd_step, dot_rel, grad_rel;
};

template <typename T> Tolerances<T> tolerances(bool linear) {
  if constexpr (sizeof(T) == 4)
    return {linear ? 1.0 : 1e-2, linear ? 1e-5 : 2e-3, 1e-2};
  else
    return {linear ? 1.0 : 1e-6, linear ? 1e-12 : 1e-7, 1e-6};
}

template <typename T> class Checker {
public:
  Checker(const Problem<T>& p, uint64_t seed) : p_(p), rng_(seed) {}

  void run() {
    x_ = random_inputs();
    dot_product_test();
    gradient_test();
    accumulate_test();
    if (p_.tangent)
      tangent_test();
    if (p_.checked)
      checked_test();
  }

  // The checked entry point with the arrays' true sizes: no exception, and
  // exactly the raw adjoint's result.
  void checked_test() {
    Arrays w = random_like(p_.out_sizes);
    Arrays raw = adjoint(x_, w, zeros(p_.in_sizes));
    Arrays got = zeros(p_.in_sizes);
    try {
      p_.checked(cptrs(x_), ptrs(got), cptrs(w), p_.in_sizes, p_.out_sizes);
    } catch (const std::exception& e) {
      FAIL("the checked adjoint rejected the true sizes: " << e.what());
    }
    for (const auto& arr : got)
      REQUIRE_MESSAGE(arr.guards_intact(), "checked adjoint wrote outside an input adjoint");
    int bad = 0;
    for (size_t a = 0; a < raw.size(); ++a)
      for (size_t i = 0; i < raw[a].size(); ++i)
        if (std::memcmp(&raw[a][i], &got[a][i], sizeof(T)) != 0)
          ++bad;
    CHECK_MESSAGE(bad == 0, bad << " cells of the checked adjoint differ from the raw one");
  }

private:
  using Arrays = std::vector<Guarded<T>>;
  const Problem<T>& p_;
  std::mt19937_64 rng_;
  Arrays x_;

  double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng_); }

  Arrays make(const std::vector<size_t>& sizes, T guard) {
    Arrays a;
    for (size_t n : sizes)
      a.emplace_back(n, guard);
    return a;
  }

  Arrays random_inputs() {
    Arrays x = make(p_.in_sizes, T(NAN));
    for (size_t a = 0; a < x.size(); ++a) {
      auto [lo, hi] = a < p_.in_ranges.size() ? p_.in_ranges[a] : std::pair{-1.0, 1.0};
      for (size_t i = 0; i < x[a].size(); ++i)
        x[a][i] = T(uniform(lo, hi));
    }
    return x;
  }

  Arrays random_like(const std::vector<size_t>& sizes, double scale = 1.0) {
    Arrays v = make(sizes, T(NAN));
    for (auto& arr : v)
      for (size_t i = 0; i < arr.size(); ++i)
        arr[i] = T(scale * uniform(-1, 1));
    return v;
  }

  static std::vector<const T*> cptrs(const Arrays& a) {
    std::vector<const T*> p;
    for (const auto& x : a)
      p.push_back(x.data());
    return p;
  }
  static std::vector<T*> ptrs(Arrays& a) {
    std::vector<T*> p;
    for (auto& x : a)
      p.push_back(x.data());
    return p;
  }

  // Outputs start at zero, so cells a kernel does not write compare equal.
  Arrays forward(const Arrays& x) {
    Arrays y = make(p_.out_sizes, T(-7777));
    forward_into(x, y);
    return y;
  }
  // forward() into outputs made by make(out_sizes, -7777) (their guards checked after each call).
  void forward_into(const Arrays& x, Arrays& y) {
    for (auto& arr : y)
      for (size_t i = 0; i < arr.size(); ++i)
        arr[i] = 0;
    p_.forward(cptrs(x), ptrs(y));
    for (const auto& arr : y)
      REQUIRE_MESSAGE(arr.guards_intact(), "forward wrote outside an output");
  }

  Arrays adjoint(const Arrays& x, const Arrays& seeds, Arrays start) {
    p_.adjoint(cptrs(x), ptrs(start), cptrs(seeds));
    for (const auto& arr : start)
      REQUIRE_MESSAGE(arr.guards_intact(), "adjoint wrote outside an input adjoint");
    return start;
  }

  Arrays zeros(const std::vector<size_t>& sizes) {
    Arrays z = make(sizes, std::numeric_limits<T>::signaling_NaN());
    for (auto& arr : z)
      for (size_t i = 0; i < arr.size(); ++i)
        arr[i] = 0;
    return z;
  }

  Arrays shifted(const Arrays& x, const Arrays& v, double h) {
    Arrays out = x;
    for (size_t a = 0; a < x.size(); ++a)
      for (size_t i = 0; i < x[a].size(); ++i)
        out[a][i] = T(double(x[a][i]) + h * double(v[a][i]));
    return out;
  }

  static double dot(const Arrays& a, const Arrays& b) {
    double s = 0;
    for (size_t k = 0; k < a.size(); ++k)
      for (size_t i = 0; i < a[k].size(); ++i)
        s += double(a[k][i]) * double(b[k][i]);
    return s;
  }

  // <J v, w> with J v = (f(x + h v) - f(x - h v)) / 2h, against <v, J^T w>.
  void dot_product_test() {
    auto tol = tolerances<T>(p_.linear);
    for (int trial = 0; trial < 3; ++trial) {
      Arrays v = random_like(p_.in_sizes), w = random_like(p_.out_sizes);
      Arrays fp = forward(shifted(x_, v, tol.fd_step)), fm = forward(shifted(x_, v, -tol.fd_step));
      double lhs = 0, scale = 0;
      for (size_t k = 0; k < fp.size(); ++k)
        for (size_t i = 0; i < fp[k].size(); ++i) {
          double jv = (double(fp[k][i]) - double(fm[k][i])) / (2 * tol.fd_step);
          lhs += jv * double(w[k][i]);
          scale += std::fabs(jv * double(w[k][i]));
        }
      Arrays jtw = adjoint(x_, w, zeros(p_.in_sizes));
      double rhs = dot(v, jtw);
      INFO("<Jv,w> = " << lhs << ", <v,J^T w> = " << rhs);
      CHECK(std::fabs(lhs - rhs) <= tol.dot_rel * std::max(1.0, scale));
    }
  }

  double loss(const Arrays& x, const Arrays& w) {
    Arrays y = make(p_.out_sizes, T(-7777));
    return loss_into(x, w, y);
  }
  // The loss with the forward's outputs written into y (forward_into).
  double loss_into(const Arrays& x, const Arrays& w, Arrays& y) {
    forward_into(x, y);
    double l = 0;
    for (size_t k = 0; k < y.size(); ++k)
      for (size_t i = 0; i < y[k].size(); ++i)
        l += 0.5 * double(y[k][i]) * double(y[k][i]) + double(w[k][i]) * double(y[k][i]);
    return l;
  }

  // dL/dx from the adjoint (seed y + w) against central differences, per
  // component.
  void gradient_test() {
    auto tol = tolerances<T>(false);
    Arrays w = random_like(p_.out_sizes);
    Arrays y = forward(x_);
    Arrays seed = y;
    for (size_t k = 0; k < seed.size(); ++k)
      for (size_t i = 0; i < seed[k].size(); ++i)
        seed[k][i] = y[k][i] + w[k][i];
    Arrays g = adjoint(x_, seed, zeros(p_.in_sizes));
    // Central differences of L carry a rounding error of about eps*|L|/h on
    // top of the O(h^2) truncation: allow for both.
    const double eps = sizeof(T) == 4 ? 6e-8 : 1.1e-16;
    const double l0 = std::fabs(loss(x_, w));
    // One input cell moved at a time in a working copy, and one set of outputs reused (what
    // forward() does, without allocating): copies and allocations per cell made the large
    // sizes' tests (n = 8300, past the parallel threshold) spend most of their time in the
    // allocator and the kernel's page faults.
    Arrays xw = x_, yw = make(p_.out_sizes, T(-7777));
    int bad = 0;
    for (size_t a = 0; a < x_.size(); ++a)
      for (size_t i = 0; i < x_[a].size(); ++i) {
        double h = tol.fd_step * std::max(1.0, std::fabs(double(x_[a][i])));
        if constexpr (sizeof(T) == 4)
          h = 1e-2;
        const T xp = T(double(x_[a][i]) + h), xm = T(double(x_[a][i]) - h);
        xw[a][i] = xp;
        const double lp = loss_into(xw, w, yw);
        xw[a][i] = xm;
        const double lm = loss_into(xw, w, yw);
        xw[a][i] = x_[a][i];
        double fd = (lp - lm) / (double(xp) - double(xm));
        double ad = double(g[a][i]);
        double allowed = tol.grad_rel * std::max(1.0, std::fabs(fd)) + 64 * eps * l0 / h;
        if (std::fabs(fd - ad) > allowed && bad++ < 5)
          MESSAGE("input " << a << " cell " << i << ": finite difference " << fd << ", adjoint "
                           << ad << ", allowed error " << allowed);
      }
    CHECK_MESSAGE(bad == 0, bad << " gradient components disagree with finite differences");
    // Each moved cell was put back: a forward that wrote into its inputs shows here.
    for (size_t a = 0; a < x_.size(); ++a)
      REQUIRE_MESSAGE(std::memcmp(xw[a].data(), x_[a].data(), x_[a].size() * sizeof(T)) == 0,
                      "the forward changed its input " << a);
  }

  // The tangent kernel: its outputs are the forward kernel's, its output
  // tangents J v agree with central differences, and <w, J v> from it equals
  // <v, J^T w> from the adjoint (both exact: to rounding).
  void tangent_test() {
    auto tol = tolerances<T>(p_.linear);
    for (int trial = 0; trial < 2; ++trial) {
      Arrays v = random_like(p_.in_sizes), w = random_like(p_.out_sizes);
      // Output cells the kernel does not write stay 0, as in forward().
      Arrays y = zeros(p_.out_sizes), ydot = zeros(p_.out_sizes);
      p_.tangent(cptrs(x_), cptrs(v), ptrs(y), ptrs(ydot));
      for (const auto& arr : y)
        REQUIRE_MESSAGE(arr.guards_intact(), "tangent wrote outside an output");
      for (const auto& arr : ydot)
        REQUIRE_MESSAGE(arr.guards_intact(), "tangent wrote outside an output tangent");
      // Bit for bit: the tangent prints the kernel's stores from its IR, as
      // the parallel forward of the torch ops does (emit_tangent.cpp), and
      // each must compute what the kernel computes, not a value close to it.
      Arrays f = forward(x_);
      int bad = 0;
      for (size_t k = 0; k < f.size(); ++k)
        for (size_t i = 0; i < f[k].size(); ++i)
          if (!(f[k][i] == y[k][i]) && !(std::isnan(f[k][i]) && std::isnan(y[k][i])) &&
              bad++ < 5)
            MESSAGE("output " << k << " cell " << i << ": forward " << f[k][i] << ", tangent's "
                              << y[k][i] << " (differ by " << double(f[k][i]) - double(y[k][i])
                              << ")");
      CHECK_MESSAGE(bad == 0, bad << " outputs of the tangent kernel differ from the forward's "
                                     "(bit for bit)");
      Arrays fp = forward(shifted(x_, v, tol.fd_step)), fm = forward(shifted(x_, v, -tol.fd_step));
      bad = 0;
      for (size_t k = 0; k < fp.size(); ++k)
        for (size_t i = 0; i < fp[k].size(); ++i) {
          double jv = (double(fp[k][i]) - double(fm[k][i])) / (2 * tol.fd_step);
          double d = double(ydot[k][i]);
          if (std::fabs(jv - d) > 10 * tol.dot_rel * std::max(1.0, std::fabs(jv)) && bad++ < 5)
            MESSAGE("output " << k << " cell " << i << ": finite difference " << jv
                              << ", tangent " << d);
        }
      CHECK_MESSAGE(bad == 0, bad << " tangent components disagree with finite differences");
      Arrays jtw = adjoint(x_, w, zeros(p_.in_sizes));
      double lhs = dot(w, ydot), rhs = dot(v, jtw), scale = 0;
      for (size_t k = 0; k < w.size(); ++k)
        for (size_t i = 0; i < w[k].size(); ++i)
          scale += std::fabs(double(w[k][i]) * double(ydot[k][i]));
      const double exact = sizeof(T) == 4 ? 1e-4 : 1e-12;
      INFO("<w, J v> (tangent) = " << lhs << ", <v, J^T w> (adjoint) = " << rhs);
      CHECK(std::fabs(lhs - rhs) <= exact * std::max(1.0, scale));
    }
  }

  // adjoint(start = r) == r + adjoint(start = 0)
  void accumulate_test() {
    Arrays w = random_like(p_.out_sizes);
    Arrays r = random_like(p_.in_sizes, 3.0);
    Arrays fresh = adjoint(x_, w, zeros(p_.in_sizes));
    Arrays start = zeros(p_.in_sizes);
    for (size_t a = 0; a < r.size(); ++a)
      for (size_t i = 0; i < r[a].size(); ++i)
        start[a][i] = r[a][i];
    Arrays acc = adjoint(x_, w, start);
    double eps = sizeof(T) == 4 ? 1e-5 : 1e-13;
    int bad = 0;
    for (size_t a = 0; a < r.size(); ++a)
      for (size_t i = 0; i < r[a].size(); ++i) {
        double want = double(r[a][i]) + double(fresh[a][i]);
        if (std::fabs(double(acc[a][i]) - want) > eps * std::max(1.0, std::fabs(want)))
          ++bad;
      }
    CHECK_MESSAGE(bad == 0, bad << " adjoint cells overwrote instead of accumulating (+=)");
  }
};

/// Runs all checks on `p` with a fixed seed.
template <typename T> void check_adjoint(const Problem<T>& p, uint64_t seed = 20261121) {
  Checker<T>(p, seed).run();
}

/// A kernel with one input array of n elements and one output of m, checked (check_adjoint)
/// through its three entry points, each given the flat arrays (the kernel's sizes bound in
/// `forward(in, out)`, `adjoint(in, in_adj, seed)`, `tangent(in, dir, out, out_dot)`).
template <typename F, typename A, typename T>
void check_one_to_one(size_t n, size_t m, F forward, A adjoint, T tangent) {
  Problem<double> p;
  p.in_sizes = {n};
  p.out_sizes = {m};
  p.forward = [&](auto in, auto out) { forward(in[0], out[0]); };
  p.adjoint = [&](auto in, auto adj, auto seed) { adjoint(in[0], adj[0], seed[0]); };
  p.tangent = [&](auto in, auto d, auto out, auto dout) { tangent(in[0], d[0], out[0], dout[0]); };
  check_adjoint(p);
}

// The checker works through std::function, so one compiled copy serves every test: a test
// executable that links tests/kernels/main.cpp (which instantiates it) defines
// DPGEN_TEST_CHECKER_COMPILED_ONCE and its hundreds of test files skip compiling it again
// (most of their compile time, several seconds each under the sanitizers).
#ifdef DPGEN_TEST_CHECKER_COMPILED_ONCE
extern template class Checker<float>;
extern template class Checker<double>;
#endif

} // namespace dpgen_test
