"""The Python package as a user gets it (ctest torch.package): `pip install --no-build-isolation`
of this source tree into a fresh virtual environment in a temporary folder, then, in new
processes of that environment run from another folder with no dpgen variables set:
dpgen_torch.load of a kernel file written here (gradcheck of its ops, rollout and solve over
them, Revolve == full tape bit for bit), the cache hit in a new process (the same library,
nothing rebuilt), each error path (dpgen's file:line:col for a file and a string, the
compiler's with its log), an edited included header (rebuilds), and the README's quick start
example (a string kernel) run by two processes at once on one cache.

The CMake build pip drives is $DPGEN_CMAKE_BUILD_DIR when set (ctest sets the build folder
this test belongs to, whose targets are then already up to date), else build-pip/ in the
source tree (a full build: many minutes). One cache folder serves every case: three kernel
builds (10 to 25 s each on 2 cores), the README's twice at once."""
import json
import os
import shutil
import subprocess
import sys
import tempfile
import textwrap
import time
import unittest

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
PYTHON = "/usr/bin/python3" if os.path.exists("/usr/bin/python3") else sys.executable

# The user's kernel file: an explicit heat step (the rollout's step) and the SPD operator
# -d/dx(k dx/dx) with Dirichlet walls (the solve's operator); k: face conductivities.
HEAT = """\
// A user's kernels, written by tests/torch/test_package.py.
#include "dpgen/annotate.hpp"
#include "heat_flux.hpp" // heat_flux(): an included header, so that editing it rebuilds

DPGEN_KERNEL void heat_step(DPGEN_IN const double* T, DPGEN_IN const double* k,
                            DPGEN_OUT double* T_next, int n, double dt) {
  for (int i = 1; i < n - 1; ++i)
    T_next[i] = T[i] + dt * (heat_flux(T[i], T[i + 1], k[i + 1]) -
                             heat_flux(T[i - 1], T[i], k[i]));
}

DPGEN_KERNEL void neg_div_k_grad(DPGEN_IN const double* x, DPGEN_IN const double* k,
                                 DPGEN_OUT double* y, int n) {
  for (int i = 0; i < n; ++i) {
    const double left = i > 0 ? x[i - 1] : 0.0;
    const double right = i < n - 1 ? x[i + 1] : 0.0;
    y[i] = k[i] * (x[i] - left) + k[i + 1] * (x[i] - right);
  }
}
"""

FLUX = "inline double heat_flux(double a, double b, double k) {{ return {} * k * (b - a); }}\n"

# Outside the subset on line 6, column 28: a read of the output being written.
BAD = """\
// rejected by dpgen
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void bad(DPGEN_IN const double* a, DPGEN_OUT double* b, int n) {
  for (int i = 0; i < n; ++i)
    b[i] = a[i] * b[i] + a[i];
}
"""

# Parses with Clang (dpgen) but not with the C++ compiler that builds the op.
NO_COMPILE = """\
#include "dpgen/annotate.hpp"
#ifndef __clang__
#error "dpgen_torch test: this kernel does not compile with this compiler"
#endif
DPGEN_KERNEL void twice(DPGEN_IN const double* a, DPGEN_OUT double* b, int n) {
  for (int i = 0; i < n; ++i)
    b[i] = 2.0 * a[i];
}
"""


class Package(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.mkdtemp(prefix="dpgen-torch-package-")
        cls.env_dir = os.path.join(cls.tmp, "env")
        cls.cache = os.path.join(cls.tmp, "cache")
        cls.work = os.path.join(cls.tmp, "work")
        os.makedirs(cls.work)
        for name, text in (("heat.cpp", HEAT), ("heat_flux.hpp", FLUX.format(1.0)),
                           ("bad.cpp", BAD), ("no_compile.cpp", NO_COMPILE)):
            with open(os.path.join(cls.work, name), "w") as f:
                f.write(text)
        subprocess.run([PYTHON, "-m", "venv", "--system-site-packages", cls.env_dir], check=True)
        started = time.perf_counter()
        p = subprocess.run([os.path.join(cls.env_dir, "bin", "pip"), "install",
                            "--no-build-isolation", "--no-index", "--no-cache-dir", ROOT],
                           cwd=cls.work, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                           text=True)
        cls.install_seconds = time.perf_counter() - started
        if p.returncode != 0:
            raise AssertionError(f"pip install failed:\n{p.stdout[-6000:]}")
        print(f"pip install: {cls.install_seconds:.1f} s", file=sys.stderr)

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.tmp, ignore_errors=True)

    def child(self, code):
        """Runs code in a new process of the environment, from the work folder, with no
        PYTHONPATH and no DPGEN_* variable but the cache folder; returns its last stdout line
        parsed as JSON."""
        env = {k: v for k, v in os.environ.items()
               if not k.startswith("DPGEN") and k != "PYTHONPATH"}
        env["DPGEN_TORCH_CACHE"] = self.cache
        p = subprocess.run([os.path.join(self.env_dir, "bin", "python"), "-c",
                            textwrap.dedent(code)], cwd=self.work, env=env,
                           stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        if p.returncode != 0:
            self.fail(f"child failed ({p.returncode}):\n{p.stdout}\n{p.stderr[-6000:]}")
        return json.loads(p.stdout.strip().splitlines()[-1])

    def test_a_import_from_anywhere_and_the_dpgen_command(self):
        r = self.child("""
            import json, dpgen_torch, torch
            print(json.dumps({"file": dpgen_torch.__file__, "generator": dpgen_torch.generator(),
                              "shipped": hasattr(torch.ops.dpgen, "upwind_step")}))
        """)
        site = os.path.join(self.env_dir, "lib")
        self.assertTrue(r["file"].startswith(site), r)
        self.assertTrue(r["generator"].startswith(site), r)
        self.assertTrue(r["shipped"])
        out = subprocess.run([os.path.join(self.env_dir, "bin", "dpgen"), "--version"],
                             stdout=subprocess.PIPE, text=True, check=True).stdout
        self.assertIn("dpgen 0.1.0", out)

    def test_b_load_gradcheck_rollout_solve(self):
        r = self.child("""
            import json, time, torch, dpgen_torch
            from torch.autograd import gradcheck
            t = time.perf_counter()
            m = dpgen_torch.load("heat.cpp")
            seconds = time.perf_counter() - t
            assert sorted(m.ops) == ["heat_step", "neg_div_k_grad"], m.ops
            torch.manual_seed(0)
            D, n = torch.float64, 9
            T = torch.rand(n, dtype=D, requires_grad=True)
            k = (torch.rand(n + 1, dtype=D) + 0.5).requires_grad_()
            assert gradcheck(lambda T, k: m.heat_step(T, k, n, 0.1), (T, k))
            assert gradcheck(lambda x, k: m.neg_div_k_grad(x, k, n), (T, k))
            # the kernel computes what it says
            ref = torch.zeros(n, dtype=D)
            ref[1:-1] = T[1:-1] + 0.1 * (k[2:-1] * (T[2:] - T[1:-1]) - k[1:-2] * (T[1:-1] - T[:-2]))
            assert torch.allclose(m.heat_step(T, k, n, 0.1), ref, rtol=1e-14, atol=0)
            # rollout over the user's step, Revolve and full tape
            for cp in (0, 3):
                assert gradcheck(lambda T, k: dpgen_torch.rollout(m.heat_step, T, 12,
                                 checkpoints=cp, k=k, n=n, dt=0.1), (T, k))
            grads = []
            for cp in (0, 1, 4, 30):
                a, b = T.detach().clone().requires_grad_(), k.detach().clone().requires_grad_()
                dpgen_torch.rollout(m.heat_step, a, 30, checkpoints=cp, k=b, n=n,
                                    dt=0.1).square().sum().backward()
                grads.append((a.grad, b.grad))
            identical = all(torch.equal(g[0], grads[0][0]) and torch.equal(g[1], grads[0][1])
                            for g in grads)
            # solve over the user's operator: CG forward, implicit-gradient backward
            assert gradcheck(lambda b, k: dpgen_torch.solve(m.neg_div_k_grad, b, k=k, n=n,
                             rtol=1e-13), (T, k))
            print(json.dumps({"seconds": seconds, "library": m.__file__,
                              "revolve_identical": identical}))
        """)
        self.assertTrue(r["revolve_identical"])
        self.assertTrue(r["library"].startswith(self.cache), r)
        print(f"load (build): {r['seconds']:.1f} s", file=sys.stderr)
        type(self).library = r["library"]

    def test_c_cache_hit_in_a_new_process(self):
        if not getattr(type(self), "library", None):
            self.skipTest("needs test_b's build")
        # (test_b's library: a hit only touches its entry's manifest, a build would write a
        # new lib<stem>-<id>.so and remove the old entry)
        st = os.stat(type(self).library)
        built = (st.st_ino, st.st_mtime_ns)
        r = self.child("""
            import json, time, torch, dpgen_torch
            t = time.perf_counter()
            m = dpgen_torch.load("heat.cpp")
            seconds = time.perf_counter() - t
            ones = lambda k: torch.ones(k, dtype=torch.float64)
            x = m.heat_step(ones(5), ones(6), 5, 0.1)
            print(json.dumps({"seconds": seconds, "library": m.__file__, "sum": float(x.sum())}))
        """)
        self.assertEqual(r["library"], type(self).library)  # the same build: nothing rebuilt
        self.assertEqual(r["sum"], 3.0)
        st = os.stat(type(self).library)
        self.assertEqual((st.st_ino, st.st_mtime_ns), built)  # nothing rebuilt
        # (a build compiles torch's headers, 10 s and more: a hit is milliseconds, and this
        # bound leaves room for a loaded machine)
        self.assertLessEqual(r["seconds"], 5.0)
        print(f"load (cache hit, new process): {r['seconds'] * 1e3:.0f} ms", file=sys.stderr)
        # every entry is whole: no temporary build folder left, a manifest in each
        for name in os.listdir(self.cache):
            self.assertFalse(name.startswith("."), name)
            if not name.endswith(".failed"):
                self.assertTrue(os.path.isfile(os.path.join(self.cache, name, "manifest.json")))

    def test_d_errors(self):
        r = self.child("""
            import json, os, dpgen_torch
            out = {}
            try:
                dpgen_torch.load("bad.cpp")
            except dpgen_torch.KernelError as e:
                out["file"] = [str(e), e.diagnostics]
            try:
                dpgen_torch.load(open("bad.cpp").read())
            except dpgen_torch.KernelError as e:
                out["string"] = [str(e), e.diagnostics]
            try:
                dpgen_torch.load(open("bad.cpp").read(), name="mine")
            except dpgen_torch.KernelError as e:
                out["named"] = str(e)
            try:
                dpgen_torch.load("no_compile.cpp")
            except dpgen_torch.CompileError as e:
                out["compile"] = [str(e), e.log_path, open(e.log_path).read()]
            for label, call in (("missing", lambda: dpgen_torch.load("nothere.cpp")),
                                ("name", lambda: dpgen_torch.load("heat.cpp", name="a-b"))):
                try:
                    call()
                except (FileNotFoundError, ValueError) as e:
                    out[label] = type(e).__name__ + ": " + str(e)
            print(json.dumps(out))
        """)
        bad = os.path.join(self.work, "bad.cpp")
        message, diags = r["file"]
        self.assertIn(f"{bad}:6:", message)
        self.assertIn("error:", message)
        self.assertEqual(diags[0][:2], [bad, 6])
        message, diags = r["string"]
        self.assertIn("<string>:6:", message)
        self.assertNotIn(self.cache, message)  # no temporary path in the user's messages
        self.assertEqual(diags[0][:2], ["<string>", 6])
        self.assertIn("<mine>:6:", r["named"])
        message, log, log_text = r["compile"]
        self.assertIn(log, message)
        self.assertTrue(log.startswith(self.cache))
        self.assertIn("no_compile.cpp:3:2: error: #error", message)
        self.assertIn("#error", log_text)
        self.assertIn("FileNotFoundError", r["missing"])
        self.assertIn("must be a C identifier", r["name"])
        # a failed build leaves no cache entry, only its .failed folder
        self.assertEqual([n for n in os.listdir(self.cache) if n.startswith("no_compile")
                          and not n.endswith(".failed")], [])

    def test_e_editing_an_included_header_rebuilds(self):
        if not getattr(type(self), "library", None):
            self.skipTest("needs test_b's build")
        with open(os.path.join(self.work, "heat_flux.hpp"), "w") as f:
            f.write(FLUX.format(2.0))
        r = self.child("""
            import json, torch, dpgen_torch
            m = dpgen_torch.load("heat.cpp")
            x = m.heat_step(torch.ones(5, dtype=torch.float64),
                            torch.arange(6, dtype=torch.float64), 5, 0.1)
            print(json.dumps({"library": m.__file__, "x": x.tolist()}))
        """)
        self.assertNotEqual(r["library"], type(self).library)
        # T = 1 everywhere: the flux terms vanish; then a kernel that does read the header:
        self.assertEqual(r["x"], [0.0, 1.0, 1.0, 1.0, 0.0])
        r2 = self.child("""
            import json, torch, dpgen_torch
            m = dpgen_torch.load("heat.cpp")
            T = torch.tensor([0.0, 1.0, 0.0], dtype=torch.float64)
            x = m.heat_step(T, torch.ones(4, dtype=torch.float64), 3, 0.1)
            print(json.dumps({"library": m.__file__, "x": x.tolist()}))
        """)
        self.assertEqual(r2["library"], r["library"])  # and that build is the cached one now
        self.assertAlmostEqual(r2["x"][1], 1.0 + 2.0 * 0.1 * (-1.0 - 1.0), places=14)
        heat = [n for n in os.listdir(self.cache) if n.startswith("heat-")]
        self.assertEqual(len(heat), 1, heat)  # the stale entry was replaced

    def test_f_readme_quick_start_twice_at_once(self):
        # The README's example as a reader pastes it (a string kernel), run by two processes at
        # the same time on one cache: both get the op, and the cache holds one whole entry.
        with open(os.path.join(ROOT, "README.md")) as f:
            readme = f.read()
        start = readme.index("```python\n", readme.index("## Python quick start")) + 10
        snippet = readme[start:readme.index("```", start)]
        self.assertIn("dpgen_torch.load(", snippet)
        env = {k: v for k, v in os.environ.items()
               if not k.startswith("DPGEN") and k != "PYTHONPATH"}
        env["DPGEN_TORCH_CACHE"] = self.cache
        procs = [subprocess.Popen([os.path.join(self.env_dir, "bin", "python"), "-c", snippet],
                                  cwd=self.work, env=env, stdout=subprocess.PIPE,
                                  stderr=subprocess.STDOUT, text=True) for _ in range(2)]
        for p in procs:
            out = p.communicate()[0]
            self.assertEqual(p.returncode, 0, out)
            self.assertEqual(out.strip().splitlines()[0], "True", out)  # gradcheck
        entries = [n for n in os.listdir(self.cache) if "blur" in n]
        self.assertEqual(len(entries), 1, entries)
        self.assertTrue(os.path.isfile(os.path.join(self.cache, entries[0], "manifest.json")))


if __name__ == "__main__":
    sys.exit(0 if unittest.main(exit=False, verbosity=2).result.wasSuccessful() else 1)
