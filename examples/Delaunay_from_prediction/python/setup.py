# Copyright (c) 2026 Delaunay_from_prediction contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
#
# The Python module `delaunay_from_prediction` built by pip, without CMake and without a
# download, with Debian's python3-setuptools, python3-pybind11 and python3-numpy:
#
#   python3 -m pip install --no-build-isolation examples/Delaunay_from_prediction/python
#
# (from the repository root; in a venv made with `/usr/bin/python3 -m venv
# --system-site-packages`, or for Debian's /usr/bin/python3 itself, which refuses pip outside
# a venv unless given --break-system-packages, PEP 668). The same module as CMake's target
# delaunay_from_prediction_python: one translation unit, the package's headers from the
# repository's include/ (found from this file's path: build from a checkout), CGAL (header-only;
# Epick's exact fallback uses GMP, through gmpxx when it links, as CGAL's CMake does, and MPFR),
# Release flags (-O3 -DNDEBUG -g0: Debian's Python adds -g, and debug information for this one
# large CGAL translation unit is large and slow to write), -frounding-math (CGAL's interval
# arithmetic with g++), C++17, hidden visibility. TBB (CGAL_LINKED_WITH_TBB, for the functions'
# parallel=True) when a test program using it compiles and links; DFP_NO_TBB=1 turns it off.
# setuptools' build/ and .egg-info go to a temporary folder removed when setup.py exits, so that
# the source tree stays clean (pip builds in place).

import atexit
import os
import re
import shutil
import sys
import tempfile

from setuptools import setup

try:
    from pybind11.setup_helpers import Pybind11Extension, build_ext
except ImportError:
    sys.exit("delaunay_from_prediction: pybind11 is missing: install Debian's python3-pybind11 "
             "(scripts/install_dependencies.sh does), then pip install --no-build-isolation")

HERE = os.path.dirname(os.path.abspath(__file__))
REPOSITORY = os.path.normpath(os.path.join(HERE, "..", "..", ".."))
INCLUDE = os.path.join(REPOSITORY, "include")
if not os.path.isfile(os.path.join(INCLUDE, "CGAL", "Delaunay_from_prediction_2.h")):
    sys.exit("delaunay_from_prediction: the package's headers are not at " + INCLUDE +
             " (include/CGAL/Delaunay_from_prediction_2.h): setup.py builds from a checkout of "
             "the repository, three folders above it (examples/Delaunay_from_prediction/python)")


def version():
    """package_info's version if it has one, else the project's (top-level CMakeLists.txt,
    project(... VERSION x.y.z)), else 0.1.0."""
    for name in ("version", "version.txt"):
        path = os.path.join(REPOSITORY, "package_info", "Delaunay_from_prediction", name)
        if os.path.isfile(path):
            with open(path, encoding="utf-8") as f:
                text = f.read().strip()
            if text:
                return text
    path = os.path.join(REPOSITORY, "CMakeLists.txt")
    if os.path.isfile(path):
        with open(path, encoding="utf-8") as f:
            match = re.search(r"project\s*\(\s*Delaunay_from_prediction\b[^)]*\bVERSION\s+([0-9][0-9.]*)",
                              f.read())
        if match:
            return match.group(1)
    return "0.1.0"


def description():
    path = os.path.join(REPOSITORY, "package_info", "Delaunay_from_prediction", "description.txt")
    if os.path.isfile(path):
        with open(path, encoding="utf-8") as f:
            return f.read().strip()
    return "Delaunay triangulation from a predicted triangulation (CGAL)"


def links(compiler, source, libraries):
    """Whether a C++17 program compiles and links with these libraries (the compiler and
    flags setuptools uses for the module)."""
    from setuptools.errors import CompileError, LinkError
    with tempfile.TemporaryDirectory() as folder:
        path = os.path.join(folder, "check.cpp")
        with open(path, "w", encoding="utf-8") as f:
            f.write(source)
        try:
            objects = compiler.compile([path], output_dir=folder, extra_postargs=["-std=c++17"])
            compiler.link_executable(objects, os.path.join(folder, "check"), libraries=libraries,
                                     target_lang="c++")
        except (CompileError, LinkError):
            return False
    return True


TBB_CHECK = """#include <tbb/parallel_for.h>
#include <tbb/scalable_allocator.h>
#include <atomic>
int main() { std::atomic<int> n{0}; tbb::parallel_for(0, 8, [&](int) { ++n; });
  tbb::scalable_allocator<int> a; a.deallocate(a.allocate(1), 1); return n == 8 ? 0 : 1; }
"""
GMPXX_CHECK = """#include <gmpxx.h>
int main() { mpq_class q(1, 3); return q * 3 == 1 ? 0 : 1; }
"""


class BuildExt(build_ext):
    """pybind11's build_ext, with TBB and gmpxx added when they link (as CMake's CGAL::CGAL and
    CGAL::TBB_support do)."""

    def build_extensions(self):
        gmpxx = links(self.compiler, GMPXX_CHECK, ["gmpxx", "gmp"])
        no_tbb = os.environ.get("DFP_NO_TBB", "").strip().lower() not in ("", "0", "off", "no", "false")
        tbb = not no_tbb and links(self.compiler, TBB_CHECK, ["tbb", "tbbmalloc"])
        for ext in self.extensions:
            if gmpxx:
                ext.define_macros.append(("CGAL_USE_GMPXX", "1"))
                ext.libraries[:0] = ["gmpxx"]
            if tbb:
                ext.define_macros.append(("CGAL_LINKED_WITH_TBB", None))
                ext.libraries[:0] = ["tbb", "tbbmalloc"]
        print("delaunay_from_prediction: TBB " +
              ("found: CGAL_LINKED_WITH_TBB, -ltbb -ltbbmalloc" if tbb else
               "turned off (DFP_NO_TBB)" if no_tbb else "not found (libtbb-dev): parallel=True runs on one thread") +
              "; gmpxx " + ("found: CGAL_USE_GMPXX" if gmpxx else "not found"))
        super().build_extensions()


# Relative when setup.py runs in its folder (pip does), so that the object lands under build/.
SOURCE = os.path.join(HERE, "delaunay_from_prediction_python.cpp")
if os.path.abspath(os.getcwd()) == HERE:
    SOURCE = os.path.basename(SOURCE)

# Out of the source tree: build/ (objects, the wheel's staging) and the .egg-info.
scratch = tempfile.mkdtemp(prefix="delaunay_from_prediction_build_")
atexit.register(shutil.rmtree, scratch, True)

setup(
    name="delaunay-from-prediction",
    version=version(),
    description=description(),
    license="GPL-3.0-or-later",
    classifiers=["License :: OSI Approved :: GNU General Public License v3 or later (GPLv3+)",
                 "Programming Language :: C++", "Programming Language :: Python :: 3"],
    python_requires=">=3.7",
    install_requires=["numpy"],
    packages=[],
    ext_modules=[
        Pybind11Extension(
            "delaunay_from_prediction",
            [SOURCE],
            include_dirs=[INCLUDE],
            libraries=["mpfr", "gmp"],
            cxx_std=17,
            # After Python's own flags (Debian's -O2 -g): CMake's Release flags win.
            extra_compile_args=["-O3", "-DNDEBUG", "-g0", "-frounding-math", "-fvisibility=hidden"],
        )
    ],
    cmdclass={"build_ext": BuildExt},
    zip_safe=False,
    options={"build": {"build_base": os.path.join(scratch, "build")},
             "egg_info": {"egg_base": scratch}},
)
