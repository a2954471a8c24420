"""verify and fuzz campaigns (small counts): the records of the command
line's --json, the progress callback, a callback's exception, Ctrl-C."""
import os
import signal
import threading
import time

import pytest

import gridlock
from conftest import FORMULAS, SEED, cli_json

SMALL = [p for p in FORMULAS if p.stem in ("tiny-sat", "tiny-unsat", "lsat-sat")]
# Times differ from run to run; everything else must be equal.
TIMES = {"ms_sat", "ms_compile", "ms_solve", "ms_gaps", "ms_continuous_solve", "ms_certify"}


@pytest.mark.parametrize("model", ["discrete", "continuous", "both"])
def test_verify_equals_cli(model):
    rows = []
    got = gridlock.verify([str(p) for p in SMALL], model=model, progress=rows.append)
    want = cli_json("verify", *SMALL, "--model", model)
    assert got["summary"] == want["summary"]
    assert got["summary"]["agree"] == len(SMALL)
    assert len(got["formulas"]) == len(want["formulas"]) == len(rows)
    for mine, theirs in zip(got["formulas"], want["formulas"]):
        assert {k: v for k, v in mine.items() if k not in TIMES} == {
            k: v for k, v in theirs.items() if k not in TIMES}
    assert rows == got["formulas"]


def test_verify_formula_objects():
    fs = [gridlock.Formula.read(str(p)) for p in SMALL]
    got = gridlock.verify(fs, names=[p.stem for p in SMALL])
    assert [r["formula"] for r in got["formulas"]] == [p.stem for p in SMALL]
    assert [r["sat"] for r in got["formulas"]] == [
        "YES" if gridlock.sat_solve(f) else "NO" for f in fs]
    with pytest.raises(gridlock.Error, match="one name per formula"):
        gridlock.verify(fs, names=["a"])
    with pytest.raises(gridlock.Error, match="no-such.cnf"):
        gridlock.verify(["no-such.cnf"])


def test_fuzz_equals_cli():
    tallies = []
    got = gridlock.fuzz(count=30, seed=SEED, progress=tallies.append)
    want = cli_json("fuzz", "--count", 30, "--seed", SEED)
    for key in ("formulas", "sat", "unsat", "unknown", "certificates_checked", "disagreements", "status", "seed"):
        assert got[key] == want[key], key
    assert len(tallies) == 30 and tallies[-1]["formulas"] == 30
    assert got["formulas"] == got["sat"] + got["unsat"] == 30


def test_jobs_give_the_same_records():
    one = gridlock.fuzz(count=40, seed=SEED, jobs=1)
    two = gridlock.fuzz(count=40, seed=SEED, jobs=2)
    for key in ("formulas", "sat", "unsat", "unknown", "certificates_checked", "no_certificates_checked",
                "disagreements", "status", "seed"):
        assert one[key] == two[key], key
    rows = []
    got = gridlock.verify([str(p) for p in SMALL], jobs=2, progress=rows.append)
    alone = gridlock.verify([str(p) for p in SMALL], jobs=1)
    assert got["summary"] == alone["summary"]
    strip = [{k: v for k, v in r.items() if k not in TIMES} for r in got["formulas"]]
    assert strip == [{k: v for k, v in r.items() if k not in TIMES} for r in alone["formulas"]]
    assert [r["formula"] for r in rows] == [str(p) for p in SMALL]  # in order, whatever finished first
    with pytest.raises(gridlock.Error, match="jobs"):
        gridlock.fuzz(count=1, jobs=0)
    with pytest.raises(gridlock.Error, match="jobs"):
        gridlock.verify([], jobs=2000)


def test_fuzz_formula_is_the_campaigns():
    f = gridlock.fuzz_formula(SEED, 4)
    assert f == gridlock.fuzz_formula(SEED, 4) and f.num_vars >= 3
    assert gridlock.verify([f], names=["f4"])["summary"]["agree"] == 1


def test_callback_exception_stops_the_campaign():
    seen = []

    def progress(tally):
        seen.append(tally)
        if len(seen) == 3:
            raise ValueError("enough")

    with pytest.raises(ValueError, match="enough"):
        gridlock.fuzz(count=500, seed=SEED, progress=progress)
    assert len(seen) == 3
    assert gridlock.fuzz(count=2, seed=SEED)["formulas"] == 2  # the stop request was cleared


def test_ctrl_c_interrupts_fuzz():
    timer = threading.Timer(0.5, os.kill, (os.getpid(), signal.SIGINT))
    timer.start()
    start = time.monotonic()
    with pytest.raises(KeyboardInterrupt):
        gridlock.fuzz(count=10**9, seed=SEED)
    timer.join()
    assert time.monotonic() - start < 10


def test_bad_arguments_are_errors():
    with pytest.raises(gridlock.Error, match="kinds"):
        gridlock.fuzz(count=1, kinds=["cubic"])
    with pytest.raises(gridlock.Error, match="min_vars"):
        gridlock.fuzz(count=1, min_vars=7, max_vars=3)
    with pytest.raises(gridlock.Error, match="model"):
        gridlock.verify([], model="quantum")
