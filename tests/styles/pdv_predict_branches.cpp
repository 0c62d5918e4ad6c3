// A hydro code's PdV kernel shape (issue 20, defect 4): the predictor and the
// corrector are the two arms of `if (predict == 0)`, each with its own loop
// nests writing the same outputs, one of them also read back as a work array
// in its arm. An arm that does not run writes nothing, so the output rules
// hold arm by arm.
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void pdv_predict_branches(DPGEN_IN const double* pressure,
                                       DPGEN_IN const double* volume, DPGEN_OUT double* flux,
                                       DPGEN_OUT double* energy, int n, double dt, int predict) {
  if (predict == 0) {
    for (int i = 1; i < n; ++i)
      flux[i] = 0.5 * dt * (pressure[i] + pressure[i - 1]) * volume[i];
    flux[0] = 0.0;
    for (int i = 0; i < n; ++i)
      energy[i] = pressure[i] - flux[i] * volume[i];
  } else {
    for (int i = 0; i < n; ++i)
      flux[i] = dt * pressure[i] * pressure[i];
    for (int i = 0; i < n; ++i)
      energy[i] = volume[i] * volume[i] + pressure[i];
  }
}
