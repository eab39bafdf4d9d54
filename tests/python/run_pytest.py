#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-2-Clause
"""Tests the INSTALLED Python binding: `meson install --destdir` into a scratch folder of
the build tree, then pytest on tests/python/test_calped.py with PYTHONPATH pointing into
it (and no path to the build tree's library), so the package must find the library the
way it does after a real `meson install`.

Meson runs it with protocol 'gtest' only so that it merges the junit file pytest writes
(at the --gtest_output=xml:FILE path Meson passes) into its own log: scripts/run-tests.sh
then counts each pytest case like a GoogleTest case. Exit 77 (skipped, with the reason)
without numpy or pytest, and where ctypes cannot load the library (CALPED_PYTEST_SKIP:
sanitizer and cross builds, tests/python/meson.build).

    run_pytest.py BUILD_DIR TEST_FILE [--gtest_output=xml:FILE]
"""
import importlib.util
import os
import shutil
import subprocess
import sys

SKIP = 77


def main():
    args = [a for a in sys.argv[1:] if not a.startswith("--gtest_output=")]
    junit = [a.split("xml:", 1)[1] for a in sys.argv[1:] if a.startswith("--gtest_output=xml:")]
    if len(args) != 2:
        print("usage: run_pytest.py BUILD_DIR TEST_FILE", file=sys.stderr)
        return 2
    build, test_file = args
    reason = os.environ.get("CALPED_PYTEST_SKIP")
    if reason:
        print("SKIP: " + reason)
        return SKIP
    missing = [m for m in ("numpy", "pytest") if importlib.util.find_spec(m) is None]
    if missing:
        print("SKIP: no %s for %s (Debian: apt-get install %s)" % (
            " and ".join(missing), sys.executable, " ".join("python3-" + m for m in missing)))
        return SKIP

    destdir = os.path.join(build, "tests", "python", "destdir")
    shutil.rmtree(destdir, ignore_errors=True)
    install = [os.environ.get("CALPED_MESON", "meson"), "install", "-C", build, "--no-rebuild",
               "--quiet", "--destdir", destdir, "--tags", "runtime,python-runtime"]
    print("+ " + " ".join(install), flush=True)
    subprocess.run(install, check=True)

    env = dict(os.environ)
    for name in ("CALPED_LIBRARY", "LD_LIBRARY_PATH"):
        env.pop(name, None)
    package_parent = destdir + os.environ["CALPED_PY_INSTALL_DIR"]  # absolute, with the prefix
    env["PYTHONPATH"] = package_parent
    env["CALPED_TEST_DESTDIR"] = os.path.abspath(destdir)
    env["PYTHONDONTWRITEBYTECODE"] = "1"  # nothing written into the source tree
    cmd = [sys.executable, "-m", "pytest", "-v", "-p", "no:cacheprovider", "--rootdir",
           os.path.dirname(os.path.abspath(test_file)), "-o", "junit_suite_name=python", test_file]
    if junit:
        cmd += ["--junit-xml", junit[0]]
    print("+ PYTHONPATH=%s %s" % (package_parent, " ".join(cmd)), flush=True)
    rc = subprocess.run(cmd, env=env).returncode
    if rc == 0:
        shutil.rmtree(destdir, ignore_errors=True)
    return rc


if __name__ == "__main__":
    sys.exit(main())
