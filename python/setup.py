"""Builds the extension module with the checkout's CMake project (the build directory of
scripts/setup.sh, or PPSYNTH_BUILD_DIR) and packs it with the package's Python files."""
import os
import shutil
import subprocess

from setuptools import setup
from setuptools.command.build_py import build_py
from setuptools.dist import Distribution

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BUILD = os.environ.get("PPSYNTH_BUILD_DIR", os.path.join(ROOT, "build"))


class BuildWithCMake(build_py):
    def run(self):
        if not os.path.exists(os.path.join(BUILD, "CMakeCache.txt")):
            subprocess.check_call(["cmake", "-S", ROOT, "-B", BUILD, "-G", "Ninja", "-DCMAKE_BUILD_TYPE=Release"])
        subprocess.check_call(["cmake", "--build", BUILD, "--target", "ppsynth_python", "-j", str(os.cpu_count() or 1)])
        src = os.path.join(BUILD, "python", "ppsynth")
        dst = os.path.join(self.build_lib, "ppsynth")
        shutil.rmtree(dst, ignore_errors=True)
        shutil.copytree(src, dst, ignore=shutil.ignore_patterns("__pycache__"))


class WithExtension(Distribution):
    def has_ext_modules(self):  # a platform wheel: the package holds a compiled module
        return True


setup(cmdclass={"build_py": BuildWithCMake}, distclass=WithExtension, packages=[])
