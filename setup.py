"""Builds the Python module through the project's CMake: the target _meshquilt in
MESHQUILT_BUILD_DIR (default build-python/, configured here when new), then packages
BUILD/python/meshquilt."""
import os
import shutil
import subprocess

from setuptools import Distribution, setup
from setuptools.command.build_py import build_py

ROOT = os.path.dirname(os.path.abspath(__file__))


class CMakeBuild(build_py):
    def run(self):
        super().run()  # the package's Python files
        build = os.environ.get("MESHQUILT_BUILD_DIR") or os.path.join(ROOT, "build-python")
        if not os.path.exists(os.path.join(build, "CMakeCache.txt")):
            subprocess.check_call(["cmake", "-S", ROOT, "-B", build, "-G", "Ninja", "-DCMAKE_BUILD_TYPE=Release",
                                   "-DMESHQUILT_TESTS=OFF", "-DMESHQUILT_PERF=OFF"])
        subprocess.check_call(["cmake", "--build", build, "--target", "_meshquilt", "-j", str(os.cpu_count() or 1)])
        package = os.path.join(build, "python", "meshquilt")
        target = os.path.join(self.build_lib, "meshquilt")
        os.makedirs(target, exist_ok=True)
        for name in os.listdir(package):
            shutil.copy2(os.path.join(package, name), target)


class BinaryDistribution(Distribution):
    def has_ext_modules(self):
        return True  # a platform wheel: the package carries a compiled module


setup(options={"build": {"build_base": "build-setuptools"}}, packages=["meshquilt"], package_dir={"meshquilt": "python/meshquilt"},
      package_data={"meshquilt": ["*.pyi", "py.typed"]}, cmdclass={"build_py": CMakeBuild},
      distclass=BinaryDistribution)
