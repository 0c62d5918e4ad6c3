"""Solvers over any dpgen op, each one autograd node whose backward runs the generated adjoints:

rollout(step, state, steps, checkpoints=K, **params)
    state_T of state_{t+1} = step(state_t, **params). Backward is the reverse sweep, one
    step's backward (its generated adjoint) at a time, t = T-1 .. 0; the states it needs come
    from a tape of every state (checkpoints=0) or are recomputed from at most K stored states
    (binomial checkpointing, Revolve's schedule). Both make the same calls on the same states
    in the same order, so their gradients are equal bit for bit.
solve(operator, b, **params)
    x with A(params) x = b, where operator(x, **params) = A(params) x is linear in x (by CG,
    or BiCGSTAB for symmetric=False). Backward is the implicit function rule: one more solve
    A^T lambda = x_bar (A itself when symmetric; else A^T v from the operator's own backward),
    then b_bar = lambda and params_bar = -(d(A(params) x)/d params)^T lambda, the operator
    op's backward seeded with -lambda. Never the unrolled iterations: memory O(n).
"""
import math

import torch

__all__ = ["rollout", "solve", "ConvergenceError", "revolve_advances"]


# ---- rollout ---------------------------------------------------------------------------------

def _as_states(value, what):
    states = (value,) if torch.is_tensor(value) else tuple(value)
    for s in states:
        if not torch.is_tensor(s) or not s.is_floating_point():
            raise TypeError(f"dpgen_torch.rollout: {what} must be a floating-point tensor or a "
                            f"tuple of them, got {type(s).__name__}"
                            + (f" of dtype {s.dtype}" if torch.is_tensor(s) else ""))
    return states


def _step(step, states, params, t):
    """states_{t+1} = step(*states_t, **params), with its shape checked against states_t."""
    out = _as_states(step(*states, **params), f"the step's result at t = {t}")
    if len(out) != len(states) or any(a.shape != b.shape for a, b in zip(out, states)):
        raise ValueError(
            "dpgen_torch.rollout: the step maps states of shapes "
            f"{[tuple(s.shape) for s in states]}"
            f" to {[tuple(s.shape) for s in out]} at t = {t}; a step must return the state it "
            "takes (pass the other outputs' shapes, e.g. <output>_shape=..., as parameters)")
    return out


def _only_declared_leaves(outputs, wrt, what):
    """Raises if the graph of `outputs` reaches a tensor requiring grad that is not in `wrt`:
    a step or operator that closes over one (an nn.Module's weights, say) would silently get no
    gradient for it, since the backward differentiates with respect to its arguments only."""
    declared = {id(t) for t in wrt}
    seen, stack = set(), [t.grad_fn for t in outputs if t.grad_fn is not None]
    while stack:
        fn = stack.pop()
        if fn in seen:
            continue
        seen.add(fn)
        leaf = getattr(fn, "variable", None)  # AccumulateGrad: a leaf requiring grad
        if leaf is not None:
            if id(leaf) not in declared:
                raise ValueError(
                    f"dpgen_torch.{what}: the callable uses a tensor that requires grad (sizes "
                    f"{list(leaf.shape)}) but is not one of its arguments, and would get no "
                    "gradient; pass it as a keyword parameter instead of capturing it")
            continue
        stack.extend(f for f, _ in fn.next_functions if f is not None)


def revolve_advances(steps, snapshots):
    """Griewank's minimal number of forward steps ("advances") that reversing `steps` steps
    costs while holding at most `snapshots` states (the initial one included):
        t(l, s) = r l - beta(s + 1, r - 1),  beta(s, r) = C(s + r, s),
    r the smallest integer with l <= beta(s, r). rollout's Revolve backward advances exactly
    this many times (plus one recorded step per adjoint step)."""
    if snapshots < 1:
        raise ValueError(f"revolve needs at least 1 snapshot, got {snapshots}")
    if steps <= 1:
        return 0
    if snapshots == 1:  # r = l - 1: every state recomputed from the first
        return steps * (steps - 1) // 2
    r = 0
    while math.comb(snapshots + r, snapshots) < steps:
        r += 1
    return r * steps - math.comb(snapshots + r, r - 1)


def _revolve_split(l, s):
    """How far the first snapshot goes when reversing l >= 2 steps with s >= 2 states: the
    smallest m minimising m + t(l - m, s - 1) + t(m, s) (advance m, reverse the right part
    with one state less, then the left part). The cost is convex in m: bisect on its slope."""
    def cost(m):
        return m + revolve_advances(l - m, s - 1) + revolve_advances(m, s)
    lo, hi = 1, l - 1
    while lo < hi:
        mid = (lo + hi) // 2
        if cost(mid + 1) >= cost(mid):
            hi = mid
        else:
            lo = mid + 1
    return lo


class _Rollout(torch.autograd.Function):
    @staticmethod
    def forward(ctx, step, steps, checkpoints, names, consts, n_states, *tensors):
        states = tuple(tensors[:n_states])
        params = dict(zip(names, tensors[n_states:]), **consts)
        tape = [] if checkpoints == 0 else None  # every state but the last (full tape)
        s = states
        for t in range(steps):
            if tape is not None and t > 0:
                tape.append(s)
            s = _step(step, s, params, t)
        ctx.step, ctx.steps, ctx.checkpoints = step, steps, checkpoints
        ctx.names, ctx.consts, ctx.n_states = names, consts, n_states
        ctx.tape = tape
        ctx.save_for_backward(*tensors)
        # an output must not be an input (steps = 0, or a step that returns its argument)
        return tuple(x.clone() if any(x is y for y in tensors) else x for x in s)

    @staticmethod
    def backward(ctx, *grads):
        saved = ctx.saved_tensors
        n = ctx.n_states
        states0, pvals = tuple(saved[:n]), saved[n:]
        step, names, consts = ctx.step, ctx.names, ctx.consts
        need_p = [ctx.needs_input_grad[6 + n + i] for i in range(len(pvals))]
        adj = [g if g is not None else torch.zeros_like(s) for g, s in zip(grads, states0)]
        acc = [None] * len(pvals)
        no_grad_params = dict(zip(names, pvals), **consts)

        def adjoint_step(t, s):
            # adj = dL/ds_{t+1} in, dL/ds_t out; parameter adjoints added to acc
            nonlocal adj
            with torch.enable_grad():
                x = tuple(si.detach().requires_grad_() for si in s)
                p = [v.detach().requires_grad_() if need else v.detach()
                     for v, need in zip(pvals, need_p)]
                y = _step(step, x, dict(zip(names, p), **consts), t)
                wrt = list(x) + [v for v, need in zip(p, need_p) if need]
                if t == ctx.steps - 1:  # once: the graph of every step has the same leaves
                    _only_declared_leaves(y, list(x) + list(p), "rollout")
                g = torch.autograd.grad(y, wrt, grad_outputs=adj, allow_unused=True)
            adj = [gi if gi is not None else torch.zeros_like(xi) for gi, xi in zip(g[:n], x)]
            k = n
            for i, need in enumerate(need_p):
                if need:
                    if g[k] is not None:
                        acc[i] = g[k] if acc[i] is None else acc[i] + g[k]
                    k += 1

        def advance(s, t0, count):
            with torch.no_grad():
                for t in range(t0, t0 + count):
                    s = _step(step, s, no_grad_params, t)
            return s

        if ctx.checkpoints == 0:
            tape = [states0] + ctx.tape
            for t in range(ctx.steps - 1, -1, -1):
                adjoint_step(t, tape[t])
        else:
            # Revolve: a stack of frames [t0, l, s, base]; a frame reverses steps [t0, t0 + l)
            # from its base state s_t0 holding at most s states, its base included. At most
            # `checkpoints` bases are alive at once (each push has one state less to use).
            frames = [[0, ctx.steps, ctx.checkpoints, states0]]
            while frames:
                f = frames[-1]
                t0, l, s, base = f
                if l == 0:
                    frames.pop()
                elif l == 1:
                    adjoint_step(t0, base)
                    f[1] = 0
                elif s == 1:  # the base only: recompute every state from it
                    for t in range(t0 + l - 1, t0 - 1, -1):
                        adjoint_step(t, advance(base, t0, t - t0))
                    f[1] = 0
                else:
                    m = _revolve_split(l, s)
                    frames.append([t0 + m, l - m, s - 1, advance(base, t0, m)])
                    f[1] = m  # then the left part, with all s states again
        state_grads = [a if ctx.needs_input_grad[6 + i] else None for i, a in enumerate(adj)]
        param_grads = [a if need and a is not None else
                       (torch.zeros_like(v) if need else None)
                       for a, v, need in zip(acc, pvals, need_p)]
        return (None,) * 6 + tuple(state_grads) + tuple(param_grads)


def rollout(step, state, steps, checkpoints=0, **params):
    """state_T after `steps` applications of state_{t+1} = step(state_t, **params), as one
    autograd node whose backward runs step's backward (for a dpgen op: its generated adjoint)
    once per step, from t = T-1 down to 0.

    step: a dpgen op (or any differentiable callable, e.g. a lambda composing ops) whose first
    argument is the state and whose result is the next state of the same shape; for a tuple
    state, step(*state, **params) returns a tuple of the same shapes. params: the step's other
    arguments by name (tensor parameters get gradients, summed over the steps; numbers and
    shapes are passed through). checkpoints: 0 keeps every state (memory: steps states); K >= 1
    holds at most K states at once, the initial one included, and recomputes the others with
    Revolve's binomial schedule (revolve_advances(steps, K) extra steps). The gradients are
    identical bit for bit either way. The step must be deterministic.
    """
    if int(steps) != steps or steps < 0:
        raise ValueError(f"dpgen_torch.rollout: steps must be an integer >= 0, got {steps}")
    if int(checkpoints) != checkpoints or checkpoints < 0:
        raise ValueError("dpgen_torch.rollout: checkpoints must be 0 (keep every state) or the "
                         f"number of states to hold, >= 1; got {checkpoints}")
    single = torch.is_tensor(state)
    states = _as_states(state, "state")
    names = tuple(k for k, v in params.items() if torch.is_tensor(v))
    consts = {k: v for k, v in params.items() if not torch.is_tensor(v)}
    out = _Rollout.apply(step, int(steps), int(checkpoints), names, consts, len(states),
                         *states, *(params[k] for k in names))
    return out[0] if single else out


# ---- solve -----------------------------------------------------------------------------------

class ConvergenceError(RuntimeError):
    """The Krylov solve did not reach its tolerance; `iterations` and `residual` say how far
    it got."""

    def __init__(self, message, iterations, residual):
        super().__init__(message)
        self.iterations = iterations
        self.residual = residual


def _dot(a, b):
    return torch.dot(a.reshape(-1), b.reshape(-1))


def _cg(apply, b, x0, tol, max_iterations, diagonal, what):
    """Preconditioned CG for SPD A (Jacobi when diagonal is given); returns x."""
    x = torch.zeros_like(b) if x0 is None else x0.clone()
    r = b.clone() if x0 is None else b - apply(x)           # r = b - A x
    rnorm = float(r.norm())
    if rnorm <= tol:
        return x
    z = r / diagonal if diagonal is not None else r          # z = M^-1 r
    p = z.clone()
    rz = _dot(r, z)
    for it in range(1, max_iterations + 1):
        q = apply(p)                                         # q = A p
        pq = _dot(p, q)
        if not pq > 0:
            raise ConvergenceError(f"{what}: p'Ap = {float(pq):.3g} <= 0 at iteration {it}: the "
                                   "operator is not symmetric positive definite (symmetric="
                                   "False solves it with BiCGSTAB)", it, rnorm)
        alpha = rz / pq
        x += alpha * p                                       # x += alpha p
        r -= alpha * q                                       # r -= alpha A p
        rnorm = float(r.norm())
        if rnorm <= tol:
            return x
        if not math.isfinite(rnorm):
            break
        z = r / diagonal if diagonal is not None else r
        rz_new = _dot(r, z)
        p = z + (rz_new / rz) * p                            # p = z + beta p
        rz = rz_new
    raise ConvergenceError(f"{what}: CG did not converge in {max_iterations} iterations "
                           f"(residual {rnorm:.3e}, tolerance {tol:.3e})", max_iterations, rnorm)


def _bicgstab(apply, b, x0, tol, max_iterations, diagonal, what):
    """BiCGSTAB (right Jacobi preconditioning when diagonal is given) for a general A."""
    x = torch.zeros_like(b) if x0 is None else x0.clone()
    r = b.clone() if x0 is None else b - apply(x)
    rnorm = float(r.norm())
    if rnorm <= tol:
        return x
    r_hat = r.clone()                                        # the shadow residual
    rho = alpha = omega = 1.0
    v = torch.zeros_like(b)
    p = torch.zeros_like(b)
    precondition = (lambda u: u / diagonal) if diagonal is not None else (lambda u: u)
    for it in range(1, max_iterations + 1):
        rho_new = _dot(r_hat, r)
        if rho_new == 0 or omega == 0:
            raise ConvergenceError(f"{what}: BiCGSTAB broke down at iteration {it} (residual "
                                   f"{rnorm:.3e})", it, rnorm)
        p = r + (rho_new / rho) * (alpha / omega) * (p - omega * v)
        p_hat = precondition(p)
        v = apply(p_hat)
        alpha = rho_new / _dot(r_hat, v)
        s = r - alpha * v                                    # the half-step residual
        if float(s.norm()) <= tol:
            return x + alpha * p_hat
        s_hat = precondition(s)
        t = apply(s_hat)
        omega = _dot(t, s) / _dot(t, t)
        x = x + alpha * p_hat + omega * s_hat
        r = s - omega * t
        rho = rho_new
        rnorm = float(r.norm())
        if rnorm <= tol:
            return x
        if not math.isfinite(rnorm):
            break
    raise ConvergenceError(f"{what}: BiCGSTAB did not converge in {max_iterations} iterations "
                           f"(residual {rnorm:.3e}, tolerance {tol:.3e})", max_iterations, rnorm)


class _Solve(torch.autograd.Function):
    @staticmethod
    def forward(ctx, operator, options, names, consts, b, *pvals):
        params = dict(zip(names, pvals), **consts)

        def apply(v):
            y = operator(v, **params)
            if not torch.is_tensor(y) or y.shape != b.shape:
                raise ValueError("dpgen_torch.solve: the operator must return one tensor of b's "
                                 f"shape {tuple(b.shape)}, got "
                                 + (f"shape {tuple(y.shape)}" if torch.is_tensor(y) else
                                    type(y).__name__))
            return y

        krylov = _cg if options["symmetric"] else _bicgstab
        x = krylov(apply, b, options["x0"], options["tol"](b), options["max_iterations"],
                   options["diagonal"], "dpgen_torch.solve forward")
        ctx.operator, ctx.options, ctx.names, ctx.consts = operator, options, names, consts
        ctx.save_for_backward(x, *pvals)
        return x

    @staticmethod
    def backward(ctx, x_bar):
        x, *pvals = ctx.saved_tensors
        x = x.detach()  # the saved output: its graph leads back to this node
        names, consts, options = ctx.names, ctx.consts, ctx.options
        params = dict(zip(names, (v.detach() for v in pvals)), **consts)
        if options["symmetric"]:
            def apply_t(v):                                  # A^T = A
                return ctx.operator(v, **params)
        else:
            def apply_t(v):                                  # A^T v: the operator's backward
                with torch.enable_grad():
                    xr = x.detach().requires_grad_()
                    y = ctx.operator(xr, **params)
                    return torch.autograd.grad(y, xr, v)[0]
        krylov = _cg if options["symmetric"] else _bicgstab
        lam = krylov(apply_t, x_bar.contiguous(), None, options["tol"](x_bar),
                     options["max_iterations"], options["diagonal"],
                     "dpgen_torch.solve backward (A^T lambda = x_bar)")
        need = [ctx.needs_input_grad[5 + i] for i in range(len(pvals))]
        p_bars = [None] * len(pvals)
        with torch.enable_grad():
            # params_bar = -(d(A(params) x)/d params)^T lambda: the operator's backward at x
            p = [v.detach().requires_grad_() if nd else v.detach() for v, nd in zip(pvals, need)]
            y = ctx.operator(x, **dict(zip(names, p)), **consts)
            _only_declared_leaves([y], p, "solve")
            wrt = [v for v, nd in zip(p, need) if nd]
            g = torch.autograd.grad(y, wrt, grad_outputs=-lam, allow_unused=True) if wrt else ()
        if any(need):
            it = iter(g)
            for i, nd in enumerate(need):
                if nd:
                    gi = next(it)
                    p_bars[i] = gi if gi is not None else torch.zeros_like(pvals[i])
        b_bar = lam if ctx.needs_input_grad[4] else None
        return (None, None, None, None, b_bar) + tuple(p_bars)


def solve(operator, b, *, rtol=1e-10, atol=0.0, max_iterations=None, symmetric=True,
          diagonal=None, x0=None, **params):
    """x with A(params) x = b, where operator(x, **params) computes A(params) x (a dpgen op of
    a kernel linear in its first argument, or any differentiable callable).

    Forward: CG (symmetric=True: A must be symmetric positive definite) or BiCGSTAB
    (symmetric=False), Jacobi-preconditioned when `diagonal` (A's diagonal, b's shape) is
    given, from x0 or 0, until ||b - A x|| <= max(rtol ||b||, atol); max_iterations defaults
    to 10 * b.numel(). Backward: one more solve A^T lambda = x_bar with the same options
    (A^T v from the operator's backward when not symmetric), b_bar = lambda, and for each tensor
    parameter -(d(A(params) x)/d params)^T lambda by the operator's backward seeded with
    -lambda. Raises ConvergenceError (iterations, residual) when either solve falls short.
    """
    if not torch.is_tensor(b) or not b.is_floating_point():
        raise TypeError("dpgen_torch.solve: b must be a floating-point tensor")
    if max_iterations is None:
        max_iterations = 10 * max(b.numel(), 1)
    if int(max_iterations) != max_iterations or max_iterations < 1:
        raise ValueError(f"dpgen_torch.solve: max_iterations must be >= 1, got {max_iterations}")
    if not (rtol >= 0 and atol >= 0) or rtol == atol == 0:
        raise ValueError(f"dpgen_torch.solve: need rtol >= 0, atol >= 0, not both 0 (got "
                         f"{rtol}, {atol})")
    if diagonal is not None:
        diagonal = diagonal.detach()
        if diagonal.shape != b.shape or not bool((diagonal != 0).all()):
            raise ValueError("dpgen_torch.solve: diagonal (the Jacobi preconditioner) must have "
                             f"b's shape {tuple(b.shape)} and no zero")
    if x0 is not None:
        x0 = x0.detach()
    options = {"symmetric": bool(symmetric), "diagonal": diagonal, "x0": x0,
               "max_iterations": int(max_iterations),
               "tol": lambda rhs: max(rtol * float(rhs.norm()), atol)}
    names = tuple(k for k, v in params.items() if torch.is_tensor(v))
    consts = {k: v for k, v in params.items() if not torch.is_tensor(v)}
    return _Solve.apply(operator, options, names, consts, b, *(params[k] for k in names))
