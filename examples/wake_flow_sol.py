#!/usr/bin/env python3
"""Solver in the loop on the 2D wake flow (the Physics-based Deep Learning book's
diffphys-code-sol.ipynb, Um et al. 2020 appendix B.1), with dpgen kernels as the solver.

The flow: a channel 100 wide (x, closed walls) and 200 long (y, open: inflow at the bottom,
outflow at the top) with a circular obstacle of radius 10 at (50, 50). One step, as the
notebook's KarmanFlow.step:
  1. explicit viscosity, diffusivity res^2 / Re (res: cells across, as the notebook passes it);
  2. the inflow band: v = 1, u = 0 on the faces with y < 5;
  3. semi-Lagrangian advection of the marker (plus its inflow, the box y in [5, 10], x in
     [25, 75]) and of the velocity by itself;
  4. pressure projection with the obstacle (faces touching it closed, p = 0 beyond the outflow).
Steps 1, 3 and 4 are dpgen kernels (examples/kernels/wake2d.cpp) turned into autograd ops by
dpgen_torch.load; their backward is the generated adjoint. The pressure solve is a direct
block-Cholesky solve of the same operator (checked against the kernel) with the implicit
gradient (A is symmetric: the backward is one more solve).

The reference runs the same step on a grid --factor times finer (4: as the notebook) and is
averaged onto the source grid (face fluxes: mean of the fine faces on each coarse face). Data:
--warmup steps from the notebook's warm start (v = 1, a sideways poke), then --frames frames,
for the 6 training Reynolds numbers and the 4 test ones of the notebook (the lowest, 120000,
outside the training range). The network sees u, v and Re divided by the training data's
std; it corrects the velocity after every source step. Trainings: DP (through --msteps
unrolled source steps and corrections, the notebook's loss), and supervised (the same network
on precomputed one-step pairs: the source step of a reference frame against the next frame; no
solver in the loss). Evaluation: 100 steps from each test simulation's first frame, the error
per step mean|u - u_ref| + mean|v - v_ref|, averaged over the 100 steps (accumulated MAE).
Prints, per seed, `sol2d: net=... msteps=... seed=... test_mae source=... dp=... supervised=...`.

  /usr/bin/python3 examples/wake_flow_sol.py   (or env/bin/python with pip's install)

runs the whole experiment (seeds 0, 1 and 2, 6000 iterations each; about 30 minutes on one
core, the reference data included, cached in build/ for later runs).
"""
import argparse
import math
import os
import struct
import sys
import time
import zlib

import numpy as np
import torch

HERE = os.path.dirname(os.path.abspath(__file__))
try:
    import dpgen_torch
except ImportError:  # not installed: the source tree's package (its build*/ has the generator)
    sys.path.insert(0, os.path.join(os.path.dirname(HERE), "python"))
    import dpgen_torch

TRAIN_RE = (160000.0, 320000.0, 640000.0, 1280000.0, 2560000.0, 5120000.0)
TEST_RE = (120000.0, 480000.0, 1920000.0, 7680000.0)
LENGTH = 100.0  # width of the channel; its length is 2 * LENGTH


def parse(argv=None):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                formatter_class=argparse.ArgumentDefaultsHelpFormatter)
    p.add_argument("--nx", type=int, default=32, help="source cells across (ny = 2 nx)")
    p.add_argument("--factor", type=int, default=4, help="reference grid: factor x finer")
    p.add_argument("--warmup", type=int, default=1000,
                   help="reference steps before the first frame (the notebook skips 999)")
    p.add_argument("--frames", type=int, default=500, help="frames per training simulation")
    p.add_argument("--eval-steps", type=int, default=100, help="steps of the evaluation")
    p.add_argument("--data", default=None,
                   help="cache file of the reference data (.npz; made if missing); default "
                        "build/wake_data_<settings>.npz in the source tree")
    p.add_argument("--net", choices=["small", "resnet"], default="small",
                   help="network_small (4 convs 5x5, 32 features) or the paper's ResNet")
    p.add_argument("--msteps", type=int, nargs="+", default=[4],
                   help="unrolled steps of the DP training (several: one training each)")
    p.add_argument("--iters", type=int, default=6000, help="Adam iterations of each training")
    p.add_argument("--batch", type=int, default=3, help="simulations per batch")
    p.add_argument("--lr", type=float, default=1e-3, help="Adam learning rate")
    p.add_argument("--lr-decay", type=float, default=0.1,
                   help="the rate decays exponentially to this fraction of --lr at the end")
    p.add_argument("--seeds", type=int, nargs="+", default=[0, 1, 2],
                   help="seeds of the trainings")
    p.add_argument("--no-supervised", action="store_true", help="skip the supervised baseline")
    p.add_argument("--threads", type=int, default=1, help="torch.set_num_threads")
    p.add_argument("--out", default=None, help="folder for pictures and per-step errors")
    p.add_argument("--check-gradient", action="store_true",
                   help="only check the gradients of the unrolled solver (gradcheck on a "
                        "small grid: central differences against the generated adjoints)")
    p.add_argument("--require-dp-ratio", type=float, default=0.0,
                   help="fail unless, for every seed, the DP hybrid's MAE is at most this "
                        "times the source's, on the lowest-Re test simulation and on average")
    p.add_argument("--require-dp-below-supervised", action="store_true",
                   help="fail unless the DP hybrid's average MAE is below the supervised "
                        "one's for every seed")
    a = p.parse_args(argv)
    if a.nx < 8 or a.nx % 4:
        p.error(f"--nx must be a multiple of 4 and at least 8, got {a.nx}")
    if a.factor < 1:
        p.error(f"--factor must be at least 1, got {a.factor}")
    for name in ("warmup", "eval_steps", "iters", "batch"):
        if getattr(a, name) < (0 if name == "warmup" else 1):
            p.error(f"--{name.replace('_', '-')} out of range: {getattr(a, name)}")
    if any(m < 1 for m in a.msteps):
        p.error(f"--msteps must be at least 1, got {a.msteps}")
    if a.frames < max(a.msteps) + 2:
        p.error(f"--frames must be at least --msteps + 2 = {max(a.msteps) + 2}, got {a.frames}")
    if not (0 < a.lr_decay <= 1):
        p.error(f"--lr-decay must be in (0, 1], got {a.lr_decay}")
    return a


# ---- the solver --------------------------------------------------------------------------

_ops = None


def kernels():
    """The wake kernels as ops (dpgen_torch.load: generated, compiled and cached once)."""
    global _ops
    if _ops is None:
        _ops = dpgen_torch.load(os.path.join(HERE, "kernels", "wake2d.cpp"))
    return _ops


class BlockCholesky:
    """A = L L^T for the pressure operator, A block tridiagonal in the rows (blocks of nx
    cells): L has diagonal blocks L_j and sub-diagonal blocks M_j. Solves take 2 ny small
    matrix products for a whole batch."""

    def __init__(self, diag_blocks, couplings):
        ny, nx, _ = diag_blocks.shape
        self.linv_t = torch.empty_like(diag_blocks)  # (L_j^{-1})^T
        self.m = torch.zeros_like(diag_blocks)       # M_j = C_j L_{j-1}^{-T}
        prev = None
        for j in range(ny):
            s = diag_blocks[j].clone()
            if j > 0:
                self.m[j] = couplings[j] @ prev.T   # C_j L_{j-1}^{-T}, prev = L_{j-1}^{-1}
                s -= self.m[j] @ self.m[j].T
            lj = torch.linalg.cholesky(s)
            prev = torch.linalg.solve_triangular(lj, torch.eye(nx, dtype=s.dtype), upper=False)
            self.linv_t[j] = prev.T
        self.ny, self.nx = ny, nx

    def solve(self, b):
        """x with A x = b for b of shape (batch, ny, nx)."""
        ys = []
        y = None
        for j in range(self.ny):
            r = b[:, j] if j == 0 else b[:, j] - y @ self.m[j].T
            y = r @ self.linv_t[j]
            ys.append(y)
        xs = [None] * self.ny
        x = None
        for j in range(self.ny - 1, -1, -1):
            r = ys[j] if j == self.ny - 1 else ys[j] - x @ self.m[j + 1]
            x = r @ self.linv_t[j].T
            xs[j] = x
        return torch.stack(xs, dim=1)


class _PressureSolve(torch.autograd.Function):
    @staticmethod
    def forward(ctx, b, chol):
        ctx.chol = chol
        return chol.solve(b)

    @staticmethod
    def backward(ctx, g):
        return ctx.chol.solve(g), None  # A symmetric: b_bar = A^{-1} x_bar


class Wake:
    """The wake flow on an nx-by-2nx grid: masks, the pressure factorization, one step."""

    def __init__(self, nx):
        self.nx, self.ny = nx, 2 * nx
        self.h = LENGTH / nx
        nx, ny, h = self.nx, self.ny, self.h
        f64 = dict(dtype=torch.float64)
        xc = (torch.arange(nx, **f64) + 0.5) * h
        yc = (torch.arange(ny, **f64) + 0.5) * h
        solid = ((xc[None, :] - 50.0) ** 2 + (yc[:, None] - 50.0) ** 2) <= 10.0 ** 2
        self.fluid = (~solid).to(torch.float64)                         # (ny, nx)
        fl = self.fluid
        # x faces: open between two fluid cells; walls closed
        wx = torch.zeros(ny, nx + 1, **f64)
        wx[:, 1:nx] = fl[:, :-1] * fl[:, 1:]
        # y faces: interior between two fluid cells; the inflow row 0 has its velocity
        # prescribed (weight 0); the outflow row ny is open (p = 0 beyond)
        wy = torch.zeros(ny + 1, nx, **f64)
        wy[1:ny] = fl[:-1] * fl[1:]
        wy[ny] = fl[ny - 1]
        self.wx, self.wy = wx, wy
        # faces kept before the projection: all but walls and faces touching the obstacle
        self.keep_u = wx.clone()
        self.keep_v = wy.clone()
        self.keep_v[0] = fl[0]
        # the inflow band y < 5: v = 1, u = 0 (faces by their positions, as a hard mask)
        yu = (torch.arange(ny, **f64) + 0.5) * h
        yv = torch.arange(ny + 1, **f64) * h
        self.band_u = (yu < 5.0).to(torch.float64)[:, None].expand(ny, nx + 1).clone()
        self.band_v = (yv < 5.0).to(torch.float64)[:, None].expand(ny + 1, nx).clone()
        # the marker inflow: the box y in [5, 10], x in [25, 75], as area fractions of cells
        def overlap(lo, hi, n):
            a = torch.arange(n, **f64) * h
            return ((torch.minimum(a + h, torch.tensor(hi)) - torch.maximum(a, torch.tensor(lo)))
                    .clamp(min=0) / h)
        self.inflow = overlap(5.0, 10.0, ny)[:, None] * overlap(25.0, 75.0, nx)[None, :]
        # the pressure operator's blocks (rows j of nx cells)
        inv_h2 = 1.0 / (h * h)
        diag = torch.zeros(ny, nx, nx, **f64)
        coup = torch.zeros(ny, nx, nx, **f64)
        idx = torch.arange(nx)
        for j in range(ny):
            d = (wx[j, 1:] + wx[j, :-1] + wy[j + 1] + wy[j]) * inv_h2 + (1.0 - fl[j])
            diag[j, idx, idx] = d
            off = -wx[j, 1:nx] * inv_h2
            diag[j, idx[:-1], idx[1:]] = off
            diag[j, idx[1:], idx[:-1]] = off
            if j > 0:
                coup[j, idx, idx] = -wy[j] * inv_h2
        self.chol = BlockCholesky(diag, coup)

    def initial(self):
        """The notebook's warm start: v = 1 everywhere, a sideways poke u = 1 in a small box
        downstream of the obstacle (placed as in the reference's 128 x 256 grid)."""
        nx, ny, h = self.nx, self.ny, self.h
        u = torch.zeros(ny, nx + 1, dtype=torch.float64)
        v = torch.ones(ny + 1, nx, dtype=torch.float64)
        yu = (torch.arange(ny, dtype=torch.float64) + 0.5) * h
        xu = torch.arange(nx + 1, dtype=torch.float64) * h
        hr = LENGTH / 128
        rows = (yu >= (128 + 10) * hr) & (yu < (128 + 20) * hr)
        cols = (xu >= (64 - 2) * hr) & (xu < (64 + 2) * hr)
        u[rows[:, None] & cols[None, :]] = 1.0
        s = torch.zeros(ny, nx, dtype=torch.float64)
        return s, u, v

    def viscosity(self, re):
        """nu dt / h^2 with the notebook's diffusivity res^2 / Re, res = cells across."""
        return (self.nx * self.nx / re) / (self.h * self.h)

    def step(self, s, u, v, re, marker=True):
        """One step for a batch: s (B, ny, nx), u (B, ny, nx+1), v (B, ny+1, nx), re (B
        floats). Returns (s, u, v); s is passed through untouched when marker=False (it does
        not act on the velocity)."""
        k = kernels()
        nx, ny = self.nx, self.ny
        us, vs, ss, divs = [], [], [], []
        for b in range(u.shape[0]):
            c = self.viscosity(float(re[b]))
            ub = k.wake_diffuse_u(u[b], nx, ny, c)
            vb = k.wake_diffuse_v(v[b], nx, ny, c)
            ub = ub * (1.0 - self.band_u)
            vb = vb * (1.0 - self.band_v) + self.band_v
            if marker:
                ss.append(k.wake_advect_marker(s[b] + self.inflow, ub, vb, nx, ny, 1.0 / self.h))
            ua = k.wake_advect_u(ub, vb, nx, ny, 1.0 / self.h) * self.keep_u
            va = k.wake_advect_v(ub, vb, nx, ny, 1.0 / self.h, v_out_shape=[ny + 1, nx]) * self.keep_v
            us.append(ua)
            vs.append(va)
            divs.append(k.wake_divergence(ua, va, nx, ny, self.h, div_shape=[ny, nx]))
        p = _PressureSolve.apply(-torch.stack(divs), self.chol)
        u2 = torch.stack([k.wake_subtract_gradient_u(us[b], p[b], self.wx, nx, ny, self.h)
                          for b in range(len(us))])
        v2 = torch.stack([k.wake_subtract_gradient_v(vs[b], p[b], self.wy, nx, ny, self.h)
                          for b in range(len(vs))])
        return (torch.stack(ss) if marker else s), u2, v2

    def divergence(self, u, v):
        k = kernels()
        return torch.stack([k.wake_divergence(u[b], v[b], self.nx, self.ny, self.h,
                                              div_shape=[self.ny, self.nx])
                            for b in range(u.shape[0])])


def downsample(s, u, v, f):
    """Fine (B, f ny, f nx) fields onto the coarse grid: cell means for s, the mean of the f
    fine faces on each coarse face for u and v (the coarse faces' fluxes)."""
    if f == 1:
        return s, u, v
    B, ny, nx = s.shape
    sc = s.reshape(B, ny // f, f, nx // f, f).mean(dim=(2, 4))
    uc = u[:, :, ::f].reshape(B, ny // f, f, nx // f + 1).mean(dim=2)
    vc = v[:, ::f, :].reshape(B, ny // f + 1, nx // f, f).mean(dim=3)
    return sc, uc, vc


def make_data(a, res, label):
    """Reference frames for the Reynolds numbers `res`: (s, u, v) numpy arrays of shape
    (sims, frames, ...) on the source grid."""
    fine = Wake(a.nx * a.factor)
    n = len(res)
    s, u, v = (t.expand(n, *t.shape).clone() for t in fine.initial())
    re = list(res)
    frames = a.frames if label == "train" else a.eval_steps + 1
    out = ([], [], [])
    t0 = time.time()
    with torch.no_grad():
        for t in range(a.warmup + frames):
            if t >= a.warmup:
                for lst, x in zip(out, downsample(s, u, v, a.factor)):
                    lst.append(x.numpy().copy())
            s, u, v = fine.step(s, u, v, re)
            if not torch.isfinite(u).all() or not torch.isfinite(v).all():
                raise RuntimeError(f"wake_flow_sol: the reference ({label}) blew up at step {t}")
            if t % 200 == 0:
                print(f"  reference {label} {fine.nx}x{fine.ny}: step {t}/{a.warmup + frames} "
                      f"({time.time() - t0:.0f} s)", flush=True)
    return [np.stack(lst, axis=1) for lst in out]


def _solver_version():
    """A hash of what the reference data depend on: the kernels, and this file's solver and
    data generation (the code above this function)."""
    import hashlib
    h = hashlib.sha256()
    with open(os.path.join(HERE, "kernels", "wake2d.cpp"), "rb") as f:
        h.update(f.read())
    with open(os.path.abspath(__file__), "rb") as f:
        text = f.read()
    h.update(text[text.index(b"class BlockCholesky"):text.index(b"def _solver_version")])
    return h.hexdigest()[:12]


def load_data(a):
    version = _solver_version()
    path = a.data or os.path.join(
        os.path.dirname(HERE), "build",
        f"wake_data_nx{a.nx}_f{a.factor}_w{a.warmup}_n{a.frames}_e{a.eval_steps}.npz")
    settings = np.array([a.nx, a.factor, a.warmup, a.frames, a.eval_steps])
    if os.path.isfile(path):
        d = np.load(path)
        if (str(d.get("version", "")) == version and "settings" in d.files and
                np.array_equal(d["settings"], settings)):
            print(f"reference data: {path}", flush=True)
            return {k: d[k] for k in d.files}
        print(f"reference data: {path} is from other settings or another solver version: "
              "recomputing", flush=True)
    t0 = time.time()
    print(f"reference data: computing ({a.nx * a.factor}x{2 * a.nx * a.factor} cells, "
          f"{a.warmup} warm-up steps), to {path}", flush=True)
    tr = make_data(a, TRAIN_RE, "train")
    te = make_data(a, TEST_RE, "test")
    d = dict(train_s=tr[0], train_u=tr[1], train_v=tr[2], test_s=te[0], test_u=te[1],
             test_v=te[2], version=np.array(version), settings=settings)
    os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    tmp = path + f".tmp{os.getpid()}.npz"
    np.savez(tmp, **d)
    os.replace(tmp, path)
    print(f"reference data: {time.time() - t0:.0f} s", flush=True)
    return d


# ---- the networks ------------------------------------------------------------------------

def conv(cin, cout):
    return torch.nn.Conv2d(cin, cout, 5, padding=2)


class Small(torch.nn.Module):
    """network_small: 3 conv layers of 32 features (5x5, LeakyReLU as Keras's, slope 0.3)
    and a 5x5 conv to (u, v)."""

    def __init__(self):
        super().__init__()
        self.body = torch.nn.Sequential(conv(3, 32), torch.nn.LeakyReLU(0.3), conv(32, 32),
                                        torch.nn.LeakyReLU(0.3), conv(32, 32),
                                        torch.nn.LeakyReLU(0.3), conv(32, 2))

    def forward(self, x):
        return self.body(x)


class ResNet(torch.nn.Module):
    """The paper's network (network_medium): a conv, 5 residual blocks of two 5x5 convs with
    32 features, a conv to (u, v)."""

    def __init__(self):
        super().__init__()
        self.inp = conv(3, 32)
        self.blocks = torch.nn.ModuleList(
            torch.nn.ModuleList([conv(32, 32), conv(32, 32)]) for _ in range(5))
        self.out = conv(32, 2)
        self.act = torch.nn.LeakyReLU(0.3)

    def forward(self, x):
        x = self.act(self.inp(x))
        for c1, c2 in self.blocks:
            x = self.act(x + c2(self.act(c1(x))))
        return self.out(x)


class Corrector:
    """Network input/output as the notebook's to_keras / to_phiflow: channels u at the east
    faces of the cells, v at their south faces, Re; the output corrects the interior x faces
    and the y faces of rows 0 .. ny-1; each divided (multiplied) by the training std."""

    def __init__(self, net, stats):
        self.net, self.stats = net, stats

    def __call__(self, u, v, re):
        su, sv, sre = self.stats
        B, ny, nx1 = u.shape
        nx = nx1 - 1
        x = torch.stack([u[:, :, 1:] / su, v[:, :ny, :] / sv,
                         (torch.as_tensor(re, dtype=torch.float64) / sre)[:, None, None]
                         .expand(B, ny, nx)], dim=1)
        out = self.net(x.float()).double()
        du = torch.zeros_like(u)
        du[:, :, 1:nx] = out[:, 0, :, :nx - 1] * su
        dv = torch.zeros_like(v)
        dv[:, :ny, :] = out[:, 1] * sv
        return u + du, v + dv


def velocity_loss(u, v, ur, vr, stats):
    """The notebook's loss term: l2_loss ((sum of squares) / 2) of the differences of the
    interior x faces and of the y faces, each divided by the training std."""
    su, sv, _ = stats
    return (((u[:, :, 1:-1] - ur[:, :, 1:-1]) / su).square().sum() +
            ((v - vr) / sv).square().sum()) / 2


# ---- training and evaluation --------------------------------------------------------------

def make_net(kind, seed):
    torch.manual_seed(seed)
    return Small() if kind == "small" else ResNet()


def train(a, wake, data, stats, seed, msteps, supervised_pairs=None):
    """Adam on DP batches (msteps unrolled steps) or, with supervised_pairs, on precomputed
    one-step pairs. Returns the network and (first loss, last loss)."""
    net = make_net(a.net, seed)
    corr = Corrector(net, stats)
    opt = torch.optim.Adam(net.parameters(), lr=a.lr)
    gamma = a.lr_decay ** (1.0 / max(1, a.iters))
    sched = torch.optim.lr_scheduler.ExponentialLR(opt, gamma)
    gen = np.random.default_rng(seed + 1000 * msteps + (7 if supervised_pairs else 0))
    u_all = torch.from_numpy(data["train_u"])
    v_all = torch.from_numpy(data["train_v"])
    nsim, nframes = u_all.shape[:2]
    losses = []
    t0 = time.time()
    for it in range(a.iters):
        sims = gen.integers(0, nsim, a.batch)
        if supervised_pairs is not None:
            frames = gen.integers(0, nframes - 1, a.batch)
            su_, sv_ = supervised_pairs
            u0, v0 = su_[sims, frames], sv_[sims, frames]
            ur, vr = u_all[sims, frames + 1], v_all[sims, frames + 1]
            re = [TRAIN_RE[i] for i in sims]
            u1, v1 = corr(u0, v0, re)
            loss = velocity_loss(u1, v1, ur, vr, stats)
        else:
            frames = gen.integers(0, nframes - msteps, a.batch)
            re = [TRAIN_RE[i] for i in sims]
            u, v = u_all[sims, frames], v_all[sims, frames]
            s = None
            loss = 0.0
            for m in range(1, msteps + 1):
                s, u, v = wake.step(s, u, v, re, marker=False)
                u, v = corr(u, v, re)
                loss = loss + velocity_loss(u, v, u_all[sims, frames + m],
                                            v_all[sims, frames + m], stats)
            loss = loss / msteps
        opt.zero_grad()
        loss.backward()
        opt.step()
        sched.step()
        lv = float(loss)
        if not math.isfinite(lv):
            raise RuntimeError(f"wake_flow_sol: the training loss is {lv} at iteration {it}")
        losses.append(lv)
        if it % max(1, a.iters // 10) == 0 or it == a.iters - 1:
            kind = "supervised" if supervised_pairs is not None else f"dp(msteps={msteps})"
            print(f"  seed {seed} {kind}: iter {it:5d} loss {lv:10.4f} "
                  f"(mean of last 50 {np.mean(losses[-50:]):10.4f}) {time.time() - t0:6.1f} s",
                  flush=True)
    k = max(1, min(50, a.iters // 10))
    return net, (float(np.mean(losses[:k])), float(np.mean(losses[-k:])))


def supervised_pairs(wake, data):
    """The source step of every training frame (but the last): the supervised inputs."""
    u_all = torch.from_numpy(data["train_u"])
    v_all = torch.from_numpy(data["train_v"])
    nsim, nframes = u_all.shape[:2]
    us, vs = [], []
    with torch.no_grad():
        for t in range(nframes - 1):
            _, u, v = wake.step(None, u_all[:, t], v_all[:, t], TRAIN_RE, marker=False)
            us.append(u)
            vs.append(v)
    return torch.stack(us, dim=1), torch.stack(vs, dim=1)


def rollout(a, wake, data, corr):
    """The test simulations from their first frame, eval_steps steps (corrected by corr if
    given). Returns errors (sims, steps) and the final states."""
    u_ref = torch.from_numpy(data["test_u"])
    v_ref = torch.from_numpy(data["test_v"])
    s = torch.from_numpy(data["test_s"][:, 0]).clone()
    u, v = u_ref[:, 0].clone(), v_ref[:, 0].clone()
    errs, states = [], []
    with torch.no_grad():
        for t in range(1, a.eval_steps + 1):
            s, u, v = wake.step(s, u, v, TEST_RE)
            if corr is not None:
                u, v = corr(u, v, TEST_RE)
            e = ((u - u_ref[:, t])[:, :, 1:-1].abs().mean(dim=(1, 2)) +
                 (v - v_ref[:, t]).abs().mean(dim=(1, 2)))
            errs.append(e)
            states.append((u.clone(), v.clone()))
    return torch.stack(errs, dim=1).numpy(), states


def check_gradient():
    """gradcheck (central differences) of 2 unrolled steps of the wake solver on a 12 x 24
    grid w.r.t. the initial velocity, through the generated adjoints and the pressure solve;
    and of the pressure solve alone; and the solve's residual under the kernel operator."""
    torch.manual_seed(0)
    wake = Wake(12)
    _, u0, v0 = wake.initial()
    with torch.no_grad():  # a developed state: a few steps from the warm start
        s, u, v = None, u0[None], v0[None]
        for _ in range(5):
            s, u, v = wake.step(s, u, v, [1e4], marker=False)
    u = (u + 0.05 * torch.randn_like(u)).requires_grad_()
    v = (v + 0.05 * torch.randn_like(v)).requires_grad_()

    def two_steps(u, v):
        s_, u_, v_ = wake.step(None, u, v, [1e4], marker=False)
        s_, u_, v_ = wake.step(None, u_, v_, [1e4], marker=False)
        return u_, v_

    ok = torch.autograd.gradcheck(two_steps, (u, v), eps=1e-6, atol=1e-6, rtol=1e-5)
    print(f"gradcheck of 2 unrolled steps (u, v -> u2, v2; {u.numel() + v.numel()} inputs): {ok}")
    b = torch.randn(1, wake.ny, wake.nx, dtype=torch.float64, requires_grad=True)
    ok2 = torch.autograd.gradcheck(lambda b: _PressureSolve.apply(b, wake.chol), (b,))
    print(f"gradcheck of the pressure solve: {ok2}")
    k = kernels()
    p = wake.chol.solve(b.detach())[0]
    r = k.wake_pressure_operator(p.flatten(), wake.wx, wake.wy, wake.fluid, wake.nx, wake.ny,
                                 wake.h, out_shape=[wake.ny * wake.nx]) - b.detach().flatten()
    rel = float(r.norm() / b.norm())
    print(f"pressure solve residual under the kernel operator: {rel:.2e}")
    with torch.no_grad():
        _, u1, v1 = wake.step(None, u.detach(), v.detach(), [1e4], marker=False)
        div = wake.divergence(u1, v1)
    dmax = float((div * wake.fluid).abs().max())
    print(f"max |div| after a step (fluid cells): {dmax:.2e}")
    if not (ok and ok2 and rel < 1e-10 and dmax < 1e-10):
        raise SystemExit("wake_flow_sol: the gradient check failed")


# ---- pictures (no plotting library: a PNG writer and an SVG line chart) ------------------

def write_png(path, rgb):
    h, w, _ = rgb.shape
    raw = b"".join(b"\0" + rgb[r].astype(np.uint8).tobytes() for r in range(h))

    def chunk(tag, data):
        return (struct.pack(">I", len(data)) + tag + data +
                struct.pack(">I", zlib.crc32(tag + data) & 0xFFFFFFFF))
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0))
                + chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


def vorticity(u, v, h):
    """Curl at the cell centres (dv/dx - du/dy), from face values."""
    uc = 0.5 * (u[:, :-1] + u[:, 1:])
    vc = 0.5 * (v[:-1] + v[1:])
    return np.gradient(vc, h, axis=1) - np.gradient(uc, h, axis=0)


def vorticity_panels(path, fields, h, scale=6):
    """Fields side by side (flow upwards), each framed in black, blue-white-red on one
    symmetric scale (the 99th percentile of |vorticity|), and a colour bar on the right."""
    ws = [vorticity(u, v, h) for u, v in fields]
    lim = max(np.percentile(np.abs(w), 99) for w in ws) or 1.0
    panels_png(path, [np.clip(w / lim, -1, 1)[::-1] for w in ws], scale)  # y up


def panels_png(path, ts, scale):
    """Panels of values in [-1, 1] (first row at the top) and a colour bar."""
    def colour(t):
        rgb = np.empty(t.shape + (3,))
        pos, neg = np.clip(t, 0, 1), np.clip(-t, 0, 1)
        rgb[..., 0] = 255 * (1 - neg)
        rgb[..., 1] = 255 * (1 - pos - neg)
        rgb[..., 2] = 255 * (1 - pos)
        return rgb

    def framed(rgb):
        rgb = np.kron(rgb, np.ones((scale, scale, 1)))
        out = np.zeros((rgb.shape[0] + 2, rgb.shape[1] + 2, 3))  # a black frame
        out[1:-1, 1:-1] = rgb
        return out

    tiles = [framed(colour(t)) for t in ts]
    height = tiles[0].shape[0]
    bar = framed(colour(np.linspace(1, -1, (height - 2) // scale)[:, None] * np.ones((1, 2))))
    bar = np.concatenate([bar, np.full((height - bar.shape[0], bar.shape[1], 3), 255.0)])
    gap = np.full((height, 8, 3), 255.0)
    parts = []
    for t in tiles + [bar]:
        parts += [t, gap]
    write_png(path, np.concatenate(parts[:-1], axis=1))


def _round_step(top, ticks=5):
    """A step of 1, 2 or 5 x 10^k giving about `ticks` intervals up to `top`."""
    raw = top / ticks
    k = 10 ** math.floor(math.log10(raw))
    return next(m * k for m in (1, 2, 5, 10) if m * k >= raw)


def error_svg(path, curves, title):
    """Error per step, one polyline per (label, colour, values); round ticks on both axes."""
    W, H, m = 640, 360, 60
    n = len(curves[0][2])
    ystep = _round_step(max(max(c[2]) for c in curves))
    top = ystep * math.ceil(max(max(c[2]) for c in curves) / ystep)
    xstep = _round_step(n)

    def px(i):
        return m + (W - 2 * m) * i / n

    def py(y):
        return H - m - (H - 2 * m) * y / top

    s = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{W}" height="{H}" '
         f'font-family="sans-serif" font-size="12"><rect width="{W}" height="{H}" fill="white"/>',
         f'<text x="{W / 2}" y="20" text-anchor="middle">{title}</text>',
         f'<line x1="{m}" y1="{H - m}" x2="{W - m}" y2="{H - m}" stroke="black"/>',
         f'<line x1="{m}" y1="{m}" x2="{m}" y2="{H - m}" stroke="black"/>',
         f'<text x="{W / 2}" y="{H - 15}">step</text>']
    for i in range(0, n + 1, xstep):
        s.append(f'<line x1="{px(i):.1f}" y1="{H - m}" x2="{px(i):.1f}" y2="{H - m + 4}" '
                 f'stroke="black"/><text x="{px(i):.1f}" y="{H - m + 16}" '
                 f'text-anchor="middle">{i}</text>')
    for k in range(int(round(top / ystep)) + 1):
        y = k * ystep
        s.append(f'<line x1="{m - 4}" y1="{py(y):.1f}" x2="{m}" y2="{py(y):.1f}" '
                 f'stroke="black"/><text x="{m - 6}" y="{py(y) + 4:.1f}" '
                 f'text-anchor="end">{y:.10g}</text>')
    for k, (label, colour, ys) in enumerate(curves):
        s.append(f'<polyline fill="none" stroke="{colour}" stroke-width="2" points="'
                 + " ".join(f"{px(i + 1):.1f},{py(y):.1f}" for i, y in enumerate(ys)) + '"/>')
        s.append(f'<text x="{W - m - 110}" y="{m + 15 * k}" fill="{colour}">{label}</text>')
    s.append("</svg>")
    with open(path, "w") as f:
        f.write("\n".join(s))


# ---- main ----------------------------------------------------------------------------------

def main(argv=None):
    a = parse(argv)
    torch.set_num_threads(a.threads)
    if a.check_gradient:
        check_gradient()
        return 0
    t_start = time.time()
    data = load_data(a)
    wake = Wake(a.nx)
    tu, tv = data["train_u"], data["train_v"]
    stats = (float(np.std(np.abs(tu[:, :, :, 1:-1]))), float(np.std(np.abs(tv))),
             float(np.std(np.abs(np.array(TRAIN_RE)))))
    print(f"source grid {a.nx}x{2 * a.nx}, reference {a.nx * a.factor}x{2 * a.nx * a.factor}; "
          f"training data std: u {stats[0]:.4f} v {stats[1]:.4f} Re {stats[2]:.1f}", flush=True)
    src_err, src_states = rollout(a, wake, data, None)
    pairs = None if a.no_supervised else supervised_pairs(wake, data)
    failures = []
    results = []
    for seed in a.seeds:
        sup_err = None
        if pairs is not None:
            t0 = time.time()
            net_s, ls = train(a, wake, data, stats, seed, 1, supervised_pairs=pairs)
            sup_err, _ = rollout(a, wake, data, Corrector(net_s, stats))
            print(f"  seed {seed} supervised: loss {ls[0]:.3f} -> {ls[1]:.3f}, "
                  f"{time.time() - t0:.0f} s", flush=True)
        for ms in a.msteps:
            t0 = time.time()
            net, ld = train(a, wake, data, stats, seed, ms)
            dp_err, dp_states = rollout(a, wake, data, Corrector(net, stats))
            print(f"  seed {seed} dp msteps={ms}: loss {ld[0]:.3f} -> {ld[1]:.3f}, "
                  f"{time.time() - t0:.0f} s", flush=True)
            src, dp = src_err.mean(axis=1), dp_err.mean(axis=1)
            per_sim = " ".join(f"Re{int(r)}:{s_:.4f}/{d_:.4f}" +
                               (f"/{q_:.4f}" if sup_err is not None else "")
                               for r, s_, d_, q_ in zip(TEST_RE, src, dp,
                                                         sup_err.mean(axis=1) if sup_err is not
                                                         None else src))
            line = (f"sol2d: net={a.net} msteps={ms} seed={seed} test_mae source={src.mean():.4f}"
                    f" dp={dp.mean():.4f}" +
                    (f" supervised={sup_err.mean():.4f}" if sup_err is not None else "") +
                    f" lowest_re source={src[0]:.4f} dp={dp[0]:.4f}" +
                    (f" supervised={sup_err.mean(axis=1)[0]:.4f}" if sup_err is not None else ""))
            print(line, flush=True)
            print(f"  per test Re (source/dp{'/supervised' if sup_err is not None else ''}): "
                  f"{per_sim}", flush=True)
            results.append((seed, ms, src, dp, None if sup_err is None else sup_err.mean(axis=1)))
            if a.require_dp_ratio > 0:
                for what, s_, d_ in (("lowest Re", src[0], dp[0]),
                                     ("average", src.mean(), dp.mean())):
                    if not d_ <= a.require_dp_ratio * s_:
                        failures.append(f"seed {seed} msteps {ms}: DP MAE {d_:.4f} > "
                                        f"{a.require_dp_ratio} x source {s_:.4f} ({what})")
            if a.require_dp_below_supervised and sup_err is not None and \
                    not dp.mean() < sup_err.mean():
                failures.append(f"seed {seed} msteps {ms}: DP MAE {dp.mean():.4f} not below "
                                f"supervised {sup_err.mean():.4f}")
            if a.out:
                os.makedirs(a.out, exist_ok=True)
                tag = f"{a.net}_m{ms}_s{seed}"
                np.savetxt(os.path.join(a.out, f"errors_{tag}.csv"),
                           np.concatenate([src_err, dp_err] +
                                          ([sup_err] if sup_err is not None else [])).T,
                           delimiter=",", header=",".join(
                               [f"source_Re{int(r)}" for r in TEST_RE] +
                               [f"dp_Re{int(r)}" for r in TEST_RE] +
                               ([f"supervised_Re{int(r)}" for r in TEST_RE]
                                if sup_err is not None else [])))
                error_svg(os.path.join(a.out, f"error_per_step_{tag}.svg"),
                          [("source", "#1f4fbf", list(src_err[0])),
                           ("DP hybrid", "#2a9d2a", list(dp_err[0]))] +
                          ([("supervised", "#d07000", list(sup_err[0]))]
                           if sup_err is not None else []),
                          f"error per step, test Re {int(TEST_RE[0])} (mean|du| + mean|dv|)")
                t = min(a.eval_steps, 50)
                ref = (data["test_u"][0, t], data["test_v"][0, t])
                vorticity_panels(os.path.join(a.out, f"vorticity_{tag}_t{t}.png"),
                                 [(src_states[t - 1][0][0].numpy(), src_states[t - 1][1][0].numpy()),
                                  (dp_states[t - 1][0][0].numpy(), dp_states[t - 1][1][0].numpy()),
                                  ref], wake.h)
    if len(results) > 1:
        for ms in a.msteps:
            rows = [r for r in results if r[1] == ms]
            if len(rows) < 2:
                continue
            src = np.array([r[2].mean() for r in rows])
            dp = np.array([r[3].mean() for r in rows])
            ratio = dp / src
            msg = (f"summary msteps={ms} over {len(rows)} seeds: source {src.mean():.4f}, "
                   f"dp {dp.mean():.4f} +- {dp.std(ddof=1):.4f} ({ratio.mean():.3f} +- "
                   f"{ratio.std(ddof=1):.3f} x source)")
            if rows[0][4] is not None:
                sup = np.array([r[4].mean() for r in rows])
                msg += (f", supervised {sup.mean():.4f} +- {sup.std(ddof=1):.4f} "
                        f"({(sup / src).mean():.3f} x source); dp below supervised in "
                        f"{int((dp < sup).sum())} of {len(rows)}")
            print(msg)
            low = np.array([r[3][0] / r[2][0] for r in rows])
            msg = (f"summary msteps={ms} lowest Re over {len(rows)} seeds: dp {low.mean():.3f} +- "
                   f"{low.std(ddof=1):.3f} x source")
            if rows[0][4] is not None:
                sup = np.array([r[4][0] / r[2][0] for r in rows])
                msg += f", supervised {sup.mean():.3f} +- {sup.std(ddof=1):.3f} x source"
            print(msg)
    print(f"total {time.time() - t_start:.0f} s")
    if failures:
        print("wake_flow_sol: requirement failed:\n  " + "\n  ".join(failures), file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
