// The boundary kinds of tests/styles/enum_params.cpp: an enum class in a
// header, as codes keep their configuration types.
#pragma once

enum class Bc { Zero, Copy, Flip };

#include "dpgen/annotate.hpp"

/// A kind as a member: of an object of parameters, and of a solver class
/// whose member kernel reads it (tests/styles/enum_params.cpp).
struct BcParams {
  double dt;
  Bc bc;
};

class EdgeSolver {
public:
  EdgeSolver(int n, Bc bc, const double* u, double* v) : n_(n), bc_(bc), u_(u), v_(v) {}
  DPGEN_KERNEL void run() const;

private:
  int n_;
  Bc bc_;
  const double* u_ DPGEN_IN;
  double* v_ DPGEN_OUT;
};
