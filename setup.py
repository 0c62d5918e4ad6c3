"""pip's build of dpgen_torch: CMake builds the generator (tool/) and the shipped kernels' ops
library (torch/), and the package gets them with the runtime headers:

    dpgen_torch/bin/dpgen                  the generator (finds ../include/dpgen/annotate.hpp)
    dpgen_torch/include/dpgen/*.hpp        the runtime headers (annotate.hpp, torch.hpp, ...)
    dpgen_torch/lib/libdpgen_torch.so      torch.ops.dpgen.<shipped kernel>, loaded at import

The CMake build folder is build-pip/ in the source tree (kept, so that a reinstall only
rebuilds what changed), or $DPGEN_CMAKE_BUILD_DIR: an existing build folder configured with
-DDPGEN_WITH_TORCH=ON is used as it is (its targets dpgen and dpgen_torch brought up to date);
an empty or new one is configured here. $CMAKE_BUILD_PARALLEL_LEVEL sets the jobs (default 2).
"""
import os
import shutil
import subprocess
import sys

from setuptools import setup
from setuptools.command.build_py import build_py
from setuptools.dist import Distribution

ROOT = os.path.dirname(os.path.abspath(__file__))


class BinaryDistribution(Distribution):
    """The wheel holds an executable and a shared library: platform-specific."""

    def has_ext_modules(self):
        return True


def _cmake_cache(build_dir):
    cache = {}
    try:
        with open(os.path.join(build_dir, "CMakeCache.txt")) as f:
            for line in f:
                name, sep, value = line.strip().partition("=")
                if sep and not line.startswith(("#", "//")):
                    cache[name.split(":")[0]] = value
    except OSError:
        pass
    return cache


class BuildPyWithCMake(build_py):
    def run(self):
        super().run()
        build_dir = os.path.abspath(os.environ.get("DPGEN_CMAKE_BUILD_DIR") or
                                    os.path.join(ROOT, "build-pip"))
        cache = _cmake_cache(build_dir)
        if not cache:
            generator = ["-G", "Ninja"] if shutil.which("ninja") else []
            self._run(["cmake", "-S", ROOT, "-B", build_dir] + generator + [
                "-DCMAKE_BUILD_TYPE=Release", "-DDPGEN_WITH_TORCH=ON",
                "-DDPGEN_BUILD_TESTS=OFF", "-DDPGEN_BUILD_EXAMPLES=OFF", "-DDPGEN_INSTALL=OFF",
                f"-DPython3_EXECUTABLE={sys.executable}"])
        elif cache.get("DPGEN_WITH_TORCH", "OFF").upper() not in ("ON", "1", "TRUE", "YES"):
            raise RuntimeError(f"dpgen_torch: the CMake build folder {build_dir} is configured "
                               "without -DDPGEN_WITH_TORCH=ON")
        jobs = os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL", "2")
        self._run(["cmake", "--build", build_dir, "-j", jobs, "--target", "dpgen", "dpgen_torch"])

        pkg = os.path.join(self.build_lib, "dpgen_torch")
        for sub in ("bin", "lib", "include"):
            shutil.rmtree(os.path.join(pkg, sub), ignore_errors=True)
        os.makedirs(os.path.join(pkg, "bin"))
        os.makedirs(os.path.join(pkg, "lib"))
        shutil.copy2(os.path.join(build_dir, "tool", "dpgen"), os.path.join(pkg, "bin", "dpgen"))
        shutil.copy2(os.path.join(build_dir, "torch", "libdpgen_torch.so"),
                     os.path.join(pkg, "lib", "libdpgen_torch.so"))
        shutil.copytree(os.path.join(ROOT, "runtime", "include", "dpgen"),
                        os.path.join(pkg, "include", "dpgen"))

    def _run(self, cmd):
        print("dpgen_torch build:", " ".join(cmd), flush=True)
        subprocess.run(cmd, check=True)


setup(
    package_dir={"": "python"},
    packages=["dpgen_torch"],
    cmdclass={"build_py": BuildPyWithCMake},
    distclass=BinaryDistribution,
    # setuptools' own build folder, away from CMake's build/ of scripts/test.sh
    options={"build": {"build_base": os.path.join("build-pip", "setuptools")}},
    zip_safe=False,
)
