"""dpgen_torch.load: an annotated kernel file (or source string) to PyTorch ops in one call.

The steps, each a subprocess whose output goes to the entry's build.log:
  1. dpgen <kernel> and dpgen --torch <kernel> (the installed generator) write the adjoint
     and the op sources; a rejected kernel raises KernelError with dpgen's file:line:col lines;
  2. the C++ compiler builds the kernel, its adjoint and the ops (the latter in a wrapper that
     registers them in a namespace of their own, dpgen_<id>, so that two versions of a kernel
     can live in one process) and links lib<stem>.so against libtorch; a failure raises
     CompileError naming the log;
  3. the folder, built under a temporary name, is renamed to its cache key: an entry is there
     whole or not at all.
The key hashes the kernel text, its name, the flags and the toolchain (the generator binary,
the runtime headers, torch's version, the compiler); the headers a kernel includes from
outside /usr are recorded with their hashes and checked on every hit. After every build the
cache is pruned (prune_cache: entries unused for 30 days, then the least recently used while it
is over 2048 MB; $DPGEN_TORCH_CACHE_MAX_AGE_DAYS, $DPGEN_TORCH_CACHE_MAX_MB).
"""
import hashlib
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import threading
import time
import types
import uuid
from concurrent.futures import ThreadPoolExecutor

import torch

from . import _locate

__all__ = ["load", "KernelError", "CompileError", "cache_dir", "prune_cache"]

_FORMAT = 2  # bump when the layout of a cache entry changes
_lock = threading.Lock()
_loaded = {}  # entry folder -> module, in this process
_KERNEL_SUFFIXES = (".cpp", ".cc", ".cxx", ".c")


class KernelError(RuntimeError):
    """dpgen rejected the kernel. str() holds dpgen's messages (`file:line:col: error: ...`,
    the file being the user's kernel file, or `<string>` / `<name>` for a source string);
    `diagnostics` holds them parsed as (file, line, column, severity, message) tuples."""

    def __init__(self, message, diagnostics):
        super().__init__(message)
        self.diagnostics = diagnostics


KernelError.__module__ = "dpgen_torch"


class CompileError(RuntimeError):
    """The C++ compiler or linker failed on the generated code; `log_path` is the full log."""

    def __init__(self, message, log_path):
        super().__init__(message)
        self.log_path = log_path


CompileError.__module__ = "dpgen_torch"


def cache_dir():
    """$DPGEN_TORCH_CACHE, else $XDG_CACHE_HOME/dpgen_torch, else ~/.cache/dpgen_torch."""
    env = os.environ.get("DPGEN_TORCH_CACHE")
    if env:
        return os.path.abspath(env)
    base = os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache")
    return os.path.join(base, "dpgen_torch")


# ---- pruning -------------------------------------------------------------------------------

_DEFAULT_MAX_MB = 2048
_DEFAULT_MAX_AGE_DAYS = 30
_GRACE_SECONDS = 60  # an entry used this recently is never removed for size (another process
#                      may be between reading its manifest and loading its library)
_STALE_BUILD_SECONDS = 24 * 3600  # a temporary build folder this old is a crashed build's


def _limit_from_env(var, default):
    raw = os.environ.get(var)
    if raw is None or raw == "":
        return default
    try:
        value = float(raw)
    except ValueError:
        raise ValueError(f"dpgen_torch: ${var}={raw!r} is not a number") from None
    if not value >= 0 or value != value:
        raise ValueError(f"dpgen_torch: ${var}={raw!r} must be >= 0 (0: no bound)")
    return value


def _tree_size(path):
    total = 0
    for dirpath, _, files in os.walk(path):
        for f in files:
            try:
                total += os.lstat(os.path.join(dirpath, f)).st_size
            except OSError:
                pass
    return total


def _last_use(entry):
    """When an entry was last loaded: its manifest's mtime (touched on every hit), else the
    folder's."""
    for p in (os.path.join(entry, "manifest.json"), entry):
        try:
            return os.stat(p).st_mtime
        except OSError:
            pass
    return 0.0


def _touch(entry):
    try:
        os.utime(os.path.join(entry, "manifest.json"))
    except OSError:  # a read-only cache: the entry just ages
        pass


def prune_cache(max_mb=None, max_age_days=None, cache=None, dry_run=False):
    """Removes cache entries so that the cache stays bounded; returns the removed folders.

    max_age_days: entries not loaded for longer are removed (default
    $DPGEN_TORCH_CACHE_MAX_AGE_DAYS, else 30). max_mb: then, while the cache is larger, the
    least recently loaded entries are removed (default $DPGEN_TORCH_CACHE_MAX_MB, else 2048).
    0 disables either bound. Never removed: the entries this process has loaded, and, for size,
    entries loaded in the last minute (another process may be loading them), so the bound can be
    exceeded by those. Failed builds (<name>-<key>.failed) count as entries; temporary build
    folders of crashed builds (older than a day) and leftovers of interrupted removals always go.
    load() calls this after every build (never on a cache hit, which stays a few milliseconds).
    """
    max_mb = _limit_from_env("DPGEN_TORCH_CACHE_MAX_MB", _DEFAULT_MAX_MB) if max_mb is None \
        else max_mb
    max_age_days = _limit_from_env("DPGEN_TORCH_CACHE_MAX_AGE_DAYS", _DEFAULT_MAX_AGE_DAYS) \
        if max_age_days is None else max_age_days
    for what, value in (("max_mb", max_mb), ("max_age_days", max_age_days)):
        if isinstance(value, bool) or not isinstance(value, (int, float)) or not value >= 0:
            raise ValueError(f"dpgen_torch.prune_cache: {what} must be a number >= 0 (0: no "
                             f"bound), got {value!r}")
    root = os.path.abspath(cache) if cache else cache_dir()
    if not os.path.isdir(root):
        return []
    now = time.time()
    in_use = {os.path.abspath(e) for e in _loaded}
    removed = []

    def remove(path):
        if not dry_run:
            if ".trash-" in os.path.basename(path):
                shutil.rmtree(path, ignore_errors=True)
            else:
                _discard(path)
        removed.append(path)

    entries = []  # (last use, size, path)
    for name in sorted(os.listdir(root)):
        path = os.path.join(root, name)
        if not os.path.isdir(path) or os.path.islink(path):
            continue
        if ".trash-" in name:
            remove(path)
            continue
        if name.startswith("."):  # a build in progress, or a crashed one
            if now - _last_use(path) > _STALE_BUILD_SECONDS:
                remove(path)
            continue
        if not name.endswith(".failed") and not os.path.isfile(os.path.join(path, "manifest.json")):
            continue  # not ours
        entries.append((_last_use(path), _tree_size(path), path))
    kept = []
    for used, size, path in entries:
        if max_age_days > 0 and now - used > max_age_days * 86400 and path not in in_use:
            remove(path)
        else:
            kept.append((used, size, path))
    if max_mb > 0:
        total = sum(size for _, size, _ in kept)
        for used, size, path in sorted(kept):  # least recently used first
            if total <= max_mb * 1024 * 1024:
                break
            if path in in_use or now - used < _GRACE_SECONDS:
                continue
            remove(path)
            total -= size
    return removed


def _sha256_file(path, h=None):
    h = h or hashlib.sha256()
    with open(path, "rb") as f:
        for block in iter(lambda: f.read(1 << 20), b""):
            h.update(block)
    return h


_toolchain_cache = {}


def _compiler(c=False):
    if c:
        return os.environ.get("CC") or shutil.which("cc") or "cc"
    return os.environ.get("CXX") or shutil.which("c++") or "c++"


def _toolchain_id(generator, include_dir):
    """A hash of everything outside the kernel that the built library depends on."""
    cxx, cc = _compiler(), _compiler(c=True)
    parts = [generator, include_dir, cxx, cc]
    stats = []
    for p in (generator, os.path.join(include_dir, "dpgen", "torch.hpp"),
              os.path.join(include_dir, "dpgen", "annotate.hpp")):
        st = os.stat(p)
        stats.append((p, st.st_size, st.st_mtime_ns))
    for p in (cxx, cc):
        real = shutil.which(p) or p
        real = os.path.realpath(real)
        try:
            st = os.stat(real)
            stats.append((real, st.st_size, st.st_mtime_ns))
        except OSError:
            stats.append((real, 0, 0))
    memo = repr((parts, stats))
    if memo in _toolchain_cache:
        return _toolchain_cache[memo]
    h = hashlib.sha256()
    h.update(f"format {_FORMAT}\ntorch {torch.__version__}\npython {sys.version}\n".encode())
    h.update(f"cxx11abi {int(torch._C._GLIBCXX_USE_CXX11_ABI)}\n".encode())
    h.update(repr(parts).encode())
    # the compilers by path, size and time (running them for --version costs more than a hit)
    h.update(repr(stats[3:]).encode())
    for p in (generator, os.path.join(include_dir, "dpgen", "torch.hpp"),
              os.path.join(include_dir, "dpgen", "annotate.hpp")):
        _sha256_file(p, h)
    _toolchain_cache[memo] = h.hexdigest()
    return _toolchain_cache[memo]


def _read_source(source, name):
    """(text, kernel path or None, stem of the generated files, display name) for a file path
    or a source string."""
    if isinstance(source, os.PathLike) or (isinstance(source, str) and "\n" not in source and
                                           "DPGEN_KERNEL" not in source):
        path = os.path.abspath(os.fspath(source))
        if not os.path.isfile(path):
            raise FileNotFoundError(
                f"dpgen_torch.load: no kernel file {path} (pass the kernel's source text, with "
                "its DPGEN_KERNEL functions, to load a string)")
        stem, ext = os.path.splitext(os.path.basename(path))
        if ext not in _KERNEL_SUFFIXES:
            raise ValueError(f"dpgen_torch.load: {path}: a kernel file ends in "
                             f"{', '.join(_KERNEL_SUFFIXES)}")
        with open(path, "r", encoding="utf-8") as f:
            text = f.read()
        return text, path, stem, path
    if not isinstance(source, str):
        raise TypeError("dpgen_torch.load: expected a kernel file path or the kernel's source "
                        f"text, got {type(source).__name__}")
    stem = name or "kernel"
    return source, None, stem, f"<{name}>" if name else "<string>"


def _valid_name(name):
    if not isinstance(name, str) or not re.fullmatch(r"[A-Za-z_][A-Za-z0-9_]*", name):
        raise ValueError(f"dpgen_torch.load: name {name!r} must be a C identifier (it names "
                         "the module, its cache entry and, for a string, its file)")


def _parse_depfile(path):
    """The files a make-style depfile lists (dpgen's --stamp <file>.d)."""
    try:
        with open(path) as f:
            text = f.read().replace("\\\n", " ")
    except OSError:
        return []
    _, _, deps = text.partition(": ")
    return [d.replace("\\ ", " ") for d in re.split(r"(?<!\\)\s+", deps.strip()) if d]


def _deps_ok(deps):
    for path, digest in deps:
        try:
            if _sha256_file(path).hexdigest() != digest:
                return False
        except OSError:
            return False
    return True


_DIAGNOSTIC = re.compile(r"^(.*?):(\d+):(\d+): (error|warning|remark|note): (.*)$")


def _diagnostics(text):
    out = []
    for line in text.splitlines():
        m = _DIAGNOSTIC.match(line)
        if m:
            out.append((m.group(1), int(m.group(2)), int(m.group(3)), m.group(4), m.group(5)))
    return out


class _Build:
    """One build of a cache entry in a temporary folder (tmp) with its log."""

    def __init__(self, tmp, log_path):
        self.tmp = tmp
        self.log_path = log_path
        self.log = open(log_path, "w")

    def run(self, cmd, cwd=None):
        """Runs cmd, logs its command line and output, returns (returncode, output)."""
        started = time.perf_counter()
        p = subprocess.run(cmd, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                           text=True)
        sec = time.perf_counter() - started
        with _lock_log:
            self.log.write("$ " + " ".join(cmd) + "\n" + p.stdout +
                           f"[exit {p.returncode}, {sec:.1f} s]\n\n")
            self.log.flush()
        return p.returncode, p.stdout


    def run_all(self, cmds):
        """Runs cmds at once; the first to fail stops the others (a compile error in the small
        kernel unit need not wait for the ops unit). Returns [(returncode, output)] in order,
        returncode None for a command stopped early."""
        outs = [tempfile.TemporaryFile("w+") for _ in cmds]
        started = time.perf_counter()
        procs = [subprocess.Popen(c, stdout=o, stderr=subprocess.STDOUT, text=True)
                 for c, o in zip(cmds, outs)]
        seconds = [None] * len(procs)
        try:
            while True:
                for i, p in enumerate(procs):
                    if seconds[i] is None and p.poll() is not None:
                        seconds[i] = time.perf_counter() - started
                if all(s is not None for s in seconds):
                    break
                if any(p.returncode not in (None, 0) for p in procs):
                    for p in procs:
                        if p.poll() is None:
                            p.terminate()
                    break
                time.sleep(0.05)
            results = []
            for c, p, o, sec in zip(cmds, procs, outs, seconds):
                stopped = p.poll() is None or p.returncode < 0
                p.wait()
                o.seek(0)
                out = o.read()
                rc = None if stopped else p.returncode
                sec = sec if sec is not None else time.perf_counter() - started
                with _lock_log:
                    self.log.write("$ " + " ".join(c) + "\n" + out +
                                   ("[stopped]" if rc is None else f"[exit {rc}, {sec:.1f} s]") +
                                   "\n\n")
                results.append((rc, out))
            self.log.flush()
            return results
        finally:
            for p in procs:
                if p.poll() is None:
                    p.kill()
                    p.wait()
            for o in outs:
                o.close()


_lock_log = threading.Lock()


def _torch_include_dirs():
    """libtorch's headers as torch.utils.cpp_extension.include_paths() names them (without
    importing that module: it is slow and prints a CUDA notice)."""
    inc = os.path.join(os.path.dirname(torch.__file__), "include")
    return [inc, os.path.join(inc, "torch", "csrc", "api", "include")]


def _op_schemas(torch_cpp):
    """{op name: schema} from the m.def("...") lines of a generated <stem>_torch.cpp."""
    with open(torch_cpp) as f:
        text = f.read()
    schemas = {}
    for m in re.finditer(r'm\.def\(((?:\s*"(?:[^"\\]|\\.)*")+)', text):
        schema = "".join(re.findall(r'"((?:[^"\\]|\\.)*)"', m.group(1)))
        schemas[schema.split("(", 1)[0]] = schema
    return schemas


def _build_entry(tmp, text, kernel_path, stem, display, extra_cflags, include_dirs, generator,
                 include_dir):
    """Generates, compiles and links into tmp; returns the manifest (dict)."""
    gen = os.path.join(tmp, "generated")
    os.makedirs(gen)
    build = _Build(tmp, os.path.join(tmp, "build.log"))
    try:
        ext = os.path.splitext(kernel_path)[1] if kernel_path else ".cpp"
        if kernel_path is None:
            src_dir = os.path.join(tmp, "source")
            os.makedirs(src_dir)
            kernel = os.path.join(src_dir, stem + ext)
            with open(kernel, "w") as f:
                f.write(text)
        else:
            kernel = kernel_path
        kdir = os.path.dirname(kernel)
        incs = ["-I" + kdir] + ["-I" + os.path.abspath(d) for d in include_dirs]
        lang = ["-std=c11"] if ext == ".c" else ["-std=c++17"]

        # 1. the generator, twice (adjoint files; op files), in parallel
        def dpgen(torch_flag):
            tag = "torch" if torch_flag else "adjoint"
            cmd = [generator] + (["--torch"] if torch_flag else []) + [
                kernel, "--out-dir", gen, "--stamp", os.path.join(gen, f"{stem}_{tag}.stamp"),
                "--"] + lang + incs + list(extra_cflags)
            return build.run(cmd)

        with ThreadPoolExecutor(2) as pool:
            results = list(pool.map(dpgen, (False, True)))
        remarks = ""
        for rc, out in results:
            if kernel_path is None:
                out = out.replace(kernel, display)
            if rc != 0:
                diags = _diagnostics(out)
                raise KernelError(f"dpgen rejected {display}:\n{out.rstrip()}", diags)
            remarks = remarks or out
        schemas = _op_schemas(os.path.join(gen, f"{stem}_torch.cpp"))
        if not schemas:
            raise KernelError(f"dpgen found no DPGEN_KERNEL function in {display}", [])

        # 2. compile (kernel, adjoint, ops) in parallel, then link
        build_id = uuid.uuid4().hex[:16]
        namespace = "dpgen_" + build_id
        wrapper = os.path.join(gen, f"{stem}_ops.cpp")
        with open(wrapper, "w") as f:
            f.write(f"// Generated by dpgen_torch.load: the ops of {stem}_torch.cpp registered as\n"
                    f"// torch.ops.{namespace}.<kernel> instead of torch.ops.dpgen.<kernel>.\n"
                    "#include <torch/library.h>\n"
                    "#undef TORCH_LIBRARY_FRAGMENT\n"
                    "#define TORCH_LIBRARY_FRAGMENT(ns, m) "
                    f"_TORCH_LIBRARY_FRAGMENT({namespace}, m, C10_UID)\n"
                    f'#include "{stem}_torch.cpp"\n')
        # <torch/torch.h> (which the generated files include) also brings torch::nn, optim and
        # data: a stand-in with the tensor and autograd API only halves the ops unit's compile
        # time. Should generated code ever need more, the unit is compiled again without it.
        shim = os.path.join(tmp, "torch_light")
        os.makedirs(os.path.join(shim, "torch"))
        with open(os.path.join(shim, "torch", "torch.h"), "w") as f:
            f.write("// dpgen_torch.load: <torch/torch.h> reduced to what the generated ops use\n"
                    "#pragma once\n#include <torch/types.h>\n#include <torch/autograd.h>\n")
        abi = f"-D_GLIBCXX_USE_CXX11_ABI={int(torch._C._GLIBCXX_USE_CXX11_ABI)}"
        common = ["-fPIC", "-fopenmp", "-I" + gen, "-I" + include_dir] + incs
        torch_incs = ["-isystem" + p for p in _torch_include_dirs()]
        objs = os.path.join(tmp, "obj")
        os.makedirs(objs)
        units = [
            ([_compiler(ext == ".c")] + lang + ["-O3", "-DNDEBUG"] + common +
             list(extra_cflags) + ["-c", kernel, "-o", os.path.join(objs, "kernel.o")]),
            ([_compiler()] + ["-std=c++17", "-O3", "-DNDEBUG", abi] + common +
             list(extra_cflags) + ["-c", os.path.join(gen, f"{stem}_adjoint.cpp"), "-o",
                                   os.path.join(objs, "adjoint.o")]),
            ([_compiler()] + ["-std=c++17", "-O2", abi, "-I" + shim] + common + torch_incs +
             list(extra_cflags) + ["-c", wrapper, "-o", os.path.join(objs, "ops.o")]),
        ]
        results = build.run_all(units)
        if results[0][0] == 0 and results[1][0] == 0 and results[2][0] != 0:
            units[2].remove("-I" + shim)
            results[2] = build.run(units[2])
        lib_name = "lib" + re.sub(r"[^A-Za-z0-9_.-]", "_", stem) + f"-{build_id}.so"
        if all(rc == 0 for rc, _ in results):
            libdirs = [os.path.join(os.path.dirname(torch.__file__), "lib")]
            link = ([_compiler(), "-shared", "-fopenmp", "-Wl,-Bsymbolic", "-o",
                     os.path.join(tmp, lib_name)] +
                    [os.path.join(objs, o) for o in ("kernel.o", "adjoint.o", "ops.o")] +
                    [f"-L{d}" for d in libdirs] + [f"-Wl,-rpath,{d}" for d in libdirs] +
                    ["-ltorch", "-ltorch_cpu", "-lc10"])
            results.append(build.run(link))
        for rc, out in results:
            if rc not in (0, None):
                first = "\n".join(l for l in out.splitlines() if "error" in l)[:2000] or out[-2000:]
                if kernel_path is None:
                    first = first.replace(kernel, display)
                raise CompileError(f"dpgen_torch.load: compiling the ops of {display} failed "
                                   f"(full log: {{log}}):\n{first}", build.log_path)

        shutil.rmtree(objs)
        # 3. what a hit checks: the files the kernel includes from outside /usr
        deps = set()
        for tag in ("adjoint", "torch"):
            for d in _parse_depfile(os.path.join(gen, f"{stem}_{tag}.stamp.d")):
                d = os.path.abspath(d)
                if not d.startswith("/usr/") and not d.startswith(tmp + os.sep):
                    deps.add(d)
        return {
            "format": _FORMAT,
            "source": display,
            "stem": stem,
            "namespace": namespace,
            "library": lib_name,
            "ops": schemas,
            "deps": sorted([d, _sha256_file(d).hexdigest()] for d in deps if os.path.isfile(d)),
            "remarks": remarks,
            "built": time.strftime("%Y-%m-%dT%H:%M:%SZ", time.gmtime()),
        }
    finally:
        build.log.close()


def _module(entry, manifest):
    """A module whose attributes are the entry's ops (loading its library once per process)."""
    lib = os.path.join(entry, manifest["library"])
    torch.ops.load_library(lib)
    ns = getattr(torch.ops, manifest["namespace"])
    mod = types.ModuleType(f"dpgen_torch.kernels.{manifest['name']}",
                           f"dpgen ops of {manifest['source']}: " + ", ".join(manifest["ops"]))
    mod.__file__ = lib
    mod.ops = tuple(manifest["ops"])
    mod.schemas = dict(manifest["ops"])
    mod.source = manifest["source"]
    mod.remarks = manifest["remarks"]
    mod.cache_entry = entry
    mod.__dpgen_manifest__ = manifest
    for name in manifest["ops"]:
        setattr(mod, name, getattr(ns, name))
    return mod


def _read_manifest(entry):
    try:
        with open(os.path.join(entry, "manifest.json")) as f:
            manifest = json.load(f)
    except (OSError, ValueError):
        return None
    if manifest.get("format") != _FORMAT or not os.path.isfile(
            os.path.join(entry, manifest.get("library", ""))):
        return None
    return manifest


def _discard(path):
    """Removes a folder (renamed first, so that no reader sees it half deleted)."""
    trash = f"{path}.trash-{uuid.uuid4().hex[:8]}"
    try:
        os.rename(path, trash)
    except OSError:
        return
    shutil.rmtree(trash, ignore_errors=True)


def load(source, *, name=None, extra_cflags=(), include_dirs=(), cache=None, rebuild=False,
         verbose=False):
    """The kernels of an annotated C++ (or C) kernel file as PyTorch ops.

    source: a path to a kernel file (.cpp, .cc, .cxx, .c), or the kernel's source text (a
    string with a newline or DPGEN_KERNEL in it). name: the module's name, a C identifier (the
    cache entry is named after it); by default the file's stem, or "kernel" for a string,
    whose diagnostics say `<name>` when named, else `<string>`. extra_cflags: compiler flags for
    the generator and the compiler (-D..., -O...); include_dirs: more -I folders (the kernel
    file's own folder is always one). cache: the cache folder (default cache_dir()). rebuild:
    build even on a hit.

    Returns a module with one attribute per kernel, torch.ops.<namespace>.<kernel>: the op
    takes the kernel's parameters without its outputs (arrays as contiguous CPU tensors of the
    kernel's dtype, scalars as numbers), returns the outputs, and its backward is the
    generated adjoint. `ops` lists the names, `schemas` their signatures, `remarks` dpgen's
    notes (e.g. reads whose adjoint is computed in scatter form).

    Raises KernelError (dpgen's file:line:col messages) for a kernel outside the subset and
    CompileError (with the log's path) when the generated code does not compile. The first
    call builds (15 to 25 s on 2 cores, mostly compiling against libtorch's headers); later
    calls, in any process, load the cached library (milliseconds). After a build the cache is
    pruned (prune_cache with its default bounds).
    """
    if isinstance(extra_cflags, str) or isinstance(include_dirs, str):
        raise TypeError("dpgen_torch.load: extra_cflags and include_dirs are lists of strings")
    if name is not None:
        _valid_name(name)
    text, kernel_path, stem, display = _read_source(source, name)
    label = re.sub(r"[^A-Za-z0-9_.-]", "_", name or stem)  # the module's and entry's name
    generator, include_dir = _locate.generator(), _locate.include_dir()
    root = os.path.abspath(cache) if cache else cache_dir()
    key = hashlib.sha256()
    for part in (_toolchain_id(generator, include_dir), label, stem,
                 display if kernel_path else "",
                 repr(list(extra_cflags)), repr([os.path.abspath(d) for d in include_dirs]),
                 text):
        key.update(part.encode() + b"\0")
    entry = os.path.join(root, f"{label}-{key.hexdigest()[:24]}")
    with _lock:
        if not rebuild:
            if entry in _loaded and _deps_ok(_loaded[entry].__dpgen_manifest__["deps"]):
                return _loaded[entry]
            manifest = _read_manifest(entry)
            if manifest and _deps_ok(manifest["deps"]):
                _touch(entry)  # its last use, for prune_cache
                _loaded[entry] = _module(entry, manifest)
                return _loaded[entry]
        os.makedirs(root, exist_ok=True)
        tmp = tempfile.mkdtemp(prefix=f".{label}-build-", dir=root)
        started = time.perf_counter()
        if verbose:
            print(f"dpgen_torch.load: building {display} in {tmp}", file=sys.stderr)
        try:
            manifest = _build_entry(tmp, text, kernel_path, stem, display, extra_cflags,
                                    include_dirs, generator, include_dir)
        except (KernelError, CompileError) as e:
            # keep the failed build (its log and generated files) under a stable name
            failed = entry + ".failed"
            _discard(failed)
            os.rename(tmp, failed)
            if isinstance(e, CompileError):
                e.log_path = os.path.join(failed, "build.log")
                e.args = (e.args[0].replace("{log}", e.log_path).replace(tmp, failed),)
            raise e from None
        except BaseException:
            shutil.rmtree(tmp, ignore_errors=True)
            raise
        manifest["name"] = label
        manifest["build_seconds"] = round(time.perf_counter() - started, 2)
        with open(os.path.join(tmp, "manifest.json"), "w") as f:
            json.dump(manifest, f, indent=1)
        if os.path.isdir(entry):
            existing = _read_manifest(entry)
            if existing and not rebuild and _deps_ok(existing["deps"]):
                # another process built it meanwhile: keep theirs (others may be loading it)
                shutil.rmtree(tmp, ignore_errors=True)
                _loaded[entry] = _module(entry, existing)
                return _loaded[entry]
            _discard(entry)  # stale (an included header changed) or rebuild=True
        try:
            os.rename(tmp, entry)
        except OSError:  # another process put a whole entry there first: use it
            shutil.rmtree(tmp, ignore_errors=True)
            manifest = _read_manifest(entry)
            if manifest is None:
                raise
        _discard(entry + ".failed")
        if verbose:
            print(f"dpgen_torch.load: built {entry} in {manifest['build_seconds']} s",
                  file=sys.stderr)
        _loaded[entry] = _module(entry, manifest)
        try:  # keep the cache bounded; a cache we cannot prune never fails a load
            pruned = prune_cache(cache=root)
            if verbose and pruned:
                print(f"dpgen_torch.load: pruned {len(pruned)} cache entries", file=sys.stderr)
        except (OSError, ValueError) as e:
            print(f"dpgen_torch.load: warning: cache not pruned: {e}", file=sys.stderr)
        return _loaded[entry]
