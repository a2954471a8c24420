"""Formulas, to_lsat, compile and the certificates: every bundled formula,
generators and the reduction against the command line, errors."""
import pytest

import gridlock
from conftest import FORMULAS, SEED, cli, cli_json, scaled


def test_round_trip(formula_path, tmp_path):
    f = gridlock.Formula.read(str(formula_path))
    assert gridlock.Formula.parse(f.to_dimacs()) == f
    f.write(str(tmp_path / "f.cnf"))
    assert gridlock.Formula.read(str(tmp_path / "f.cnf")) == f
    g = gridlock.Formula(f.num_vars, f.clauses)
    assert g.clauses == f.clauses and g.comments == []
    assert repr(f).startswith("<gridlock.Formula: ")


def test_sat_solve_equals_cli(formula_path):
    f = gridlock.Formula.read(str(formula_path))
    want = cli_json("cnf", "solve", formula_path)
    got = gridlock.sat_solve(f)
    assert got.status == want["status"]
    if got:
        assert f.satisfies(got.model) and got.model == want["model"]
    assert cli_json("cnf", "check", formula_path)["lsat_le3"] == f.is_lsat("<=3")
    assert cli_json("cnf", "check", formula_path)["lsat"] == f.is_lsat("exact3")


def test_to_lsat_equals_cli_and_lifts(formula_path):
    f = gridlock.Formula.read(str(formula_path))
    red = gridlock.to_lsat(f)
    want = cli_json("cnf", "to-lsat", formula_path)
    out = gridlock.Formula.parse(want["dimacs"])
    assert (red.output.num_vars, red.output.clauses) == (out.num_vars, out.clauses)
    assert red.output.is_lsat("<=3")
    sat = gridlock.sat_solve(f)
    if sat:
        target = red.lift_to_target(sat.model)
        assert red.output.satisfies(target)
        assert f.satisfies(red.lift_to_source(target))
    else:
        assert not gridlock.sat_solve(red.output)


def test_compile_equals_cli_and_lifts(formula_path, tmp_path):
    f = gridlock.Formula.read(str(formula_path))
    lsat = gridlock.to_lsat(f).output
    lsat.write(str(tmp_path / "g.cnf"))
    for model in ("discrete", "continuous"):
        c = gridlock.compile(lsat, model=model)
        cli("compile", tmp_path / "g.cnf", "-o", tmp_path / "i.grid", "--model", model, expect=(0,))
        assert c.instance == gridlock.Instance.read(str(tmp_path / "i.grid"))
        assert c.stats["nodes"] == len(c.instance) and c.model == model
        sat = gridlock.sat_solve(lsat)
        if not sat:
            continue
        schedule = gridlock.lift(c, assignment=sat.model)
        if model == "discrete":
            assert gridlock.simulate(c.instance, order=schedule) is None
            assert lsat.satisfies(gridlock.lift(c, order=schedule))
        else:
            assert gridlock.simulate(c.instance, times=schedule) is None
            assert lsat.satisfies(gridlock.lift(c, times=schedule))


def test_solver_schedule_lifts_to_a_model():
    f = gridlock.Formula.read(str([p for p in FORMULAS if p.stem == "uf20-01"][0]))
    lsat = gridlock.to_lsat(f)
    c = gridlock.compile(lsat.output)
    r = gridlock.solve(c.instance, timeout=60)
    assert r.status == "YES"
    assert f.satisfies(lsat.lift_to_source(gridlock.lift(c, order=r.order)))


@pytest.mark.parametrize("kind", ["ksat", "lsat", "planted"])
def test_generators_equal_cli(kind):
    for i in range(scaled(10)):
        seed = SEED + i
        if kind == "ksat":
            f, args = gridlock.random_ksat(n=12, m=40, seed=seed), ["--n", 12, "--m", 40]
        elif kind == "lsat":
            f, args = gridlock.random_lsat(n=12, m=8, seed=seed), ["--n", 12, "--m", 8]
        else:
            f, args = gridlock.planted_ksat(n=12, m=40, seed=seed), ["--n", 12, "--m", 40]
            assert gridlock.sat_solve(f)
        want = gridlock.Formula.parse(cli_json("cnf", "gen", kind, *args, "--seed", seed)["dimacs"])
        assert (f.num_vars, f.clauses) == (want.num_vars, want.clauses), f"{kind} seed {seed}"
    assert gridlock.random_lsat(n=12, m=8, seed=1).is_lsat("exact3")


def test_bad_formulas_are_errors(tmp_path):
    bad = tmp_path / "bad.cnf"
    bad.write_text("p cnf 2 1\n1 3 0\n")
    code, _, err = cli("cnf", "solve", bad)
    assert code == 1
    with pytest.raises(gridlock.Error) as e:
        gridlock.Formula.read(str(bad))
    assert err.strip() == "gridlock: error: " + str(e.value)
    assert (e.value.file, e.value.line) == (str(bad), 2)
    with pytest.raises(gridlock.Error, match=r"^x\.cnf:1: "):
        gridlock.Formula.parse("p cnf x\n", name="x.cnf")
    with pytest.raises(gridlock.Error):
        gridlock.Formula(2, [[1, 3]])  # literal out of range
    with pytest.raises(gridlock.Error):
        gridlock.random_ksat(n=2, m=5, k=3)  # k > n
    with pytest.raises(gridlock.Error, match="clause 2 is empty"):
        gridlock.compile(gridlock.Formula(1, [[1], []]))
    f = gridlock.Formula(2, [[1, 2]])
    with pytest.raises(gridlock.Error, match="twice"):
        f.satisfies([1, -1])
    with pytest.raises(gridlock.Error, match="form"):
        f.is_lsat("exact4")


def pigeonhole(holes):
    """holes + 1 pigeons in `holes` holes: unsatisfiable, and hard for resolution (CaDiCaL)."""
    var = lambda p, h: p * holes + h + 1  # noqa: E731
    clauses = [[var(p, h) for h in range(holes)] for p in range(holes + 1)]
    clauses += [[-var(p, h), -var(q, h)] for h in range(holes) for p in range(holes + 1) for q in range(p)]
    return gridlock.Formula((holes + 1) * holes, clauses)


def test_sat_solve_limits_and_ctrl_c():
    import os
    import signal
    import threading
    import time

    assert not gridlock.sat_solve(pigeonhole(4))
    hard = pigeonhole(12)
    assert gridlock.sat_solve(hard, timeout=0.3).status == "UNKNOWN"
    assert gridlock.sat_solve(hard, conflicts=100).status == "UNKNOWN"
    timer = threading.Timer(0.5, os.kill, (os.getpid(), signal.SIGINT))
    timer.start()
    start = time.monotonic()
    with pytest.raises(KeyboardInterrupt):
        gridlock.sat_solve(hard)
    timer.join()
    assert time.monotonic() - start < 10
