// The consumer's forward kernel: one step of periodic 1D diffusion.
#pragma once

#include "dpgen/annotate.hpp"

DPGEN_KERNEL void smooth(DPGEN_IN const double* u, DPGEN_OUT double* out, int n, double c);
