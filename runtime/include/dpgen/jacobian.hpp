// Dense Jacobians of small functions and rollouts from their Jacobian-vector products (JVPs,
// tangents, one column each) or vector-Jacobian products (VJPs, adjoints, one row each),
// whichever needs fewer calls; and a central-difference Jacobian to check them against.
#pragma once

#include "dpgen/error.hpp"

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <functional>
#include <stdexcept>
#include <string>

namespace dpgen {

/// A Jacobian-vector product: returns J v (size `outputs`) for a tangent v (size `inputs`).
using JacobianVectorProduct = std::function<Eigen::VectorXd(const Eigen::VectorXd& v)>;
/// A vector-Jacobian product: returns J^T w (size `inputs`) for a seed w (size `outputs`).
using VectorJacobianProduct = std::function<Eigen::VectorXd(const Eigen::VectorXd& w)>;

/// How jacobian() builds J.
enum class JacobianMode {
  automatic, ///< columns when inputs <= outputs (and a JVP is given), rows otherwise
  columns,   ///< one JVP per input: J e_j is column j
  rows,      ///< one VJP per output: J^T e_i is row i
};

/// What jacobian() did.
struct JacobianSummary {
  JacobianMode mode = JacobianMode::automatic; ///< columns or rows, as used
  Eigen::Index products = 0;                   ///< JVPs or VJPs evaluated
};

namespace detail {

inline const char* mode_name(JacobianMode mode) {
  switch (mode) {
  case JacobianMode::automatic:
    return "automatic";
  case JacobianMode::columns:
    return "columns";
  case JacobianMode::rows:
    return "rows";
  }
  return "?";
}

} // namespace detail

/// The mode jacobian() picks for `mode` with the products it is given: `automatic` takes the
/// one needing fewer products (columns on a tie: a JVP carries the primal along), or the only
/// one given. Throws std::invalid_argument when the requested product is missing.
inline JacobianMode resolve_jacobian_mode(Eigen::Index outputs, Eigen::Index inputs,
                                          bool have_jvp, bool have_vjp,
                                          JacobianMode mode = JacobianMode::automatic) {
  if (!have_jvp && !have_vjp)
    throw std::invalid_argument("jacobian: neither a JVP nor a VJP was given");
  if (mode == JacobianMode::automatic) {
    if (!have_vjp)
      return JacobianMode::columns;
    if (!have_jvp)
      return JacobianMode::rows;
    return inputs <= outputs ? JacobianMode::columns : JacobianMode::rows;
  }
  if (mode == JacobianMode::columns && !have_jvp)
    throw std::invalid_argument("jacobian: mode 'columns' needs a JVP, none was given");
  if (mode == JacobianMode::rows && !have_vjp)
    throw std::invalid_argument("jacobian: mode 'rows' needs a VJP, none was given");
  return mode;
}

/// The dense outputs-by-inputs Jacobian J from `jvp` (J v) and/or `vjp` (J^T w); either may be
/// empty. Each product is called with a unit vector and must return a finite vector of the
/// right size, or std::invalid_argument names the product, its index and what was wrong.
inline Eigen::MatrixXd jacobian(Eigen::Index outputs, Eigen::Index inputs,
                                const JacobianVectorProduct& jvp,
                                const VectorJacobianProduct& vjp,
                                JacobianMode mode = JacobianMode::automatic,
                                JacobianSummary* summary = nullptr) {
  if (outputs < 1 || inputs < 1)
    throw std::invalid_argument(detail::message(
        "jacobian: sizes must be positive (got ", outputs, " outputs, ", inputs, " inputs)"));
  const JacobianMode used = resolve_jacobian_mode(outputs, inputs, bool(jvp), bool(vjp), mode);
  Eigen::MatrixXd j(outputs, inputs);
  if (used == JacobianMode::columns) {
    Eigen::VectorXd e = Eigen::VectorXd::Zero(inputs);
    for (Eigen::Index c = 0; c < inputs; ++c) {
      e[c] = 1.0;
      const Eigen::VectorXd column = jvp(e); // J e_c
      e[c] = 0.0;
      const std::string what = detail::message("JVP of input ", c);
      detail::require_size(column.size(), outputs, "jacobian", what);
      detail::require_finite(column, "jacobian", what);
      j.col(c) = column;
    }
  } else {
    Eigen::VectorXd e = Eigen::VectorXd::Zero(outputs);
    for (Eigen::Index r = 0; r < outputs; ++r) {
      e[r] = 1.0;
      const Eigen::VectorXd row = vjp(e); // J^T e_r
      e[r] = 0.0;
      const std::string what = detail::message("VJP of output ", r);
      detail::require_size(row.size(), inputs, "jacobian", what);
      detail::require_finite(row, "jacobian", what);
      j.row(r) = row.transpose();
    }
  }
  if (summary) {
    summary->mode = used;
    summary->products = used == JacobianMode::columns ? inputs : outputs;
  }
  return j;
}

/// The Jacobian of f at x by central differences, column j = (f(x + h e_j) - f(x - h e_j)) / 2h,
/// with h = step * max(1, |x_j|). Its error is O(h^2 |f'''|) + O(eps |f| / h): for smooth f of
/// unit scale, step 1e-6 gives about 1e-9 absolute. For checking the other two, not for use.
inline Eigen::MatrixXd
jacobian_central_difference(const std::function<Eigen::VectorXd(const Eigen::VectorXd&)>& f,
                            const Eigen::VectorXd& x, double step = 1e-6) {
  if (!(step > 0.0))
    throw std::invalid_argument(
        detail::message("jacobian_central_difference: step must be positive (got ", step, ")"));
  detail::require_finite(x, "jacobian_central_difference", "x");
  const Eigen::Index outputs = f(x).size();
  Eigen::MatrixXd j(outputs, x.size());
  Eigen::VectorXd xp = x;
  for (Eigen::Index c = 0; c < x.size(); ++c) {
    const double h = step * std::max(1.0, std::abs(x[c]));
    xp[c] = x[c] + h;
    const Eigen::VectorXd fp = f(xp);
    xp[c] = x[c] - h;
    const Eigen::VectorXd fm = f(xp);
    xp[c] = x[c];
    detail::require_size(fp.size(), outputs, "jacobian_central_difference", "f(x + h e_j)");
    detail::require_size(fm.size(), outputs, "jacobian_central_difference", "f(x - h e_j)");
    j.col(c) = (fp - fm) / (2.0 * h);
  }
  return j;
}

} // namespace dpgen
