// Hand-written ops on top of the generated kernels, each one autograd node for a whole solver:
//   torch.ops.dpgen.upwind_rollout(d0, u, steps, dt, dx, checkpoints=0) -> d_steps
//     `steps` upwind steps (kernels/upwind_step.cpp) as one op; backward runs the adjoint
//     rollout (generated upwind_step_adjoint) with checkpoint.hpp: every state kept
//     (checkpoints=0) or binomial checkpointing with that many snapshots (identical result).
//   torch.ops.dpgen.diffusion_solve(b, k, h, rtol=1e-10, max_iterations=10000) -> x
//     x = A(k)^-1 b with A(k) = -d/dx(k d/dx) (kernels/neg_div_k_grad_1d.cpp) by CG; backward
//     is the transposed solve of implicit_solve.hpp (A^T lambda = x_bar, b_bar = lambda,
//     k_bar = -(d(A(k) x)/dk)^T lambda by the generated adjoint), never the unrolled iteration.
#include "neg_div_k_grad_1d_adjoint.hpp"
#include "neg_div_k_grad_1d_kernels.hpp"
#include "upwind_step_adjoint.hpp"
#include "upwind_step_kernels.hpp"

#include "dpgen/checkpoint.hpp"
#include "dpgen/implicit_solve.hpp"
#include "dpgen/parallel.hpp"
#include "dpgen/torch.hpp"

#include <torch/library.h>

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <utility>


namespace {

using Eigen::VectorXd;
using torch::autograd::AutogradContext;
using torch::autograd::variable_list;

Eigen::Map<const VectorXd> view(const torch::Tensor& t) {
  return {t.data_ptr<double>(), t.numel()};
}
Eigen::Map<VectorXd> view_mut(torch::Tensor& t) { return {t.data_ptr<double>(), t.numel()}; }

// ---- upwind_rollout ---------------------------------------------------------------------

// One upwind step on every thread: the kernel as written (serial; periodic, radius 1) run on
// strips of cells by dpgen/parallel.hpp, which gives the bits of one whole call.
void upwind_step_parallel(const double* d, const double* u, double* d_next, int n, double dt,
                          double dx) {
  const auto strip = [&](const std::array<const double*, 2>& in, double* out, int cells) {
    upwind_step(in[0], in[1], out, cells, dt, dx);
  };
  if (!dpgen::run_by_row_strips<2>({n, 1, 1, 1, /*periodic=*/true}, {d, u}, d_next, strip))
    upwind_step(d, u, d_next, n, dt, dx);
}

struct UpwindRollout : public torch::autograd::Function<UpwindRollout> {
  static torch::Tensor forward(AutogradContext* ctx, const torch::Tensor& d0,
                               const torch::Tensor& u, std::int64_t steps, double dt, double dx,
                               std::int64_t checkpoints) {
    const char* op = "dpgen::upwind_rollout";
    dpgen::torch_ops::check_array<double>(d0, op, "d0", "double");
    dpgen::torch_ops::check_array<double>(u, op, "u", "double");
    TORCH_CHECK(u.numel() == d0.numel(), op, ": argument 'u' has ", u.numel(),
                " elements but 'd0' has ", d0.numel(), " (one velocity per cell)");
    TORCH_CHECK(steps >= 0, op, ": steps must be >= 0, got ", steps);
    TORCH_CHECK(checkpoints >= 0, op, ": checkpoints must be >= 0 (0: keep every state), got ",
                checkpoints);
    const int n = dpgen::torch_ops::narrow<int>(d0.numel(), op, "d0.numel()");
    // Forward: two buffers, nothing stored (backward recomputes what it needs).
    torch::Tensor cur = d0.clone(), next = torch::empty_like(d0);
    for (std::int64_t t = 0; t < steps; ++t) {
      upwind_step_parallel(cur.data_ptr<double>(), u.data_ptr<double>(), next.data_ptr<double>(), n,
                           dt, dx);
      std::swap(cur, next);
    }
    ctx->save_for_backward({d0, u});
    ctx->saved_data["steps"] = steps;
    ctx->saved_data["dt"] = dt;
    ctx->saved_data["dx"] = dx;
    ctx->saved_data["checkpoints"] = checkpoints;
    return cur;
  }

  static variable_list backward(AutogradContext* ctx, variable_list grads) {
    dpgen::torch_ops::no_double_backward("dpgen::upwind_rollout");
    const auto saved = ctx->get_saved_variables();
    const torch::Tensor& d0 = saved[0];
    const torch::Tensor& u = saved[1];
    const int steps = static_cast<int>(ctx->saved_data["steps"].toInt());
    const double dt = ctx->saved_data["dt"].toDouble(), dx = ctx->saved_data["dx"].toDouble();
    const int checkpoints = static_cast<int>(ctx->saved_data["checkpoints"].toInt());
    const int n = static_cast<int>(d0.numel());
    const torch::Tensor seed = grads[0].defined() ? grads[0].contiguous() : torch::zeros_like(d0);
    torch::Tensor u_adj = torch::zeros_like(u);
    const double* u_ptr = u.data_ptr<double>();
    double* u_adj_ptr = u_adj.data_ptr<double>();
    auto step = [&](int, const VectorXd& s, VectorXd& s_next) {
      upwind_step_parallel(s.data(), u_ptr, s_next.data(), n, dt, dx);
    };
    auto step_adjoint = [&](int, const VectorXd& s, const VectorXd& next_adj, VectorXd& s_adj) {
      upwind_step_adjoint(s.data(), s_adj.data(), u_ptr, u_adj_ptr, next_adj.data(), n, dt, dx);
    };
    // The op's output is s_T: its gradient seeds the reverse sweep at t = steps.
    auto loss_adjoint = [&](int t, const VectorXd&, VectorXd& s_adj) {
      if (t == steps)
        s_adj += view(seed);
      return 0.0;
    };
    dpgen::CheckpointOptions options;
    options.step_assigns_every_element = true; // upwind_step writes every cell
    if (checkpoints > 0) {
      options.strategy = dpgen::CheckpointStrategy::revolve;
      options.snapshots = checkpoints;
    }
    const VectorXd s0 = view(d0);
    const dpgen::UnrolledGradient g =
        dpgen::unrolled_gradient(s0, steps, step, step_adjoint, loss_adjoint, options);
    torch::Tensor d0_adj = torch::empty_like(d0);
    view_mut(d0_adj) = g.state_adjoint;
    return {d0_adj, u_adj, torch::Tensor(), torch::Tensor(), torch::Tensor(), torch::Tensor()};
  }
};

torch::Tensor upwind_rollout(const torch::Tensor& d0, const torch::Tensor& u, std::int64_t steps,
                             double dt, double dx, std::int64_t checkpoints) {
  return UpwindRollout::apply(d0, u, steps, dt, dx, checkpoints);
}

// ---- diffusion_solve ----------------------------------------------------------------------

dpgen::CgOptions cg_options(double rtol, std::int64_t max_iterations, int n, const double* k,
                            double h) {
  dpgen::CgOptions o;
  o.relative_tolerance = rtol;
  o.max_iterations = static_cast<int>(max_iterations);
  o.name = "dpgen::diffusion_solve";
  o.jacobi_diagonal.resize(n); // diag A = (k_i + k_{i+1}) / h^2
  for (int i = 0; i < n; ++i)
    o.jacobi_diagonal[i] = (k[i] + k[i + 1]) / (h * h);
  return o;
}

struct DiffusionSolve : public torch::autograd::Function<DiffusionSolve> {
  static torch::Tensor forward(AutogradContext* ctx, const torch::Tensor& b,
                               const torch::Tensor& k, double h, double rtol,
                               std::int64_t max_iterations) {
    const char* op = "dpgen::diffusion_solve";
    dpgen::torch_ops::check_array<double>(b, op, "b", "double");
    dpgen::torch_ops::check_array<double>(k, op, "k", "double");
    TORCH_CHECK(k.numel() == b.numel() + 1, op, ": argument 'k' (face coefficients) needs ",
                b.numel() + 1, " elements for ", b.numel(), " cells, got ", k.numel());
    TORCH_CHECK(h > 0, op, ": h must be positive, got ", h);
    TORCH_CHECK(max_iterations > 0 && max_iterations <= (1 << 30), op,
                ": max_iterations must be in [1, 2^30], got ", max_iterations);
    TORCH_CHECK(torch::all(k > 0).item<bool>(), op,
                ": every face coefficient k must be positive (A(k) is then SPD)");
    const int n = dpgen::torch_ops::narrow<int>(b.numel(), op, "b.numel()");
    const double* kp = k.data_ptr<double>();
    auto apply = [&](const VectorXd& x, VectorXd& y) {
      y.resize(n);
      neg_div_k_grad_1d(x.data(), kp, y.data(), n, h);
    };
    const dpgen::LinearSolveResult r =
        dpgen::solve_forward(apply, VectorXd(view(b)), cg_options(rtol, max_iterations, n, kp, h));
    torch::Tensor x = torch::empty_like(b);
    view_mut(x) = r.solution;
    ctx->save_for_backward({k, x});
    ctx->saved_data["h"] = h;
    ctx->saved_data["rtol"] = rtol;
    ctx->saved_data["max_iterations"] = max_iterations;
    return x;
  }

  static variable_list backward(AutogradContext* ctx, variable_list grads) {
    dpgen::torch_ops::no_double_backward("dpgen::diffusion_solve");
    const auto saved = ctx->get_saved_variables();
    const torch::Tensor& k = saved[0];
    const torch::Tensor& x = saved[1];
    const double h = ctx->saved_data["h"].toDouble();
    const int n = static_cast<int>(x.numel());
    const double* kp = k.data_ptr<double>();
    if (!grads[0].defined())
      return {torch::Tensor(), torch::Tensor(), torch::Tensor(), torch::Tensor(),
              torch::Tensor()};
    auto apply = [&](const VectorXd& v, VectorXd& y) { // A is symmetric: A^T = A
      y.resize(n);
      neg_div_k_grad_1d(v.data(), kp, y.data(), n, h);
    };
    // (d(A(k) x)/dk)^T lambda, added into g: the generated adjoint w.r.t. k, seeded with lambda
    // (its adjoint w.r.t. p goes to a scratch buffer).
    VectorXd p_scratch(n);
    auto operator_adjoint = [&](const VectorXd& xv, const VectorXd& lambda, VectorXd& g) {
      p_scratch.setZero();
      neg_div_k_grad_1d_adjoint(xv.data(), p_scratch.data(), kp, g.data(), lambda.data(), n, h);
    };
    VectorXd b_bar, k_bar = VectorXd::Zero(n + 1);
    dpgen::implicit_solve_backward(
        apply, operator_adjoint, VectorXd(view(x)), VectorXd(view(grads[0].contiguous())), b_bar,
        k_bar,
        cg_options(ctx->saved_data["rtol"].toDouble(), ctx->saved_data["max_iterations"].toInt(),
                   n, kp, h));
    torch::Tensor b_adj = torch::empty_like(x), k_adj = torch::empty_like(k);
    view_mut(b_adj) = b_bar;
    view_mut(k_adj) = k_bar;
    return {b_adj, k_adj, torch::Tensor(), torch::Tensor(), torch::Tensor()};
  }
};

torch::Tensor diffusion_solve(const torch::Tensor& b, const torch::Tensor& k, double h,
                              double rtol, std::int64_t max_iterations) {
  return DiffusionSolve::apply(b, k, h, rtol, max_iterations);
}

} // namespace

TORCH_LIBRARY_FRAGMENT(dpgen, m) {
  m.def("upwind_rollout(Tensor d0, Tensor u, int steps, float dt, float dx, int checkpoints=0) "
        "-> Tensor",
        &upwind_rollout);
  m.def("diffusion_solve(Tensor b, Tensor k, float h, float rtol=1e-10, "
        "int max_iterations=10000) -> Tensor",
        &diffusion_solve);
}
