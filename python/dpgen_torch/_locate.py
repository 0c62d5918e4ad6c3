"""Where dpgen_torch finds the generator, the runtime headers and the shipped ops library.

Installed with pip, all three live inside the package (bin/dpgen, include/dpgen/*.hpp,
lib/libdpgen_torch.so). From a source tree (PYTHONPATH=<repo>/python) they come from the first
build*/ folder of that tree and runtime/include. Environment variables override either:
DPGEN_EXECUTABLE (the generator), DPGEN_TORCH_LIBRARY (the ops libraries, os.pathsep-separated).
"""
import glob
import os

PACKAGE_DIR = os.path.dirname(os.path.abspath(__file__))
_SOURCE_ROOT = os.path.dirname(os.path.dirname(PACKAGE_DIR))


def _source_tree():
    """The dpgen source tree this package sits in (python/dpgen_torch), or None when installed."""
    if os.path.isfile(os.path.join(_SOURCE_ROOT, "tool", "main.cpp")) and os.path.isfile(
            os.path.join(_SOURCE_ROOT, "runtime", "include", "dpgen", "annotate.hpp")):
        return _SOURCE_ROOT
    return None


def generator():
    """The dpgen executable: $DPGEN_EXECUTABLE, the packaged bin/dpgen, or
    <tree>/build*/tool/dpgen."""
    env = os.environ.get("DPGEN_EXECUTABLE")
    if env:
        if not os.access(env, os.X_OK):
            raise FileNotFoundError(f"dpgen_torch: DPGEN_EXECUTABLE={env} is not an executable")
        return os.path.abspath(env)
    packaged = os.path.join(PACKAGE_DIR, "bin", "dpgen")
    if os.access(packaged, os.X_OK):
        return packaged
    tree = _source_tree()
    if tree:
        found = sorted(glob.glob(os.path.join(tree, "build*", "tool", "dpgen")))
        if found:
            return found[0]
    raise FileNotFoundError(
        "dpgen_torch: the generator dpgen is not installed with this package; install with "
        "`pip install --no-build-isolation <dpgen source>` or set DPGEN_EXECUTABLE")


def include_dir():
    """The folder holding dpgen/annotate.hpp and dpgen/torch.hpp."""
    packaged = os.path.join(PACKAGE_DIR, "include")
    if os.path.isfile(os.path.join(packaged, "dpgen", "torch.hpp")):
        return packaged
    tree = _source_tree()
    if tree:
        return os.path.join(tree, "runtime", "include")
    raise FileNotFoundError("dpgen_torch: the runtime headers (dpgen/torch.hpp) are not installed")


def shipped_libraries():
    """The ops libraries to load at import: $DPGEN_TORCH_LIBRARY, the packaged
    lib/libdpgen_torch.so, or the first <tree>/build*/torch/libdpgen_torch.so; [] if none."""
    env = os.environ.get("DPGEN_TORCH_LIBRARY")
    if env:
        return [p for p in env.split(os.pathsep) if p]
    packaged = os.path.join(PACKAGE_DIR, "lib", "libdpgen_torch.so")
    if os.path.isfile(packaged):
        return [packaged]
    tree = _source_tree()
    if tree:
        return sorted(glob.glob(os.path.join(tree, "build*", "torch", "libdpgen_torch.so")))[:1]
    return []
