"""The command line against an independent model of the semantics
(conformance_model.py, written from the paper and docs/model.md only) on
seeded random instances of every family of `gridlock random`
(docs/model.md, "An independent model"). GRIDLOCK_TEST_SEED replays,
GRIDLOCK_TEST_SCALE scales the number of instances (6 per family and mix).
"""
from fractions import Fraction

import pytest

import conformance_compare as cc
import conformance_model as cm
from conftest import BINARY, SEED, SOURCE, scaled

CASES = SOURCE / "examples" / "instances"


def model_of(name):
    return cm.Model(cm.parse_grid((CASES / name).read_text()))


def test_model_reproduces_the_worked_cases():
    """docs/model.md's worked cases, from the model alone (no CLI)."""
    m = model_of("model-case1-two-growths.grid")
    assert cm.brute_discrete(m)[0] is None and cm.continuous_colliding(m) is not None
    assert cm.simulate(m, {"g1": 0, "g2": 0}).time == Fraction(1, 2)
    assert cm.continuous_free_two(m) is None
    m = model_of("model-case2-order-gadget.grid")
    assert cm.simulate(m, cm.order_starts(["a", "b"])) is None
    assert cm.simulate(m, cm.order_starts(["b", "a"])).time == 0
    assert cm.simulate(m, {"a": 0, "b": 0}) is None
    m = model_of("model-case3-block.grid")
    assert cm.brute_discrete(m) == (["Q"], None) and cm.continuous_colliding(m) is None
    m = model_of("model-case4-contract-then-grow.grid")
    assert cm.simulate(m, cm.order_starts(["c", "g"])) is None
    assert cm.simulate(m, cm.order_starts(["g", "c"])).time == 0
    assert cm.simulate(m, {"c": 0, "g": 0}) is None
    assert cm.simulate(m, {"g": 0, "c": Fraction(1, 2)}).time == 0
    m = model_of("model-case5-push-into-growth.grid")
    assert cm.simulate(m, {"e": 0, "g": 0}).time == Fraction(1, 2)
    assert cm.simulate(m, {"e": 0, "g": Fraction(1, 2)}).time == Fraction(3, 4)
    assert cm.simulate(m, {"g": 0, "e": Fraction(1, 2)}).time == Fraction(3, 4)
    assert cm.brute_discrete(m)[0] is None and cm.continuous_free_two(m) is None
    # both new nodes end in one cell (cases 1 and 5): every schedule collides
    for name, ends_in_collision in (("model-case1-two-growths.grid", True), ("model-case2-order-gadget.grid", False),
                                     ("model-case4-contract-then-grow.grid", False),
                                     ("model-case5-push-into-growth.grid", True)):
        assert cm.final_collides(model_of(name)) == ends_in_collision, name


def test_model_sees_a_broken_cycle():
    """The 2x2 block, uncoupled: cycle collision at 0 in both orders."""
    text = (CASES / "model-case3-block.grid").read_text().replace("p grid 4 4 2 1", "p grid 4 4 2 0")
    m = cm.Model(cm.parse_grid("\n".join(x for x in text.splitlines() if not x.startswith("q"))))
    for order in (["a", "b"], ["b", "a"]):
        c = cm.simulate(m, cm.order_starts(order))
        assert c.kind == "cycle" and c.time == 0
    assert cm.simulate(m, {"a": 0, "b": 0}) is None
    assert cm.continuous_free_two(m) == {"a": 0, "b": 0}


@pytest.mark.parametrize("config", cc.CONFIGS, ids=["-".join(map(str, c)).replace(",", "") for c in cc.CONFIGS])
def test_cli_agrees_with_the_model(config):
    i = cc.CONFIGS.index(config)
    rep = cc.run_all(BINARY, scaled(6), SEED + i, configs=[config])
    print("\n".join(f"{v:6d}  {k}" for k, v in sorted(rep.counts.items())))
    assert not rep.disagreements, f"seed {SEED} (GRIDLOCK_TEST_SEED replays):\n" + "\n\n".join(rep.disagreements)


def test_two_coupling_offsets_match_the_simulation(tmp_path):
    """The model's exact offset intervals (continuous_free_two) against its
    own simulation at sampled offsets: the two halves of the model agree."""
    import random

    rng = random.Random(SEED)
    run = cc.Runner(BINARY, str(tmp_path))
    for family in ("tree", "cycles", "dense"):
        for path in run.make(family, 2, 3, "expand,contract,grow", False, SEED, scaled(3)):
            m = cm.Model(cm.parse_grid(open(path).read()))
            if len(m.couplings) != 2:
                continue
            bad = cm._bad_intervals(m)
            qa, qb = m.couplings
            for d in [Fraction(rng.randint(-24, 24), 24) for _ in range(6)] + [Fraction(0)]:
                sim = cm.simulate(m, {qa: 0, qb: d}) is not None
                assert sim == any(cm._inside(d, iv) for iv in bad), f"{path} offset {d}"
            free = cm.continuous_free_two(m)
            assert free is None or cm.simulate(m, free) is None


def test_cli_agrees_with_the_model_on_the_bundled_instances():
    """examples/instances with at most 6 couplings (the brute force tries
    every order): worked cases, gadgets, continuous examples."""
    small = [p for p in sorted(CASES.glob("*.grid"))
             if len(cm.parse_grid(p.read_text()).couplings) <= 6]
    assert len(small) >= 10
    rep = cc.run_files(BINARY, [str(p) for p in small], SEED)
    print("\n".join(f"{v:6d}  {k}" for k, v in sorted(rep.counts.items())))
    assert not rep.disagreements, "\n\n".join(rep.disagreements)
