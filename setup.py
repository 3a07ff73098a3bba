"""Builds tessera's Python module (python/, pybind11) with CMake for `pip install .`.

The extension tessera._tessera is configured and built by CMake from this source tree (only the
module's target, with TESSERA_BUILD_TESTS/EXAMPLES/CLI off) and copied into the package directory
next to python/tessera/*.py. Needs cmake, a C++20 compiler, pybind11 and NumPy (Debian: cmake
pybind11-dev python3-dev python3-numpy); no download. Environment: CMAKE_BUILD_PARALLEL_LEVEL
(build jobs), TESSERA_CMAKE_ARGS (extra configure arguments).
"""
import os
import re
import shlex
import subprocess
import sys
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = Path(__file__).resolve().parent


def version():
    text = (ROOT / "include" / "tessera" / "version.hpp").read_text()
    return re.search(r'TESSERA_VERSION_STRING "([0-9.]+)"', text).group(1)


class CMakeExtension(Extension):
    def __init__(self, name):
        super().__init__(name, sources=[])


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        target_dir = Path(self.get_ext_fullpath(ext.name)).resolve().parent
        build_dir = Path(self.build_temp).resolve() / "cmake"
        build_dir.mkdir(parents=True, exist_ok=True)
        configure = [
            "cmake", "-S", str(ROOT), "-B", str(build_dir), "-Wno-dev", "-DCMAKE_BUILD_TYPE=Release",
            f"-DPython_EXECUTABLE={sys.executable}", "-DTESSERA_BUILD_PYTHON=ON", "-DTESSERA_BUILD_TESTS=OFF",
            "-DTESSERA_BUILD_EXAMPLES=OFF", "-DTESSERA_BUILD_CLI=OFF", "-DTESSERA_INSTALL=OFF",
            "-DTESSERA_WERROR=OFF",
        ]
        try:
            import pybind11
            configure.append(f"-Dpybind11_DIR={pybind11.get_cmake_dir()}")
        except ImportError:
            pass
        configure += shlex.split(os.environ.get("TESSERA_CMAKE_ARGS", ""))
        subprocess.run(configure, check=True)
        jobs = os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL", "2")
        subprocess.run(["cmake", "--build", str(build_dir), "--target", "tessera_python", "-j", jobs], check=True)
        built = next((build_dir / "python" / "tessera").glob("_tessera*.so"), None)
        if built is None:
            raise RuntimeError("CMake did not build tessera._tessera (is pybind11 / NumPy found? see the log above)")
        target_dir.mkdir(parents=True, exist_ok=True)
        self.copy_file(str(built), str(target_dir / built.name))


setup(
    version=version(),
    packages=["tessera"],
    package_dir={"tessera": "python/tessera"},
    package_data={"tessera": ["py.typed", "*.pyi"]},
    ext_modules=[CMakeExtension("tessera._tessera")],
    cmdclass={"build_ext": CMakeBuild},
    zip_safe=False,
)
