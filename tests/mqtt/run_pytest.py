#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-2-Clause
"""Runs the MQTT tests (test_mqtt.py) under pytest. Meson runs it with protocol 'gtest' only
so that it merges the junit file pytest writes (at the --gtest_output=xml:FILE path Meson
passes) into its own log, where scripts/run-tests.sh counts each case. Exit 77 (skipped,
with the reason) without pytest; each case skips by itself where its dependency is absent.

    run_pytest.py TEST_FILE [PYTEST_ARGS...] [--gtest_output=xml:FILE]
"""
import importlib.util
import os
import subprocess
import sys

SKIP = 77


def main():
    args = [a for a in sys.argv[1:] if not a.startswith("--gtest_output=")]
    junit = [a.split("xml:", 1)[1] for a in sys.argv[1:] if a.startswith("--gtest_output=xml:")]
    if not args:
        print("usage: run_pytest.py TEST_FILE [PYTEST_ARGS...]", file=sys.stderr)
        return 2
    if importlib.util.find_spec("pytest") is None:
        print("SKIP: no pytest for %s (Debian: apt-get install python3-pytest)" % sys.executable)
        return SKIP
    test_file = args[0]
    env = dict(os.environ, PYTHONDONTWRITEBYTECODE="1")
    cmd = [sys.executable, "-m", "pytest", "-v", "-rsP", "-p", "no:cacheprovider", "--rootdir",
           os.path.dirname(os.path.abspath(test_file)), "-o", "junit_suite_name=mqtt"] + args
    if junit:
        cmd += ["--junit-xml", junit[0]]
    print("+ " + " ".join(cmd), flush=True)
    return subprocess.run(cmd, env=env).returncode


if __name__ == "__main__":
    sys.exit(main())
