"""audit11: a second independent model (audit11_model.py, written from
MODEL.md and the docs only) against the command line, on its own random
generator (not `gridlock random`), plus a strict reader written from
docs/grid-format.md against `gridlock solve` on mutated files.
GRIDLOCK_TEST_SEED replays, GRIDLOCK_TEST_SCALE scales the counts.
"""
import os
import random
import subprocess
from fractions import Fraction

import audit11_compare as ac
import audit11_model as am
import audit11_reader as ar
from conftest import BINARY, SEED, SOURCE, scaled

CORNERS = SOURCE / "tests" / "data" / "model_corners"
# solve D, solve C, collide D, collide C (hand-derived in notes/audit9.md)
CORNER_ANSWERS = {
    "A13-ring-uncoupled.grid": (False, True, True, True),
    "B01-grow-lockstep-push.grid": (True, True, True, True),
    "B04-vertical-case4.grid": (True, True, True, True),
    "C01-expand-contract-lockstep.grid": (True, True, True, True),
}
NO_FREE = ("A05", "A06", "A10", "A14", "A16", "A18", "C03", "C04")


def answers(inst):
    tab = am.discrete_tables(inst)
    return (am.discrete_free(inst, tab)[0], am.continuous_free(inst)[0],
            am.discrete_colliding(inst, tab), am.continuous_colliding(inst))


def test_model_gives_the_hand_derived_corner_answers():
    for path in sorted(CORNERS.glob("*.grid")):
        got = answers(am.parse_grid(path.read_text()))
        if path.name in CORNER_ANSWERS:
            want = CORNER_ANSWERS[path.name]
        elif path.name[:3] in NO_FREE:
            want = (False, False, True, True)
        else:
            want = (True, True, False, False)
        assert got == want, path.name


def test_model_worked_case_moments():
    inst = am.parse_grid((SOURCE / "examples" / "instances" /
                          "model-case5-push-into-growth.grid").read_text())
    half = Fraction(1, 2)
    assert not am.check_times(inst, [0, half])
    assert not am.check_times(inst, [0, 0])
    inst = am.parse_grid((SOURCE / "examples" / "instances" /
                          "model-case4-contract-then-grow.grid").read_text())
    assert am.check_times(inst, [Fraction(0), Fraction(0)])
    assert not am.check_times(inst, [half, Fraction(0)])


def test_cli_agrees_with_the_model_on_random_instances(tmp_path):
    stats = {k + s: 0 for k in ("solve-d", "solve-c", "collide-d", "collide-c")
             for s in (" exact", " unproved")}
    stats["witness"] = stats["certify"] = 0
    bad = []
    for i in range(scaled(40)):
        rng = random.Random(SEED * 1000003 + i)
        text = ac.random_grid(rng, nmax=7, opmax=5, kmin=1, kmax=3)
        path = str(tmp_path / ("r%d.grid" % i))
        with open(path, "w") as f:
            f.write(text)
        problems = ac.compare(BINARY, path, am.parse_grid(text), stats, bad)
        assert not problems, "seed %d instance %d: %s" % (SEED, i, problems)


def test_reader_agrees_with_the_format_doc(tmp_path):
    for i in range(scaled(150)):
        rng = random.Random(SEED * 999983 + i)
        text = ac.random_grid(rng, nmax=5, opmax=3)
        for _ in range(rng.randint(1, 2)):
            text = ar.mutate(rng, text)
        path = str(tmp_path / ("m%d.grid" % i))
        with open(path, "w") as f:
            f.write(text)
        p = subprocess.run([BINARY, "solve", path], capture_output=True, text=True, timeout=60)
        mine = ar.valid(text)
        accepted = p.returncode in (0, 10, 20)
        assert accepted == (mine is None), "seed %d file %d: %s %s\n%s" % (
            SEED, i, p.stderr, mine, text)
        if not accepted:
            m = ar.ERR.match(p.stderr.strip())
            assert p.returncode == 1 and m and m.group(1) == path, p.stderr
    assert os.path.exists(BINARY)
