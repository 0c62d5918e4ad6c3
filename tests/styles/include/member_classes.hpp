// Classes whose methods are DPGEN_KERNELs (tests/styles/member_*.cpp): the
// annotated members are the kernel's arrays, the others its constants.
#pragma once

#include "dpgen/annotate.hpp"

#include "user_views.hpp"

/// A 1D advection solver object: private state, a method defined out of
/// class, a private helper method it calls.
class Advection1D {
public:
  Advection1D(int n, double c, const double* q, double* q_new)
      : n_(n), c_(c), q_(q), q_new_(q_new) {}
  DPGEN_KERNEL void step(double dt) const;

private:
  double flux(double left, double right) const { return c_ > 0.0 ? c_ * left : c_ * right; }
  int n_;
  double c_;
  const double* q_ DPGEN_IN;
  double* q_new_ DPGEN_OUT;
  double unused_scratch_ = 0.0; // (not read by the kernel: no parameter of it)
};

/// A smoothing functor over views, run by a parallel-for of the user's own
/// on *this from a member kernel; public members, default member values.
struct Smoother2D {
  grid::View2D<const double> u DPGEN_IN;
  grid::View2D<const double> w DPGEN_IN; // per-cell weight
  grid::View2D<double> out DPGEN_OUT;
  double theta = 0.25;

  void operator()(int j, int i) const {
    out(j, i) = u(j, i) + theta * w(j, i) * (u(j, i - 1) + u(j, i + 1) + u(j - 1, i) + u(j + 1, i) -
                                             4.0 * u(j, i));
  }
  DPGEN_KERNEL void run() const;
};

/// A reaction step that updates its state array in place (a DPGEN_INOUT
/// member): the generated wrappers did not compile until session 21 (they
/// named the new values' internal twin, u_new, as a member).
struct Reaction1D {
  int n = 0;
  double* u DPGEN_INOUT = nullptr;
  const double* rate DPGEN_IN = nullptr;
  DPGEN_KERNEL void step(double dt) const;
};
