"""The PyTorch ops (ctest torch.ops): torch.autograd.gradcheck in double precision for the op
of every kernel in kernels/ and torch/kernels/, and for the whole-solver ops; the argument
checks; checkpointed and full-tape rollouts agree; the solve's gradient is the implicit one."""
import glob
import os
import re
import sys
import unittest

import torch

import dpgen_torch  # loads libdpgen_torch.so

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
torch.manual_seed(0)
D = torch.float64


def rand(*shape):
    return torch.rand(*shape, dtype=D, requires_grad=True)


# For each kernel op: the inputs of a small but non-trivial call.
def cases():
    n, nx, ny = 9, 6, 5
    return {
        # u of both signs: both upwind branches
        "upwind_step": ((rand(n), (torch.rand(n, dtype=D) - 0.5).requires_grad_(), n, 0.3, 1.0), {}),
        "divergence2d": ((rand(ny, nx), rand(ny, nx), nx, ny, 0.5), {}),
        "laplacian2d": ((rand(ny, nx), nx, ny, 0.5), {}),
        # k has n + 1 face values: the output takes p's shape, k's size is checked
        "neg_div_k_grad_1d": ((rand(n), rand(n + 1), n, 0.5), {}),
        # the multigrid transfers: outputs of another shape than the first argument
        "mg_prolong_x": ((rand(ny, nx), nx, ny, 1.0, 0.0, -1.0, 0.5), {"f_shape": [ny, 2 * nx]}),
        "mg_prolong_y": ((rand(ny, 2 * nx), nx, ny, 0.0, 1.0, 0.5, -1.0),
                         {"f_shape": [2 * ny, 2 * nx]}),
        "mg_average_2x2": ((rand(2 * ny, 2 * nx), nx, ny), {"c_shape": [ny, nx]}),
        # the flow solver's MAC-grid kernels (u: ny x (nx+1) faces, v: (ny+1) x nx faces);
        # the semi-Lagrangian ones read at data-dependent indices, small steps keep the
        # departure points away from cell edges for the finite differences
        # px, py: 1 for a periodic axis (both settings covered across the cases)
        "flow_advect_marker": ((rand(ny, nx), rand(ny, nx + 1), rand(ny + 1, nx), rand(ny, nx),
                                nx, ny, 0.3, 0, 0), {}),
        "flow_maccormack_marker": ((rand(ny, nx), rand(ny, nx), rand(ny, nx), rand(ny, nx + 1),
                                    rand(ny + 1, nx), rand(ny, nx), nx, ny, 0.3, 1, 0), {}),
        # (the last argument zt = 1: zero tangential velocity beyond the closed walls)
        "flow_advect_u": ((rand(ny, nx + 1), rand(ny + 1, nx), nx, ny, 0.3, 1, 0, 1), {}),
        "flow_advect_v": ((rand(ny, nx + 1), rand(ny + 1, nx), nx, ny, 0.3, 0, 1, 1),
                          {"v_out_shape": [ny + 1, nx]}),
        "flow_divergence": ((rand(ny, nx + 1), rand(ny + 1, nx), nx, ny, 0.5, 1, 1),
                            {"div_shape": [ny, nx]}),
        "flow_subtract_gradient_u": ((rand(ny, nx + 1), rand(ny, nx), nx, ny, 0.5, 1), {}),
        "flow_subtract_gradient_v": ((rand(ny + 1, nx), rand(ny, nx), nx, ny, 0.5, 0), {}),
        "flow_buoyancy": ((rand(ny + 1, nx), rand(ny, nx), rand(ny + 1, nx), nx, ny, 0.2, 0.1, 1),
                          {}),
        "flow_force_u": ((rand(ny, nx + 1), rand(ny, nx), nx, ny, 0.1, 1), {}),
        "flow_pressure_operator": ((rand(ny, nx), rand(ny, nx), nx, ny, 0.5, 1.0, 0.0), {}),
    }


def shipped_kernels():
    names = []
    for f in glob.glob(os.path.join(ROOT, "kernels", "*.cpp")) + glob.glob(
            os.path.join(ROOT, "torch", "kernels", "*.cpp")):
        with open(f) as src:
            names += re.findall(r"DPGEN_KERNEL\s+void\s+(\w+)\s*\(", src.read())
    return sorted(set(names))


class KernelOps(unittest.TestCase):
    def test_every_shipped_kernel_has_a_case(self):
        self.assertEqual(sorted(cases()), shipped_kernels())

    def test_gradcheck(self):
        for name, (args, kwargs) in cases().items():
            with self.subTest(op=name):
                op = getattr(torch.ops.dpgen, name)
                self.assertTrue(torch.autograd.gradcheck(
                    lambda *a: op(*a, **kwargs), args, eps=1e-6, atol=1e-7, rtol=1e-5))

    def test_inactive_inputs(self):
        # An input that needs no gradient gets a null adjoint (the generated adjoint skips its
        # loops); the others' gradients are the same, bit for bit.
        for name, (args, kwargs) in cases().items():
            op = getattr(torch.ops.dpgen, name)
            tensors = [i for i, a in enumerate(args) if torch.is_tensor(a)]
            if len(tensors) < 2:
                continue
            fresh = lambda: [a.detach().clone() if torch.is_tensor(a) else a for a in args]
            full = fresh()
            for i in tensors:
                full[i].requires_grad_()
            out = op(*full, **kwargs)
            (out[0] if isinstance(out, tuple) else out).sum().backward()
            for i in tensors:
                with self.subTest(op=name, active=i):
                    one = fresh()
                    one[i].requires_grad_()
                    out = op(*one, **kwargs)
                    (out[0] if isinstance(out, tuple) else out).sum().backward()
                    self.assertTrue(torch.equal(one[i].grad, full[i].grad))

    def test_forward_matches_torch(self):
        # laplacian2d against slicing: the op computes what the kernel says
        nx, ny, h = 7, 5, 0.5
        a = torch.rand(ny, nx, dtype=D)
        out = torch.ops.dpgen.laplacian2d(a, nx, ny, h)
        ref = torch.zeros_like(a)
        ref[1:-1, 1:-1] = (a[1:-1, :-2] + a[1:-1, 2:] + a[:-2, 1:-1] + a[2:, 1:-1]
                           - 4 * a[1:-1, 1:-1]) / h**2
        torch.testing.assert_close(out, ref)
        self.assertEqual(out.shape, a.shape)

    def test_parallel_forward_is_the_kernel(self):
        # A kernel whose nests set each element once runs as its IR printed with those nests on
        # every thread (emit_forward.cpp: emit_parallel_forward), above 8192 iterations: the
        # kernel's values bit for bit, whatever the number of threads. Against the kernel as
        # written: upwind_rollout calls it (one step); against itself on one thread: the others.
        n, nx, ny = 1 << 15, 256, 192
        d, u = torch.rand(n, dtype=D), torch.rand(n, dtype=D) - 0.5
        a, b = torch.rand(ny, nx, dtype=D), torch.rand(ny, nx, dtype=D)
        calls = {
            "upwind_step": lambda: torch.ops.dpgen.upwind_step(d, u, n, 0.3, 1.0),
            "laplacian2d": lambda: torch.ops.dpgen.laplacian2d(a, nx, ny, 0.5),
            "divergence2d": lambda: torch.ops.dpgen.divergence2d(a, b, nx, ny, 0.5),
            "mg_prolong_y": lambda: torch.ops.dpgen.mg_prolong_y(
                a, nx // 2, ny, 0.0, 1.0, 0.5, -1.0, f_shape=[2 * ny, nx]),
            "flow_pressure_operator": lambda: torch.ops.dpgen.flow_pressure_operator(
                a, b, nx, ny, 0.5, 1.0, 0.0),
        }
        threads = torch.get_num_threads()
        try:
            torch.set_num_threads(1)
            one = {name: call() for name, call in calls.items()}
            torch.set_num_threads(2)
            for name, call in calls.items():
                with self.subTest(op=name):
                    self.assertTrue(torch.equal(call(), one[name]))
            self.assertTrue(torch.equal(one["upwind_step"],
                                        torch.ops.dpgen.upwind_rollout(d, u, 1, 0.3, 1.0)))
        finally:
            torch.set_num_threads(threads)

    def test_outputs_not_written_read_zero(self):
        # An output the kernel writes element by element (0 .. numel - 1) is allocated without a
        # zero fill; any other keeps it: a larger d_next than the n cells written, and
        # laplacian2d's boundary. Freed NaN-filled memory of the same size first (small enough
        # for the heap, which hands it out again), so that garbage would show.
        n = 4096
        d, u = torch.rand(n, dtype=D), torch.rand(n, dtype=D) - 0.5
        for _ in range(3):
            garbage = torch.full((n + 64,), float("nan"), dtype=D)
            del garbage
            out = torch.ops.dpgen.upwind_step(d, u, n, 0.1, 1.0, d_next_shape=[n + 64])
            self.assertTrue(torch.equal(out[n:], torch.zeros(64, dtype=D)))
            self.assertTrue(torch.equal(out[:n], torch.ops.dpgen.upwind_step(d, u, n, 0.1, 1.0)))
            self.assertFalse(torch.isnan(out).any())
            side = 48
            garbage = torch.full((side, side), float("nan"), dtype=D)
            del garbage
            lap = torch.ops.dpgen.laplacian2d(torch.rand(side, side, dtype=D), side, side, 0.5)
            self.assertTrue(torch.equal(lap[0], torch.zeros(side, dtype=D)))
            self.assertTrue(torch.equal(lap[:, -1], torch.zeros(side, dtype=D)))

    def test_output_shape_argument(self):
        a = torch.rand(30, dtype=D)
        out = torch.ops.dpgen.laplacian2d(a, 6, 5, 1.0, out_shape=[5, 6])
        self.assertEqual(tuple(out.shape), (5, 6))

    def errors(self, fn, *patterns):
        with self.assertRaises(RuntimeError) as cm:
            fn()
        for p in patterns:
            self.assertIn(p, str(cm.exception))

    def test_bad_arguments(self):
        n = 8
        d, u = torch.rand(n, dtype=D), torch.rand(n, dtype=D)
        up = torch.ops.dpgen.upwind_step
        self.errors(lambda: up(d.float(), u, n, 0.1, 1.0), "dpgen::upwind_step", "argument 'd'",
                    "Float", "double")
        self.errors(lambda: up(d, torch.rand(2 * n, dtype=D)[::2], n, 0.1, 1.0),
                    "argument 'u'", "not contiguous")
        self.errors(lambda: up(d, torch.empty(n, dtype=D, device="meta"), n, 0.1, 1.0),
                    "argument 'u'", "meta", "CPU")
        self.errors(lambda: up(d, u[:5], n, 0.1, 1.0), "argument 'u' has 5 elements",
                    "reaches element 7", "n = 8")
        self.errors(lambda: up(d, u, n, 0.1, 1.0, d_next_shape=[4]), "output 'd_next' has 4")
        self.errors(lambda: up(d, u, 2**40, 0.1, 1.0), "argument 'd' has 8 elements")
        k = torch.rand(n, dtype=D)  # needs n + 1 face values
        self.errors(lambda: torch.ops.dpgen.neg_div_k_grad_1d(d, k, n, 1.0),
                    "argument 'k' has 8 elements", "reaches element 8")
        # laplacian2d writes all nx*ny = 30 cells of out (default shape: a's) but reads a only
        # up to element (ny-2)*nx + nx-2 + nx = 28: the checks are exact, not nx*ny for all
        lap = torch.ops.dpgen.laplacian2d
        self.errors(lambda: lap(torch.rand(29, dtype=D), 6, 5, 1.0),
                    "output 'out' has 29 elements", "reaches element 29")
        lap(torch.rand(29, dtype=D), 6, 5, 1.0, out_shape=[5, 6])  # enough
        self.errors(lambda: lap(torch.rand(28, dtype=D), 6, 5, 1.0, out_shape=[5, 6]),
                    "argument 'a' has 28 elements", "reaches element 28")

    def test_data_dependent_reads_are_checked(self):
        # flow_advect_marker reads s only at the departure points (data-dependent): at rest, cell
        # (j, i) reads s[j * nx + i], so an s of nx * ny - 1 values is one short; pushed left
        # (u = 50: departure points clamp to column 0) the last cell is never read.
        nx, ny = 4, 3
        op = torch.ops.dpgen.flow_advect_marker
        short = rand(nx * ny - 1)
        u0, v0, inflow = torch.zeros(ny, nx + 1, dtype=D), torch.zeros(ny + 1, nx, dtype=D), rand(ny, nx)
        self.errors(lambda: op(short, u0, v0, inflow, nx, ny, 0.3, 0, 0, s_out_shape=[ny, nx]),
                    "dpgen::flow_advect_marker: 's' has 11 elements, but the kernel touches "
                    "element 11", "nx = 4, ny = 3")
        u_left = torch.full((ny, nx + 1), 50.0, dtype=D)
        out = op(short, u_left, v0, inflow, nx, ny, 0.3, 0, 0, s_out_shape=[ny, nx])
        self.assertEqual(list(out.shape), [ny, nx])

    def test_no_double_backward(self):
        n = 6
        d = rand(n)
        out = torch.ops.dpgen.upwind_step(d, torch.rand(n, dtype=D), n, 0.1, 1.0)
        self.errors(lambda: torch.autograd.grad(out.square().sum(), d, create_graph=True),
                    "second derivatives")


class OtherShapes(unittest.TestCase):
    """Ops of the test library libdpgen_torch_test.so (loaded when built)."""

    def setUp(self):
        if not hasattr(torch.ops.dpgen, "riemann_outparams"):
            self.skipTest("libdpgen_torch_test.so not loaded")

    def test_rows_of_fixed_length(self):
        # double (*u)[6]: the tensors are passed as rows of NX = 6
        ny = 5
        k = (torch.rand(ny, 6, dtype=D) + 0.5).requires_grad_()
        self.assertTrue(torch.autograd.gradcheck(
            lambda kk, uu: torch.ops.dpgen.varcoef_laplace2d_rowarray(kk, uu, ny, 2.0),
            (k, rand(ny, 6))))
        self.assertRaisesRegex(RuntimeError, "argument 'u' has 24 elements",
                               lambda: torch.ops.dpgen.varcoef_laplace2d_rowarray(
                                   k.detach(), torch.rand(24, dtype=D), ny, 2.0,
                                   lu_shape=[ny, 6]))

    def test_both_ends_of_a_shifted_read(self):
        # out[i] = f(a[i + shift], a[i + shift + 1]), i in 1..n-1
        op = torch.ops.dpgen.shifted_read
        a = rand(9)
        self.assertTrue(torch.autograd.gradcheck(lambda x: op(x, 8, 0, out_shape=[8]), (a,)))
        # a negative int argument reaches the kernel (narrow<int> refused every one before)
        self.assertTrue(torch.autograd.gradcheck(lambda x: op(x, 8, -1, out_shape=[8]), (a,)))
        with self.assertRaises(RuntimeError) as cm:  # a[-1] at i = 1
            op(a.detach(), 8, -2, out_shape=[8])
        self.assertIn("reaches element -1 of argument 'a'", str(cm.exception))
        self.assertIn("shift = -2", str(cm.exception))
        with self.assertRaises(RuntimeError) as cm:  # a[9] at i = 7
            op(a.detach(), 8, 1, out_shape=[8])
        self.assertIn("argument 'a' has 9 elements", str(cm.exception))
        self.assertIn("reaches element 9", str(cm.exception))

    def test_c_kernel_with_four_outputs_and_work_arrays(self):
        # fh, fq are written by the first loop and read by the second (work arrays)
        n = 9
        h = (torch.rand(n, dtype=D) + 1.0).requires_grad_()
        q = (torch.rand(n, dtype=D) - 0.5).requires_grad_()
        out = torch.ops.dpgen.riemann_outparams(h, q, n, 9.81, 0.1)
        self.assertEqual(len(out), 4)
        self.assertTrue(torch.autograd.gradcheck(
            lambda a, b: torch.ops.dpgen.riemann_outparams(a, b, n, 9.81, 0.1), (h, q)))


class SolverOps(unittest.TestCase):
    def test_rollout_gradcheck(self):
        n = 10
        d0, u = rand(n), (torch.rand(n, dtype=D) - 0.5).requires_grad_()
        for cp in (0, 3):
            with self.subTest(checkpoints=cp):
                self.assertTrue(torch.autograd.gradcheck(
                    lambda a, b: dpgen_torch.upwind_rollout(a, b, 12, 0.2, 1.0, cp), (d0, u)))

    def test_rollout_matches_steps_and_checkpoints_are_identical(self):
        n, steps = 16, 40
        d0 = torch.rand(n, dtype=D)
        u = torch.rand(n, dtype=D) - 0.5
        x = d0
        for _ in range(steps):
            x = torch.ops.dpgen.upwind_step(x, u, n, 0.1, 1.0)
        torch.testing.assert_close(dpgen_torch.upwind_rollout(d0, u, steps, 0.1, 1.0), x,
                                   rtol=0, atol=0)
        grads = []
        for cp in (0, 1, 5, 100):
            a, b = d0.clone().requires_grad_(), u.clone().requires_grad_()
            (dpgen_torch.upwind_rollout(a, b, steps, 0.1, 1.0, cp) ** 2).sum().backward()
            grads.append((a.grad, b.grad))
        for g in grads[1:]:  # bit-identical (checkpoint.hpp)
            self.assertTrue(torch.equal(g[0], grads[0][0]) and torch.equal(g[1], grads[0][1]))

    def test_solve_gradcheck(self):
        n = 12
        b = rand(n)
        k = (torch.rand(n + 1, dtype=D) + 0.5).requires_grad_()
        self.assertTrue(torch.autograd.gradcheck(
            lambda bb, kk: dpgen_torch.diffusion_solve(bb, kk, 0.5, 1e-13), (b, k)))

    def test_solve_residual_and_errors(self):
        n = 20
        b = torch.rand(n, dtype=D)
        k = torch.rand(n + 1, dtype=D) + 0.5
        x = dpgen_torch.diffusion_solve(b, k, 0.1)
        torch.testing.assert_close(torch.ops.dpgen.neg_div_k_grad_1d(x, k, n, 0.1), b)
        # dpgen_torch.diffusion_solve is dpgen_torch.solve of neg_div_k_grad_1d
        with self.assertRaises(ValueError) as cm:
            dpgen_torch.diffusion_solve(b, k[:n], 0.1)
        self.assertIn("needs 21 elements", str(cm.exception))
        with self.assertRaises(dpgen_torch.ConvergenceError) as cm:
            dpgen_torch.diffusion_solve(b, k, 0.1, 1e-14, 2)
        self.assertIn("solve forward: CG did not converge", str(cm.exception))
        # the C++ op of torch/solver_ops.cpp
        with self.assertRaises(RuntimeError) as cm:
            torch.ops.dpgen.diffusion_solve(b, k[:n], 0.1)
        self.assertIn("needs 21 elements", str(cm.exception))
        with self.assertRaises(RuntimeError) as cm:
            torch.ops.dpgen.diffusion_solve(b, k, 0.1, 1e-14, 2)
        self.assertIn("diffusion_solve forward", str(cm.exception))


if __name__ == "__main__":
    sys.exit(0 if unittest.main(exit=False, verbosity=2).result.wasSuccessful() else 1)
