#!/usr/bin/env python3
"""dpgen_torch.prune_cache and load()'s pruning after a build, on cache folders made up here
(entries of known sizes and last-use times): age bound, size bound (least recently used first),
the grace period and the entries this process has loaded, leftovers of crashed builds, dry runs,
the environment's bounds, bad bounds; and that load() prunes after a build (the build itself
replaced by a stand-in: the real one is torch.package's)."""
import os
import shutil
import sys
import tempfile
import time

import dpgen_torch
from dpgen_torch import _load

MB = 1024 * 1024
failures = []


def check(cond, what):
    print(("ok   " if cond else "FAIL ") + what)
    if not cond:
        failures.append(what)


def make_entry(root, name, size_mb, age_s, manifest=True):
    path = os.path.join(root, name)
    os.makedirs(path)
    with open(os.path.join(path, "libx.so"), "wb") as f:
        f.write(b"\0" * int(size_mb * MB))
    t = time.time() - age_s
    if manifest:
        with open(os.path.join(path, "manifest.json"), "w") as f:
            f.write("{}")
        os.utime(os.path.join(path, "manifest.json"), (t, t))
    os.utime(path, (t, t))
    return path


def names(paths):
    return sorted(os.path.basename(p) for p in paths)


def main():
    day = 86400
    for var in ("DPGEN_TORCH_CACHE_MAX_MB", "DPGEN_TORCH_CACHE_MAX_AGE_DAYS"):
        os.environ.pop(var, None)
    tmp = tempfile.mkdtemp(prefix="dpgen-prune-test-")
    try:
        root = os.path.join(tmp, "cache")
        os.makedirs(root)
        make_entry(root, "a-old", 1, 40 * day)
        make_entry(root, "b-10d", 1, 10 * day)
        make_entry(root, "c-5d", 1, 5 * day)
        make_entry(root, "d-2min", 1, 120)
        make_entry(root, "e-old.failed", 0.1, 40 * day, manifest=False)
        make_entry(root, ".e-build-crashed", 0.1, 2 * day, manifest=False)
        make_entry(root, ".f-build-running", 0.1, 30, manifest=False)
        make_entry(root, "g.trash-1234abcd", 0.1, 10, manifest=False)
        make_entry(root, "not-ours", 1, 400 * day, manifest=False)
        with open(os.path.join(root, "README"), "w") as f:
            f.write("a file in the cache folder stays\n")

        # dry run: nothing goes
        dry = dpgen_torch.prune_cache(max_mb=0, max_age_days=30, cache=root, dry_run=True)
        check(names(dry) == [".e-build-crashed", "a-old", "e-old.failed", "g.trash-1234abcd"],
              f"dry run lists the old entries and leftovers: {names(dry)}")
        check(os.path.isdir(os.path.join(root, "a-old")), "dry run removes nothing")

        # age bound
        removed = dpgen_torch.prune_cache(max_mb=0, max_age_days=30, cache=root)
        check(names(removed) == names(dry), f"age bound removes them: {names(removed)}")
        left = sorted(os.listdir(root))
        check(left == [".f-build-running", "README", "b-10d", "c-5d", "d-2min", "not-ours"],
              f"left: {left}")

        # size bound: least recently used first, until under the bound
        removed = dpgen_torch.prune_cache(max_mb=1.5, max_age_days=0, cache=root)
        check(names(removed) == ["b-10d", "c-5d"], f"size bound 1.5 MB removes the two least "
              f"recently used: {names(removed)}")

        # the grace period and this process's entries are kept even over the bound
        make_entry(root, "h-now", 1, 5)
        make_entry(root, "i-loaded", 1, 60 * day)
        _load._loaded[os.path.join(root, "i-loaded")] = object()
        try:
            removed = dpgen_torch.prune_cache(max_mb=0.5, max_age_days=30, cache=root)
        finally:
            del _load._loaded[os.path.join(root, "i-loaded")]
        check(names(removed) == ["d-2min"], f"size bound 0.5 MB: only d-2min goes (h-now was "
              f"used seconds ago, i-loaded is loaded here): {names(removed)}")
        check(os.path.isdir(os.path.join(root, "i-loaded")) and
              os.path.isdir(os.path.join(root, "h-now")), "both kept")

        # bounds from the environment
        os.environ["DPGEN_TORCH_CACHE_MAX_AGE_DAYS"] = "1"
        os.environ["DPGEN_TORCH_CACHE_MAX_MB"] = "0"
        removed = dpgen_torch.prune_cache(cache=root)
        check(names(removed) == ["i-loaded"],
              f"$DPGEN_TORCH_CACHE_MAX_AGE_DAYS=1 removes the 60-day-old entry: {names(removed)}")

        # bad bounds: clear errors
        for kwargs, env, needle in (({"max_mb": -1}, None, "max_mb must be a number >= 0"),
                                    ({"max_age_days": "7"}, None, "max_age_days must be"),
                                    ({}, ("DPGEN_TORCH_CACHE_MAX_MB", "lots"), "is not a number"),
                                    ({}, ("DPGEN_TORCH_CACHE_MAX_AGE_DAYS", "-3"), "must be >= 0")):
            saved = dict(os.environ)
            if env:
                os.environ[env[0]] = env[1]
            try:
                dpgen_torch.prune_cache(cache=root, **kwargs)
                check(False, f"{kwargs or env} raises")
            except ValueError as e:
                check(needle in str(e), f"{kwargs or env} raises ValueError: {e}")
            finally:
                os.environ.clear()
                os.environ.update(saved)
        check(dpgen_torch.prune_cache(cache=os.path.join(tmp, "none")) == [],
              "a missing cache folder: nothing to do")

        # load() prunes after a build (the build and the library load replaced by stand-ins)
        root2 = os.path.join(tmp, "cache2")
        os.makedirs(root2)
        make_entry(root2, "old-entry", 1, 90 * day)
        os.environ["DPGEN_TORCH_CACHE_MAX_AGE_DAYS"] = "30"
        os.environ["DPGEN_TORCH_CACHE_MAX_MB"] = "0"
        real_build, real_module = _load._build_entry, _load._module

        def fake_build(tmpdir, *args, **kwargs):
            open(os.path.join(tmpdir, "libfake.so"), "wb").close()
            return {"format": _load._FORMAT, "source": "<fake>", "stem": "fake",
                    "namespace": "dpgen_fake", "library": "libfake.so", "ops": {}, "deps": [],
                    "remarks": "", "built": ""}

        _load._build_entry = fake_build
        _load._module = lambda entry, manifest: type("M", (), {"__dpgen_manifest__": manifest,
                                                              "entry": entry})()
        try:
            m = dpgen_torch.load("DPGEN_KERNEL void f() {}\n", name="fake", cache=root2)
            built = m.entry
            left = sorted(os.listdir(root2))
            check(left == [os.path.basename(built)],
                  f"after a build, load() pruned the 90-day-old entry: {left}")
            # a hit touches the entry (its last use, for pruning)
            mpath = os.path.join(built, "manifest.json")
            os.utime(mpath, (time.time() - 5 * day,) * 2)
            _load._loaded.clear()
            dpgen_torch.load("DPGEN_KERNEL void f() {}\n", name="fake", cache=root2)
            check(time.time() - os.stat(mpath).st_mtime < 60, "a cache hit marks the entry used")
        finally:
            _load._build_entry, _load._module = real_build, real_module
            _load._loaded.clear()
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    if failures:
        print(f"{len(failures)} check(s) failed", file=sys.stderr)
        return 1
    print("all cache pruning checks passed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
