"""dpgen_torch.rollout and dpgen_torch.solve on the shipped ops (ctest torch.solvers): gradcheck
against finite differences; Revolve gradients equal to full-tape ones and to plain autograd
through the unrolled ops, bit for bit; Revolve's number of recomputed steps equal to the
optimum found by brute force; the implicit solve's gradient; errors."""
import functools
import sys
import unittest

import torch

import dpgen_torch
from dpgen_torch.solvers import revolve_advances

torch.manual_seed(0)
D = torch.float64
up = torch.ops.dpgen.upwind_step
lap = torch.ops.dpgen.neg_div_k_grad_1d


def rand(*shape):
    return torch.rand(*shape, dtype=D, requires_grad=True)


class Counting:
    """A step that counts its calls."""

    def __init__(self, f):
        self.f, self.calls = f, 0

    def __call__(self, *a, **k):
        self.calls += 1
        return self.f(*a, **k)


@functools.lru_cache(maxsize=None)
def optimal_advances(l, s):
    """The fewest forward steps that reverse l steps holding at most s states (brute force
    over every first split; independent of revolve_advances' closed form)."""
    if l <= 1:
        return 0
    if s == 1:
        return l * (l - 1) // 2
    return min(m + optimal_advances(l - m, s - 1) + optimal_advances(m, s) for m in range(1, l))


class Rollout(unittest.TestCase):
    def test_gradcheck(self):
        n = 9
        d0, u = rand(n), (torch.rand(n, dtype=D) - 0.5).requires_grad_()
        for cp in (0, 1, 3):
            with self.subTest(checkpoints=cp):
                self.assertTrue(torch.autograd.gradcheck(
                    lambda a, b: dpgen_torch.rollout(up, a, 11, checkpoints=cp, u=b, n=n,
                                                     dt=0.2, dx=1.0), (d0, u)))

    def test_tuple_state_gradcheck(self):
        # a step of two fields written as a lambda over two ops (any differentiable callable)
        n = 8
        k = (torch.rand(n + 1, dtype=D) + 0.5).requires_grad_()

        def step(d, e, u, k):
            return up(d, u, n, 0.1, 1.0) + 0.1 * e, e - 0.05 * lap(d, k, n, 1.0)

        args = (rand(n), rand(n), (torch.rand(n, dtype=D) - 0.5).requires_grad_(), k)
        for cp in (0, 2):
            with self.subTest(checkpoints=cp):
                self.assertTrue(torch.autograd.gradcheck(
                    lambda d, e, u, k: dpgen_torch.rollout(step, (d, e), 7, checkpoints=cp,
                                                           u=u, k=k), args))

    def grads(self, steps, cp, plain=False):
        n = 16
        g = torch.Generator().manual_seed(1)
        d0 = torch.rand(n, dtype=D, generator=g).requires_grad_()
        u = (torch.rand(n, dtype=D, generator=g) - 0.5).requires_grad_()
        if plain:  # autograd through the unrolled ops
            x = d0
            for _ in range(steps):
                x = up(x, u, n, 0.1, 1.0)
        else:
            x = dpgen_torch.rollout(up, d0, steps, checkpoints=cp, u=u, n=n, dt=0.1, dx=1.0)
        (x.square() * torch.arange(n, dtype=D)).sum().backward()
        return x.detach(), d0.grad, u.grad

    def test_revolve_equals_full_tape_bit_for_bit(self):
        steps = 40
        ref = self.grads(steps, 0)
        for result, label in [(self.grads(steps, cp), f"checkpoints={cp}")
                              for cp in (1, 2, 3, 7, 39, 40, 100)] + [
                                  (self.grads(steps, 0, plain=True), "plain autograd")]:
            with self.subTest(label):
                for a, b in zip(result, ref):
                    self.assertTrue(torch.equal(a, b))

    def test_equals_the_cpp_rollout_op(self):
        # the hand-written C++ op (torch/solver_ops.cpp, checkpoint.hpp) is the special case
        n, steps = 16, 30
        d0, u = torch.rand(n, dtype=D), torch.rand(n, dtype=D) - 0.5
        out = []
        for f in (lambda a, b: torch.ops.dpgen.upwind_rollout(a, b, steps, 0.1, 1.0, 4),
                  lambda a, b: dpgen_torch.upwind_rollout(a, b, steps, 0.1, 1.0, 4)):
            a, b = d0.clone().requires_grad_(), u.clone().requires_grad_()
            x = f(a, b)
            x.square().sum().backward()
            out.append((x.detach(), a.grad, b.grad))
        for a, b in zip(*out):
            torch.testing.assert_close(a, b, rtol=1e-14, atol=1e-14)

    def test_cpp_rollout_on_strips_equals_the_kernel_as_written(self):
        # 100000 cells: the C++ op runs each step on strips of cells on every thread
        # (dpgen/parallel.hpp); it must give the serial kernel's bits, and the same gradient.
        n, steps = 100000, 5
        d0, u = torch.rand(n, dtype=D), torch.rand(n, dtype=D) - 0.5
        ref = d0
        for _ in range(steps):
            ref = torch.ops.dpgen.upwind_step(ref, u, n, 0.1, 1.0)
        self.assertTrue(torch.equal(torch.ops.dpgen.upwind_rollout(d0, u, steps, 0.1, 1.0, 0), ref))
        out = []
        for f in (lambda a, b: torch.ops.dpgen.upwind_rollout(a, b, steps, 0.1, 1.0, 2),
                  lambda a, b: dpgen_torch.upwind_rollout(a, b, steps, 0.1, 1.0, 2)):
            a, b = d0.clone().requires_grad_(), u.clone().requires_grad_()
            f(a, b).square().sum().backward()
            out.append((a.grad, b.grad))
        for a, b in zip(*out):
            torch.testing.assert_close(a, b, rtol=1e-14, atol=1e-14)

    def test_revolve_recomputes_the_optimal_number_of_steps(self):
        n = 6
        for steps, cp in [(1, 1), (2, 1), (10, 1), (10, 2), (25, 3), (40, 4), (30, 30), (13, 5)]:
            with self.subTest(steps=steps, checkpoints=cp):
                step = Counting(up)
                d0 = rand(n)
                dpgen_torch.rollout(step, d0, steps, checkpoints=cp, u=torch.rand(n, dtype=D),
                                    n=n, dt=0.1, dx=1.0).sum().backward()
                # forward: steps calls; backward: the advances plus one recorded call per step
                advances = step.calls - 2 * steps
                self.assertEqual(advances, optimal_advances(steps, cp))
                self.assertEqual(advances, revolve_advances(steps, cp))
        step = Counting(up)
        dpgen_torch.rollout(step, rand(n), 20, checkpoints=0, u=torch.rand(n, dtype=D), n=n,
                            dt=0.1, dx=1.0).sum().backward()
        self.assertEqual(step.calls, 40)  # the full tape recomputes nothing

    def test_zero_steps_and_errors(self):
        d0 = rand(5)
        x = dpgen_torch.rollout(up, d0, 0, u=torch.rand(5, dtype=D), n=5, dt=0.1, dx=1.0)
        self.assertTrue(torch.equal(x, d0.detach()))
        x.sum().backward()
        self.assertTrue(torch.equal(d0.grad, torch.ones(5, dtype=D)))
        with self.assertRaisesRegex(ValueError, "steps must be an integer >= 0"):
            dpgen_torch.rollout(up, d0, -1, u=d0, n=5, dt=0.1, dx=1.0)
        with self.assertRaisesRegex(ValueError, "checkpoints must be 0"):
            dpgen_torch.rollout(up, d0, 3, checkpoints=-2, u=d0, n=5, dt=0.1, dx=1.0)
        with self.assertRaisesRegex(TypeError, "floating-point tensor"):
            dpgen_torch.rollout(up, torch.arange(5), 3, u=d0, n=5, dt=0.1, dx=1.0)
        with self.assertRaisesRegex(ValueError, r"maps states of shapes \[\(5,\)\] to \[\(10,\)\]"):
            dpgen_torch.rollout(up, d0, 3, u=d0, n=5, dt=0.1, dx=1.0, d_next_shape=[10])
        with self.assertRaisesRegex(RuntimeError, "argument 'u' has 3 elements"):
            dpgen_torch.rollout(up, d0, 3, u=torch.rand(3, dtype=D), n=5, dt=0.1, dx=1.0)
        # a tensor requiring grad captured by the step instead of passed: refused, not ignored
        u = rand(5)
        x = dpgen_torch.rollout(lambda d: up(d, u, 5, 0.1, 1.0), d0, 3)
        with self.assertRaisesRegex(ValueError, r"uses a tensor that requires grad \(sizes \[5\]"):
            x.sum().backward()


class Solve(unittest.TestCase):
    def test_gradcheck_symmetric(self):
        n = 12
        b = rand(n)
        k = (torch.rand(n + 1, dtype=D) + 0.5).requires_grad_()
        self.assertTrue(torch.autograd.gradcheck(
            lambda bb, kk: dpgen_torch.solve(lap, bb, k=kk, n=n, h=0.5, rtol=1e-13), (b, k)))
        # the diffusion special case is an instance (with a Jacobi preconditioner)
        self.assertTrue(torch.autograd.gradcheck(
            lambda bb, kk: dpgen_torch.diffusion_solve(bb, kk, 0.5, 1e-13), (b, k)))

    def test_gradcheck_nonsymmetric(self):
        # A(k, u) x = -(k x')' + (x - upwind_step(x, u)) / dt: advection-diffusion, not symmetric
        n = 10

        def operator(x, k, u):
            return lap(x, k, n, 1.0) + (x - up(x, u, n, 0.1, 1.0)) / 0.1

        b = rand(n)
        k = (torch.rand(n + 1, dtype=D) + 0.5).requires_grad_()
        u = (torch.rand(n, dtype=D) - 0.5).requires_grad_()
        self.assertTrue(torch.autograd.gradcheck(
            lambda bb, kk, uu: dpgen_torch.solve(operator, bb, k=kk, u=uu, symmetric=False,
                                                 rtol=1e-13), (b, k, u)))
        x = dpgen_torch.solve(operator, b, k=k, u=u, symmetric=False, rtol=1e-12)
        torch.testing.assert_close(operator(x, k, u), b.detach())

    def test_equals_the_cpp_solve_op(self):
        n = 20
        b, k = torch.rand(n, dtype=D), torch.rand(n + 1, dtype=D) + 0.5
        out = []
        for f in (lambda bb, kk: torch.ops.dpgen.diffusion_solve(bb, kk, 0.1, 1e-13),
                  lambda bb, kk: dpgen_torch.diffusion_solve(bb, kk, 0.1, 1e-13)):
            bb, kk = b.clone().requires_grad_(), k.clone().requires_grad_()
            x = f(bb, kk)
            (x * torch.arange(n, dtype=D)).sum().backward()
            out.append((x.detach(), bb.grad, kk.grad))
        for a, c in zip(*out):
            torch.testing.assert_close(a, c, rtol=1e-9, atol=1e-12)

    def test_errors(self):
        n = 20
        b, k = torch.rand(n, dtype=D), torch.rand(n + 1, dtype=D) + 0.5
        with self.assertRaises(dpgen_torch.ConvergenceError) as cm:
            dpgen_torch.solve(lap, b, k=k, n=n, h=0.1, rtol=1e-14, max_iterations=2)
        self.assertIn("solve forward: CG did not converge in 2 iterations", str(cm.exception))
        self.assertEqual(cm.exception.iterations, 2)
        self.assertGreater(cm.exception.residual, 0)
        with self.assertRaisesRegex(dpgen_torch.ConvergenceError, "not symmetric positive"):
            dpgen_torch.solve(lambda x: -x, b)
        with self.assertRaisesRegex(ValueError, "must return one tensor of b's shape"):
            dpgen_torch.solve(lap, b, k=k, n=n, h=0.1, out_shape=[n + 1])
        with self.assertRaisesRegex(ValueError, "needs 21 elements"):
            dpgen_torch.diffusion_solve(b, k[:n], 0.1)
        with self.assertRaisesRegex(ValueError, "h must be positive"):
            dpgen_torch.diffusion_solve(b, k, 0.0)
        with self.assertRaisesRegex(ValueError, "must be positive"):
            dpgen_torch.diffusion_solve(b, -k, 0.1)
        with self.assertRaisesRegex(ValueError, "diagonal"):
            dpgen_torch.solve(lap, b, k=k, n=n, h=0.1, diagonal=torch.zeros(n, dtype=D))
        kk = k.clone().requires_grad_()
        x = dpgen_torch.solve(lambda v: lap(v, kk, n, 0.1), b.clone().requires_grad_())
        with self.assertRaisesRegex(ValueError, r"solve: the callable uses a tensor"):
            x.sum().backward()


if __name__ == "__main__":
    sys.exit(0 if unittest.main(exit=False, verbosity=2).result.wasSuccessful() else 1)
