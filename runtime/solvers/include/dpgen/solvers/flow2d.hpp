// A differentiable 2D incompressible flow solver (a smoke plume in a closed box, or a flow with
// periodic axes) built from dpgen kernels (kernels/flow2d.cpp): semi-Lagrangian transport of a
// marker and of the velocity, a constant marker inflow, Boussinesq buoyancy, a body force field,
// and a pressure projection solved by multigrid-preconditioned CG whose gradient comes from the
// implicit-function rule. Link dpgen::kernels to use this header. The forward steps call the
// kernels' parallel forms (<kernel>_parallel_forward of the generated adjoint files: each kernel
// printed from its IR with its loops on every thread, its values bit for bit); the pressure
// operator stays the kernel as written, which multigrid runs by row strips.
#pragma once

#include "dpgen/implicit_solve.hpp"
#include "dpgen/solvers/multigrid.hpp"
#include "flow2d_adjoint.hpp"
#include "kernels.hpp"

#include <Eigen/Core>

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>

namespace dpgen {

/// How the marker is transported.
enum class MarkerAdvection {
  semi_lagrangian, ///< s(x - dt u), bilinear: first order, diffusive
  maccormack,      ///< semi-Lagrangian plus the MacCormack correction with its clamp (PhiFlow's)
};

/// What the velocity's self-advection takes for the tangential velocity beyond a closed wall
/// (u beyond the bottom and top walls, v beyond the left and right ones).
enum class WallTangent {
  clamped, ///< the value on the nearest face row inside: traces are clamped to it
  zero,    ///< 0 on ghost faces half a cell outside the wall (PhiFlow's extrapolation.ZERO)
};

/// Settings of a Flow2d step.
struct FlowOptions {
  MarkerAdvection marker_advection = MarkerAdvection::semi_lagrangian;
  double dt = 1.0;       ///< time step
  double buoyancy = 1.0; ///< v += dt * buoyancy * s (marker averaged onto the y faces)
  WallTangent wall_tangent = WallTangent::clamped; ///< closed walls, velocity transport
  /// The pressure solves (forward and backward): relative tolerance and iteration limit.
  double pressure_tolerance = 1e-10;
  int max_pressure_iterations = 100;
  /// Periodic axes (false: closed walls on both sides of that axis). On a periodic x axis the
  /// u face i = nx of each row is face 0: steps write it as a bit-identical copy and never read
  /// it (so its value in a state has no influence, and its gradient is zero); likewise the v row
  /// j = ny on a periodic y axis.
  bool periodic_x = false;
  bool periodic_y = false;
};

/// An nx-by-ny MAC grid of cells of size h (each axis closed or periodic) and one time step on
/// it. The state is one vector [s, u, v]: the marker s at the nx*ny cell centres, u on the
/// (nx+1)*ny x faces, v on the nx*(ny+1) y faces (wall faces zero; on a periodic axis the last
/// face is a copy of the first). One step, with a body force f = (fx, fy) per cell (zero unless
/// set_force is called) averaged onto the faces:
///   s1 = s(x - dt u) + inflow                      semi-Lagrangian (or MacCormack), marker
///   u1 = u(x - dt u) + dt fx                        semi-Lagrangian, velocity; force
///   v1 = v(x - dt u) + dt b s1 + dt fy              buoyancy and force
///   A p = -div(u1, v1)                              A = -laplace, walls or periodic (MG-PCG)
///   (u2, v2) = (u1, v1) - grad p                    divergence-free
/// and its adjoint, which recomputes the step's nonlinear intermediates from the state (nothing
/// is kept between calls, so a checkpointing schedule may call it in any order). The adjoint
/// needs no forward pressure solve: the kernels after the advection are linear, and their
/// adjoints never read their primal inputs (they get a NaN-filled stand-in, so a change there
/// would show in every gradient).
class Flow2d {
public:
  /// `inflow`: the marker added per step at each cell (nx*ny values).
  Flow2d(int nx, int ny, double h, Eigen::VectorXd inflow, FlowOptions options = {})
      : nx_(nx), ny_(ny), h_(h), inflow_(std::move(inflow)), options_(options),
        multigrid_(check_grid(nx, ny, h), ny, h, pressure_boundaries(options),
                   pressure_operator(options), Eigen::VectorXd::Ones(Eigen::Index(nx) * ny)),
        force_(Eigen::VectorXd::Zero(2 * Eigen::Index(nx) * ny)) {
    detail::require_size(inflow_.size(), cells(), "flow2d", "inflow");
    detail::require_finite(inflow_, "flow2d", "inflow");
    if (!(options_.dt > 0.0) || !std::isfinite(options_.buoyancy))
      throw std::invalid_argument(
          detail::message("flow2d: dt = ", options_.dt, " must be > 0 and buoyancy finite"));
    cg_.relative_tolerance = options_.pressure_tolerance;
    cg_.absolute_tolerance = 1e-300;
    cg_.max_iterations = options_.max_pressure_iterations;
    cg_.remove_null_space_mean = true; // walls or periodic: p is defined up to a constant
    cg_.preconditioner = multigrid_.preconditioner();
    cg_.name = "flow2d pressure";
    cg_.workspace = &cg_workspace_; // every pressure solve of the run reuses the same vectors
    forward_cg_ = detail::named(cg_, " forward (A x = b)");
    backward_cg_ = detail::named(cg_, " backward (A^T lambda = x_bar)");
  }

  // The CG options hold a preconditioner and a workspace that point into this object: no copies
  // or moves.
  Flow2d(const Flow2d&) = delete;
  Flow2d& operator=(const Flow2d&) = delete;

  Eigen::Index cells() const { return Eigen::Index(nx_) * ny_; }
  Eigen::Index u_faces() const { return Eigen::Index(nx_ + 1) * ny_; }
  Eigen::Index v_faces() const { return Eigen::Index(nx_) * (ny_ + 1); }
  /// Size of the state vector [s, u, v].
  Eigen::Index state_size() const { return cells() + u_faces() + v_faces(); }
  int nx() const { return nx_; }
  int ny() const { return ny_; }
  const Eigen::VectorXd& inflow() const { return inflow_; }
  bool periodic_x() const { return options_.periodic_x; }
  bool periodic_y() const { return options_.periodic_y; }

  /// The body force per unit mass, [fx, fy] at the cell centres (2*nx*ny values: fx of every
  /// cell, then fy), added as dt * f (averaged onto the faces) in every following step until set
  /// again. A force that changes in time: set it before each step (and before that step's
  /// step_adjoint, whose force_adj is then the gradient for that step's force).
  void set_force(const Eigen::VectorXd& force) {
    detail::require_size(force.size(), 2 * cells(), "flow2d set_force", "force");
    detail::require_finite(force, "flow2d set_force", "force");
    force_ = force;
  }
  const Eigen::VectorXd& force() const { return force_; }
  /// The state's parts, as writable or read-only segments.
  auto marker(Eigen::VectorXd& state) const { return state.segment(0, cells()); }
  auto u(Eigen::VectorXd& state) const { return state.segment(cells(), u_faces()); }
  auto v(Eigen::VectorXd& state) const { return state.segment(cells() + u_faces(), v_faces()); }
  auto marker(const Eigen::VectorXd& state) const { return state.segment(0, cells()); }
  auto u(const Eigen::VectorXd& state) const { return state.segment(cells(), u_faces()); }
  auto v(const Eigen::VectorXd& state) const {
    return state.segment(cells() + u_faces(), v_faces());
  }

  /// next = step(state). Throws std::invalid_argument for a state of the wrong size or with a
  /// NaN or Inf, SolveError when the pressure solve fails.
  void step(const Eigen::VectorXd& state, Eigen::VectorXd& next) {
    detail::require_size(state.size(), state_size(), "flow2d step", "state");
    // A NaN position would become an out-of-range cell index in the semi-Lagrangian kernels.
    detail::require_finite(state, "flow2d step", "state");
    forward(state);
    next.resize(state_size());
    marker(next) = s1_;
    u(next).setZero();
    v(next).setZero();
    flow_subtract_gradient_u_parallel_forward(u1_.data(), p_.data(), next.data() + cells(), nx_,
                                              ny_, h_, px());
    flow_subtract_gradient_v_parallel_forward(
        v1_.data(), p_.data(), next.data() + cells() + u_faces(), nx_, ny_, h_, py());
  }

  /// Adds (d step(state)/d state)^T next_adj into state_adj and (d step/d inflow)^T next_adj
  /// into inflow_adj (sized nx*ny).
  void step_adjoint(const Eigen::VectorXd& state, const Eigen::VectorXd& next_adj,
                    Eigen::VectorXd& state_adj, Eigen::VectorXd& inflow_adj) {
    force_adj_scratch_.setZero(2 * cells());
    step_adjoint(state, next_adj, state_adj, inflow_adj, force_adj_scratch_);
  }

  /// The same, and adds (d step/d force)^T next_adj into force_adj (sized 2*nx*ny, as the
  /// force).
  void step_adjoint(const Eigen::VectorXd& state, const Eigen::VectorXd& next_adj,
                    Eigen::VectorXd& state_adj, Eigen::VectorXd& inflow_adj,
                    Eigen::VectorXd& force_adj) {
    detail::require_size(state.size(), state_size(), "flow2d step_adjoint", "state");
    detail::require_size(next_adj.size(), state_size(), "flow2d step_adjoint", "next_adj");
    detail::require_size(state_adj.size(), state_size(), "flow2d step_adjoint", "state_adj");
    detail::require_size(inflow_adj.size(), cells(), "flow2d step_adjoint", "inflow_adj");
    detail::require_size(force_adj.size(), 2 * cells(), "flow2d step_adjoint", "force_adj");
    detail::require_finite(state, "flow2d step_adjoint", "state");
    using Eigen::VectorXd;
    const double dt_h = options_.dt / h_;
    const double* su = state.data() + cells();
    const double* sv = state.data() + cells() + u_faces();
    if (options_.marker_advection == MarkerAdvection::maccormack)
      maccormack_intermediates(state.data(), su, sv, dt_h); // s_sl, s_rev: the clamp reads them
    // The adjoints of the linear kernels below get `unread` for their primal inputs.
    const double* unread = unread_.data();
    VectorXd& s1_adj = s1_adj_;
    s1_adj = marker(next_adj);
    VectorXd& u1_adj = u1_adj_;
    VectorXd& v1_adj = v1_adj_;
    VectorXd& p_adj = p_adj_;
    u1_adj.setZero(u_faces());
    v1_adj.setZero(v_faces());
    p_adj.setZero(cells());
    // (u2, v2) = (u1, v1) - grad p
    flow_subtract_gradient_u_adjoint(unread, u1_adj.data(), unread, p_adj.data(),
                                     next_adj.data() + cells(), nx_, ny_, h_, px());
    flow_subtract_gradient_v_adjoint(unread, v1_adj.data(), unread, p_adj.data(),
                                     next_adj.data() + cells() + u_faces(), nx_, ny_, h_, py());
    // A p = -div: lambda = A^+ P p_adj (A^T = A, same V-cycle), so div_adj = -lambda. A has no
    // parameters: nothing to accumulate for theta.
    detail::require_finite(p_adj, backward_cg_.name, "x_bar");
    backward_summary_ =
        conjugate_gradient(multigrid_.fine_operator(), p_adj, lambda_, backward_cg_);
    VectorXd& div_adj = div_adj_;
    div_adj = -lambda_;
    flow_divergence_adjoint(unread, u1_adj.data(), unread, v1_adj.data(), div_adj.data(), nx_, ny_,
                            h_, px(), py());
    // v1 = v_advected + dt b s1 + dt fy,  u1 = u_advected + dt fx
    VectorXd& va_adj = va_adj_;
    VectorXd& ua_adj = ua_adj_;
    va_adj.setZero(v_faces());
    ua_adj.setZero(u_faces());
    flow_buoyancy_adjoint(unread, va_adj.data(), unread, s1_adj.data(), unread,
                          force_adj.data() + cells(), v1_adj.data(), nx_, ny_,
                          options_.dt * options_.buoyancy, options_.dt, py());
    flow_force_u_adjoint(unread, ua_adj.data(), unread, force_adj.data(), u1_adj.data(), nx_, ny_,
                         options_.dt, px());
    // u1 = u(x - dt u), v_advected = v(x - dt u), s1 = s(x - dt u) + inflow
    double* u_adj = state_adj.data() + cells();
    double* v_adj = state_adj.data() + cells() + u_faces();
    flow_advect_u_adjoint(su, u_adj, sv, v_adj, ua_adj.data(), nx_, ny_, dt_h, px(), py(), zt());
    flow_advect_v_adjoint(su, u_adj, sv, v_adj, va_adj.data(), nx_, ny_, dt_h, px(), py(), zt());
    if (options_.marker_advection == MarkerAdvection::maccormack) {
      VectorXd& sl_adj = sl_adj_;
      VectorXd& rev_adj = rev_adj_;
      VectorXd& none_adj = none_adj_;
      sl_adj.setZero(cells());
      rev_adj.setZero(cells());
      none_adj.setZero(cells());
      const VectorXd& none = zeros_;
      flow_maccormack_marker_adjoint(state.data(), state_adj.data(), s_sl_.data(), sl_adj.data(),
                                     s_rev_.data(), rev_adj.data(), su, u_adj, sv, v_adj,
                                     inflow_.data(), inflow_adj.data(), s1_adj.data(), nx_, ny_,
                                     dt_h, px(), py());
      flow_advect_marker_adjoint(s_sl_.data(), sl_adj.data(), su, u_adj, sv, v_adj, none.data(),
                                 none_adj.data(), rev_adj.data(), nx_, ny_, -dt_h, px(), py());
      flow_advect_marker_adjoint(state.data(), state_adj.data(), su, u_adj, sv, v_adj, none.data(),
                                 none_adj.data(), sl_adj.data(), nx_, ny_, dt_h, px(), py());
    } else {
      flow_advect_marker_adjoint(state.data(), state_adj.data(), su, u_adj, sv, v_adj,
                                 inflow_.data(), inflow_adj.data(), s1_adj.data(), nx_, ny_, dt_h,
                                 px(), py());
    }
  }

  /// The last forward and backward pressure solves (iterations, residuals).
  const CgSummary& forward_pressure_summary() const { return forward_summary_; }
  const CgSummary& backward_pressure_summary() const { return backward_summary_; }
  /// The CG work vectors every pressure solve reuses (for checks that steps allocate none).
  const CgWorkspace& pressure_workspace() const { return cg_workspace_; }
  /// The divergence of the velocity of a state (for checks: zero after a step).
  Eigen::VectorXd divergence(const Eigen::VectorXd& state) const {
    Eigen::VectorXd div(cells());
    flow_divergence_parallel_forward(state.data() + cells(), state.data() + cells() + u_faces(),
                                     div.data(), nx_, ny_, h_, px(), py());
    return div;
  }

private:
  int px() const { return options_.periodic_x ? 1 : 0; }
  int py() const { return options_.periodic_y ? 1 : 0; }
  int zt() const { return options_.wall_tangent == WallTangent::zero ? 1 : 0; }

  static Boundaries pressure_boundaries(const FlowOptions& o) {
    const Boundary x = o.periodic_x ? Boundary::periodic : Boundary::neumann;
    const Boundary y = o.periodic_y ? Boundary::periodic : Boundary::neumann;
    return {x, x, y, y};
  }
  // The pressure operator kernel with the options' axes bound (weights of the wrapped faces):
  // its parallel form, the kernel's values bit for bit, with its loops split from the wrap and
  // the wall weights so that the interior vectorizes (the multigrid applies it by row strips).
  static LevelOperator pressure_operator(const FlowOptions& o) {
    const double ox = o.periodic_x ? 1.0 : 0.0, oy = o.periodic_y ? 1.0 : 0.0;
    return [ox, oy](const double* x, const double* k, double* y, int nx, int ny, double h) {
      flow_pressure_operator_parallel_forward(x, k, y, nx, ny, h, ox, oy);
    };
  }

  static int check_grid(int nx, int ny, double h) {
    if (nx < 2 || ny < 2 || !(h > 0.0))
      throw std::invalid_argument(detail::message("flow2d: need at least 2x2 cells and h > 0 (got ",
                                                  nx, "x", ny, ", h = ", h, ")"));
    return nx;
  }

  // s1 (and s_sl, s_rev for MacCormack), ua and va (advected u and v), u1 (= ua + force),
  // v1 (= va + buoyancy + force) and p of one step from `state`.
  void forward(const Eigen::VectorXd& state) {
    const double dt_h = options_.dt / h_;
    const double* s = state.data();
    const double* su = state.data() + cells();
    const double* sv = state.data() + cells() + u_faces();
    s1_.resize(cells());
    ua_.resize(u_faces());
    u1_.resize(u_faces());
    va_.resize(v_faces());
    v1_.resize(v_faces());
    if (options_.marker_advection == MarkerAdvection::maccormack) {
      maccormack_intermediates(s, su, sv, dt_h);
      flow_maccormack_marker_parallel_forward(s, s_sl_.data(), s_rev_.data(), su, sv,
                                              inflow_.data(), s1_.data(), nx_, ny_, dt_h, px(),
                                              py());
    } else {
      flow_advect_marker_parallel_forward(s, su, sv, inflow_.data(), s1_.data(), nx_, ny_, dt_h,
                                          px(), py());
    }
    flow_advect_u_parallel_forward(su, sv, ua_.data(), nx_, ny_, dt_h, px(), py(), zt());
    flow_force_u_parallel_forward(ua_.data(), force_.data(), u1_.data(), nx_, ny_, options_.dt,
                                  px());
    flow_advect_v_parallel_forward(su, sv, va_.data(), nx_, ny_, dt_h, px(), py(), zt());
    flow_buoyancy_parallel_forward(va_.data(), s1_.data(), force_.data() + cells(), v1_.data(), nx_,
                                   ny_, options_.dt * options_.buoyancy, options_.dt, py());
    rhs_.resize(cells());
    flow_divergence_parallel_forward(u1_.data(), v1_.data(), rhs_.data(), nx_, ny_, h_, px(), py());
    rhs_ = -rhs_; // A p = -div
    // No initial guess: a recomputed step must give the same bits (checkpointing relies on it).
    forward_summary_ = conjugate_gradient(multigrid_.fine_operator(), rhs_, p_, forward_cg_);
  }

  // s_sl = s(x - dt u); s_rev = s_sl(x + dt u): what the MacCormack correction and clamp read.
  void maccormack_intermediates(const double* s, const double* su, const double* sv, double dt_h) {
    s_sl_.resize(cells());
    s_rev_.resize(cells());
    flow_advect_marker_parallel_forward(s, su, sv, zeros_.data(), s_sl_.data(), nx_, ny_, dt_h,
                                        px(), py());
    flow_advect_marker_parallel_forward(s_sl_.data(), su, sv, zeros_.data(), s_rev_.data(), nx_,
                                        ny_, -dt_h, px(), py());
  }

  int nx_, ny_;
  double h_;
  Eigen::VectorXd inflow_;
  FlowOptions options_;
  Multigrid multigrid_;
  CgWorkspace cg_workspace_; // r, z, p, A p of the pressure solves, reused step after step
  CgOptions cg_, forward_cg_, backward_cg_; // the last two named like solve_forward/_backward
  Eigen::VectorXd force_;                   // [fx, fy] per cell
  Eigen::VectorXd s1_, ua_, u1_, va_, v1_, p_, s_sl_, s_rev_, force_adj_scratch_;
  Eigen::VectorXd rhs_, lambda_; // -div of the forward solve; lambda = A^+ P p_adj
  // step_adjoint's work vectors, kept so that a step's adjoint allocates nothing.
  Eigen::VectorXd s1_adj_, u1_adj_, v1_adj_, p_adj_, div_adj_, ua_adj_, va_adj_, sl_adj_, rev_adj_,
      none_adj_;
  Eigen::VectorXd zeros_ = Eigen::VectorXd::Zero(cells()); // no inflow (MacCormack's passes)
  // The primal inputs of linear kernels' adjoints, which never read them: NaN, so that a read
  // would show in the gradient.
  Eigen::VectorXd unread_ =
      Eigen::VectorXd::Constant(std::max(2 * cells(), std::max(u_faces(), v_faces())),
                                std::numeric_limits<double>::quiet_NaN());
  CgSummary forward_summary_, backward_summary_;
};

} // namespace dpgen
