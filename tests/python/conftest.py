"""Shared set-up of the Python tests (run by ctest: python/CMakeLists.txt).

GRIDLOCK_BINARY is the command line the module's answers are compared with,
GRIDLOCK_SOURCE_DIR the repository (examples/); both default to a build in
build/ of this checkout. GRIDLOCK_TEST_SEED replays the seeded comparisons,
GRIDLOCK_TEST_SCALE scales their counts (as in the C++ tests).
"""
import json
import os
import pathlib
import subprocess

import pytest

SOURCE = pathlib.Path(os.environ.get("GRIDLOCK_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
BINARY = os.environ.get("GRIDLOCK_BINARY", str(SOURCE / "build" / "gridlock"))
INSTANCES = sorted((SOURCE / "examples" / "instances").glob("*.grid"))
FORMULAS = sorted((SOURCE / "examples" / "formulas").glob("*.cnf"))
SEED = int(os.environ.get("GRIDLOCK_TEST_SEED", "2026"))
SCALE = float(os.environ.get("GRIDLOCK_TEST_SCALE", "1"))


def scaled(n):
    return max(1, int(n * SCALE))


def cli(*args, expect=None):
    """Runs the command line; returns (exit code, stdout, stderr)."""
    p = subprocess.run([BINARY, *map(str, args)], capture_output=True, text=True, timeout=600)
    if expect is not None:
        assert p.returncode in expect, f"gridlock {' '.join(map(str, args))}: exit {p.returncode}\n{p.stderr}"
    return p.returncode, p.stdout, p.stderr


def cli_json(*args):
    """Runs the command line with --json; returns its one JSON object."""
    code, out, err = cli(*args, "--json", expect=(0, 1, 10, 20))
    assert out.strip(), f"no JSON from gridlock {' '.join(map(str, args))}: {err}"
    return json.loads(out)


def ids(paths):
    return [p.stem for p in paths]


@pytest.fixture(params=INSTANCES, ids=ids(INSTANCES))
def instance_path(request):
    return request.param


@pytest.fixture(params=FORMULAS, ids=ids(FORMULAS))
def formula_path(request):
    return request.param
