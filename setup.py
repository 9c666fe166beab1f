"""Builds the Python package `cueball` with CMake (see pyproject.toml).

setuptools only supplies the wheel: the sources, the compiler flags and the
install rules are python/CMakeLists.txt's. build_ext configures the project
with the Python module only (no CLI, tests or benchmarks), builds it, and
copies into the wheel what `cmake --install --component python` installs, so
whatever python/CMakeLists.txt installs (the extension, a package directory,
stubs) is what pip installs. Nothing is downloaded.

Environment: CUEBALL_CMAKE_ARGS (extra -D options, split on whitespace),
CMAKE_BUILD_PARALLEL_LEVEL (parallel jobs, default all cores), CMAKE_GENERATOR
(default Ninja when ninja is on PATH), CUEBALL_CMAKE_BUILD_DIR (a build tree of
this source already configured with -DCUEBALL_BUILD_PYTHON=ON, for the same
Python as pip's, such as build/release: its module is brought up to date with
`cmake --build` and packaged, instead of configuring and compiling a tree of
its own; ctest python_install uses it).
"""

import os
import re
import shutil
import subprocess
import sys
import sysconfig
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = Path(__file__).resolve().parent


def project_version():
    """The VERSION of project(cueball ...) in CMakeLists.txt: one source of truth."""
    text = (ROOT / "CMakeLists.txt").read_text(encoding="utf-8")
    match = re.search(r"project\s*\(\s*cueball\b[^)]*?\bVERSION\s+([0-9][0-9.]*)", text)
    if not match:
        raise RuntimeError("CMakeLists.txt: no VERSION in project(cueball ...)")
    return match.group(1)


def run(command, **kwargs):
    print("+ " + " ".join(str(c) for c in command), flush=True)
    subprocess.run([str(c) for c in command], check=True, **kwargs)


class CMakeBuild(build_ext):
    """Builds the module with CMake instead of compiling Extension sources."""

    def run(self):
        cmake = shutil.which("cmake")
        if cmake is None:
            raise RuntimeError("cmake is not on PATH (Debian: apt-get install cmake)")
        jobs = os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL") or str(os.cpu_count() or 1)
        stage = Path(self.build_temp).resolve() / "stage"
        prebuilt = os.environ.get("CUEBALL_CMAKE_BUILD_DIR")
        if prebuilt:
            build_dir = Path(prebuilt).resolve()
            module_dir = stage / self.module_dir_of(build_dir)
        else:
            build_dir = Path(self.build_temp).resolve() / "cmake"
            module_dir = stage
            self.configure(cmake, build_dir)
        run([cmake, "--build", build_dir, "--target", "cueball_python", "-j", jobs])
        if stage.exists():
            shutil.rmtree(stage)
        run([cmake, "--install", build_dir, "--component", "python", "--prefix", stage])
        suffix = sysconfig.get_config_var("EXT_SUFFIX")
        if not list((module_dir / "cueball").glob("_cueball" + suffix)):
            raise RuntimeError(f"cmake --install --component python put no cueball/_cueball{suffix} "
                               f"(the extension for {sys.executable}) in {module_dir}")
        shutil.copytree(module_dir, Path(self.build_lib), dirs_exist_ok=True)

    @staticmethod
    def configure(cmake, build_dir):
        configure = [cmake, "-S", ROOT, "-B", build_dir,
                     "-DCMAKE_BUILD_TYPE=Release",
                     "-DCUEBALL_BUILD_PYTHON=ON",
                     "-DCUEBALL_BUILD_CLI=OFF",
                     "-DCUEBALL_BUILD_TESTS=OFF",
                     "-DCUEBALL_BUILD_BENCHMARKS=OFF",
                     # The interpreter pip runs (a venv's python) and the
                     # module's place relative to the wheel's root.
                     f"-DPython_EXECUTABLE={sys.executable}",
                     "-DCUEBALL_PYTHON_INSTALL_DIR=."]
        if "CMAKE_GENERATOR" not in os.environ and shutil.which("ninja"):
            configure += ["-G", "Ninja"]
        configure += os.environ.get("CUEBALL_CMAKE_ARGS", "").split()
        run(configure)

    @staticmethod
    def module_dir_of(build_dir):
        """CUEBALL_PYTHON_INSTALL_DIR of a configured tree: where it installs the package."""
        cache = build_dir / "CMakeCache.txt"
        if not cache.is_file():
            raise RuntimeError(f"CUEBALL_CMAKE_BUILD_DIR={build_dir}: no CMakeCache.txt (not a configured build tree)")
        match = re.search(r"^CUEBALL_PYTHON_INSTALL_DIR:[A-Z]+=(.*)$", cache.read_text(encoding="utf-8"), re.M)
        if not match:
            raise RuntimeError(f"CUEBALL_CMAKE_BUILD_DIR={build_dir}: not configured with -DCUEBALL_BUILD_PYTHON=ON")
        return match.group(1).strip()

    def get_outputs(self):
        return []


setup(
    version=project_version(),
    ext_modules=[Extension("cueball._cueball", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
)
