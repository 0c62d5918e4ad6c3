// corpus: form=member expect=accept
// A solver class whose step() is the kernel: the arrays are private members
// marked after their declarator, sizes and coefficients are members too, the
// method is defined out of the class. Adjoint (issue 22):
//   Heat1D_step_adjoint(const Heat1D& self, double dt, <u_ adjoint>, <unew_ seed>)
#include "dpgen/annotate.hpp"

class Heat1D {
public:
  Heat1D(int n, double nu, const double* u, double* unew) : n_(n), nu_(nu), u_(u), unew_(unew) {}
  DPGEN_KERNEL void step(double dt) const;

private:
  int n_;
  double nu_;
  const double* u_ DPGEN_IN;
  double* unew_ DPGEN_OUT;
};

void Heat1D::step(double dt) const {
  const double c = dt * nu_;
  unew_[0] = u_[0];
  for (int i = 1; i < n_ - 1; ++i)
    unew_[i] = u_[i] + c * (u_[i - 1] - 2.0 * u_[i] + u_[i + 1]);
  unew_[n_ - 1] = u_[n_ - 1];
}
