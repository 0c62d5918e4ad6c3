"""The `dpgen` command a pip install puts on PATH: runs the generator installed in the package."""
import os
import sys

from . import _locate


def main():
    exe = _locate.generator()
    os.execv(exe, [exe] + sys.argv[1:])
