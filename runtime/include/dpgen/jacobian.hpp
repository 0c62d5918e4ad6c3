// Dense Jacobians of a function R^n -> R^m from its products: column by column from
// Jacobian-vector products (tangents, n calls) or row by row from vector-Jacobian products
// (adjoints, m calls), a helper that takes whichever needs fewer calls, and central
// differences to check them against.
#pragma once

#include "dpgen/error.hpp"

#include <Eigen/Core>

#include <cmath>
#include <functional>
#include <stdexcept>
#include <string>

namespace dpgen {

/// A Jacobian-vector product (tangent): returns J(x) v, of size m, for v of size n.
using JacobianVectorProduct =
    std::function<Eigen::VectorXd(const Eigen::VectorXd& x, const Eigen::VectorXd& v)>;

/// A vector-Jacobian product (adjoint): returns J(x)^T w, of size n, for w of size m.
using VectorJacobianProduct =
    std::function<Eigen::VectorXd(const Eigen::VectorXd& x, const Eigen::VectorXd& w)>;

/// How a Jacobian is assembled.
enum class JacobianMode {
  tangent, ///< by columns: J e_j for j < n (n Jacobian-vector products)
  adjoint, ///< by rows: J^T e_i for i < m (m vector-Jacobian products)
};

/// The enumerator's name, for messages and logs.
inline const char* to_string(JacobianMode mode) {
  return mode == JacobianMode::tangent ? "tangent" : "adjoint";
}

/// The mode needing fewer products for an m-by-n Jacobian: tangent when n <= m (a tangent
/// needs no reverse sweep, so it wins ties), adjoint otherwise.
inline JacobianMode cheaper_jacobian_mode(Eigen::Index inputs, Eigen::Index outputs) {
  return inputs <= outputs ? JacobianMode::tangent : JacobianMode::adjoint;
}

namespace detail {

inline void require_jacobian_sizes(Eigen::Index inputs, Eigen::Index outputs, const char* where) {
  if (inputs < 0 || outputs < 0)
    throw std::invalid_argument(
        message(where, ": sizes must be >= 0 (got ", inputs, " inputs, ", outputs, " outputs)"));
}

} // namespace detail

/// The m-by-n Jacobian of f at x (n = x.size(), m = `outputs`) by columns:
/// column j = jvp(x, e_j). Throws std::invalid_argument when jvp is empty or returns a vector
/// whose size is not m.
inline Eigen::MatrixXd jacobian_by_columns(const JacobianVectorProduct& jvp,
                                           const Eigen::VectorXd& x, Eigen::Index outputs) {
  const char* where = "jacobian (tangent)";
  if (!jvp)
    throw std::invalid_argument(detail::message(where, ": no Jacobian-vector product given"));
  detail::require_jacobian_sizes(x.size(), outputs, where);
  Eigen::MatrixXd jac(outputs, x.size());
  Eigen::VectorXd e = Eigen::VectorXd::Zero(x.size());
  for (Eigen::Index j = 0; j < x.size(); ++j) {
    e[j] = 1.0;
    const Eigen::VectorXd column = jvp(x, e); // J e_j = column j
    e[j] = 0.0;
    detail::require_size(column.size(), outputs, where,
                         detail::message("Jacobian-vector product for input ", j));
    jac.col(j) = column;
  }
  return jac;
}

/// The m-by-n Jacobian of f at x (n = x.size(), m = `outputs`) by rows:
/// row i = vjp(x, e_i)^T. Throws std::invalid_argument when vjp is empty or returns a vector
/// whose size is not n.
inline Eigen::MatrixXd jacobian_by_rows(const VectorJacobianProduct& vjp, const Eigen::VectorXd& x,
                                        Eigen::Index outputs) {
  const char* where = "jacobian (adjoint)";
  if (!vjp)
    throw std::invalid_argument(detail::message(where, ": no vector-Jacobian product given"));
  detail::require_jacobian_sizes(x.size(), outputs, where);
  Eigen::MatrixXd jac(outputs, x.size());
  Eigen::VectorXd e = Eigen::VectorXd::Zero(outputs);
  for (Eigen::Index i = 0; i < outputs; ++i) {
    e[i] = 1.0;
    const Eigen::VectorXd row = vjp(x, e); // J^T e_i = (row i)^T
    e[i] = 0.0;
    detail::require_size(row.size(), x.size(), where,
                         detail::message("vector-Jacobian product for output ", i));
    jac.row(i) = row.transpose();
  }
  return jac;
}

/// The m-by-n Jacobian of f at x with the products given: both given, the cheaper mode
/// (cheaper_jacobian_mode); one given, that one. `mode_used`, when not null, receives the
/// mode taken. Throws std::invalid_argument when neither is given.
inline Eigen::MatrixXd jacobian(const JacobianVectorProduct& jvp, const VectorJacobianProduct& vjp,
                                const Eigen::VectorXd& x, Eigen::Index outputs,
                                JacobianMode* mode_used = nullptr) {
  if (!jvp && !vjp)
    throw std::invalid_argument(
        "jacobian: neither a Jacobian-vector nor a vector-Jacobian product given");
  detail::require_jacobian_sizes(x.size(), outputs, "jacobian");
  JacobianMode mode = cheaper_jacobian_mode(x.size(), outputs);
  if (!vjp)
    mode = JacobianMode::tangent;
  else if (!jvp)
    mode = JacobianMode::adjoint;
  if (mode_used)
    *mode_used = mode;
  return mode == JacobianMode::tangent ? jacobian_by_columns(jvp, x, outputs)
                                       : jacobian_by_rows(vjp, x, outputs);
}

/// The Jacobian of f at x by central differences, for checking the other two (not for use):
/// column j = (f(x + h e_j) - f(x - h e_j)) / 2h with h = step (1 + |x_j|). Its error is about
/// h^2 |f'''| / 6 + eps |f| / h: for smooth f of unit scale, the default step gives ~1e-10.
/// Throws std::invalid_argument when step is not positive or f changes its output size.
inline Eigen::MatrixXd
jacobian_central_difference(const std::function<Eigen::VectorXd(const Eigen::VectorXd&)>& f,
                            const Eigen::VectorXd& x, double step = 1e-5) {
  const char* where = "jacobian (central differences)";
  if (!(step > 0.0) || !std::isfinite(step))
    throw std::invalid_argument(detail::message(where, ": step must be positive (got ", step, ")"));
  if (!f)
    throw std::invalid_argument(detail::message(where, ": no function given"));
  const Eigen::Index outputs = f(x).size();
  Eigen::MatrixXd jac(outputs, x.size());
  Eigen::VectorXd shifted = x;
  for (Eigen::Index j = 0; j < x.size(); ++j) {
    const double h = step * (1.0 + std::abs(x[j]));
    shifted[j] = x[j] + h;
    const Eigen::VectorXd plus = f(shifted);
    shifted[j] = x[j] - h;
    const Eigen::VectorXd minus = f(shifted);
    shifted[j] = x[j];
    detail::require_size(plus.size(), outputs, where, detail::message("f(x + h e_", j, ")"));
    detail::require_size(minus.size(), outputs, where, detail::message("f(x - h e_", j, ")"));
    jac.col(j) = (plus - minus) / (2.0 * h);
  }
  return jac;
}

} // namespace dpgen
