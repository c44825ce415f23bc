"""Builds the extension glint._glint with CMake (pyproject.toml has the rest): the libraries and
the module alone, optimised, with the Python that runs this."""

import glob
import os
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = os.path.dirname(os.path.abspath(__file__))


class CMakeBuild(build_ext):
    def build_extension(self, ext: Extension) -> None:
        build = os.path.join(os.path.abspath(self.build_temp), "cmake")
        subprocess.run(["cmake", "-S", ROOT, "-B", build, "-DCMAKE_BUILD_TYPE=Release",
                        "-DGLINT_BUILD_TESTS=OFF", "-DGLINT_BUILD_BENCHMARKS=OFF",
                        "-DGLINT_BUILD_PYTHON=ON", f"-DPython_EXECUTABLE={sys.executable}"],
                       check=True)
        subprocess.run(["cmake", "--build", build, "--target", "glint_python", "-j",
                        str(os.cpu_count() or 1)], check=True)
        built = glob.glob(os.path.join(build, "python", "glint", "_glint*.so"))
        if len(built) != 1:
            raise RuntimeError(f"expected one built _glint module, found {built}")
        target = self.get_ext_fullpath(ext.name)
        os.makedirs(os.path.dirname(target), exist_ok=True)
        shutil.copyfile(built[0], target)


setup(ext_modules=[Extension("glint._glint", sources=[])], cmdclass={"build_ext": CMakeBuild})
