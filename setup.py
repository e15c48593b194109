"""Builds the extension module with this checkout's CMake project and packs it beside the
package's Python files (python/ppsynth). An existing build directory (build/, or
PPSYNTH_BUILD_DIR) is reused: only the module's target is brought up to date there."""
import glob
import os
import shutil
import subprocess

from setuptools import setup
from setuptools.command.build_py import build_py
from setuptools.dist import Distribution

ROOT = os.path.dirname(os.path.abspath(__file__))
BUILD = os.environ.get("PPSYNTH_BUILD_DIR", os.path.join(ROOT, "build"))


class BuildWithCMake(build_py):
    def run(self):
        super().run()  # the Python files of python/ppsynth
        if not os.path.exists(os.path.join(BUILD, "CMakeCache.txt")):
            subprocess.check_call(["cmake", "-S", ROOT, "-B", BUILD, "-G", "Ninja", "-DCMAKE_BUILD_TYPE=Release"])
        subprocess.check_call(["cmake", "--build", BUILD, "--target", "ppsynth_python", "-j", str(os.cpu_count() or 1)])
        modules = glob.glob(os.path.join(BUILD, "python", "ppsynth", "_ppsynth*.so"))
        if len(modules) != 1:
            raise RuntimeError(f"expected one compiled module in {BUILD}/python/ppsynth, found {modules}")
        shutil.copy2(modules[0], os.path.join(self.build_lib, "ppsynth"))


class WithExtension(Distribution):
    def has_ext_modules(self):  # a platform wheel: the package holds a compiled module
        return True


# setuptools' own scratch goes beside CMake's build, not into it (both default to build/).
setup(cmdclass={"build_py": BuildWithCMake}, distclass=WithExtension,
      options={"build": {"build_base": os.path.join(ROOT, ".setuptools-build")}})
