"""Instances, the simulator and the animation page: round trips on every
bundled instance, answers equal to `gridlock check --json`, errors."""
from fractions import Fraction

import pytest

import gridlock
from conftest import INSTANCES, SEED, cli, cli_json, scaled


def test_round_trip(instance_path, tmp_path):
    inst = gridlock.Instance.read(str(instance_path))
    again = gridlock.Instance.parse(inst.to_grid(), name="copy.grid")
    assert again == inst and again.to_grid() == inst.to_grid()
    inst.write(str(tmp_path / "out.grid"))
    assert gridlock.Instance.read(str(tmp_path / "out.grid")) == inst
    assert len(inst) == len(inst.nodes) > 0
    assert len(inst.operations) == sum(len(ops) for ops in inst.couplings.values())
    assert {op["coupling"] for op in inst.operations} == set(inst.couplings)
    assert inst.anchor in inst.nodes
    assert repr(inst).startswith("<gridlock.Instance: ")


def test_pictures(instance_path):
    inst = gridlock.Instance.read(str(instance_path))
    svg = inst._repr_svg_()
    assert "<svg" in svg and svg.rstrip().endswith("</svg>")
    assert inst.to_svg(title="hello").count("hello") >= 1
    _, ascii_text, _ = cli("render", instance_path, "--ascii", expect=(0,))
    assert inst.to_ascii().strip() in ascii_text
    assert "tikzpicture" in inst.to_tikz()


def check_cli(path, order=None, times_file=None):
    if order is not None:
        return cli_json("check", path, "--order", " ".join(order))
    return cli_json("check", path, "--times", times_file)


def same_collision(mine, theirs):
    """The module's Collision against the CLI's JSON record of it."""
    if theirs is None:
        return mine is None
    assert mine is not None
    assert mine.kind == theirs["kind"]
    assert mine.time == Fraction(theirs["time"])
    assert mine.moving == theirs.get("moving", [])
    if mine.kind == "node":
        assert list(mine.regions) == theirs["regions"]
    else:
        assert mine.cycle == theirs["cycle"]
    return True


def test_simulate_equals_cli(instance_path, tmp_path):
    inst = gridlock.Instance.read(str(instance_path))
    names = list(inst.couplings)
    for order in (names, names[::-1]):
        got = gridlock.simulate(inst, order=order)
        want = check_cli(instance_path, order=order)
        assert same_collision(got, want.get("collision"))
        assert (got is None) == (want["status"] == "YES")
    times = {q: Fraction(i, 2) for i, q in enumerate(names)}
    # "v NAME TIME": a coupling may be named "c", which starts a comment line
    (tmp_path / "t.txt").write_text("".join(f"v {q} {t}\n" for q, t in times.items()))
    got = gridlock.simulate(inst, times=times)
    assert same_collision(got, check_cli(instance_path, times_file=tmp_path / "t.txt").get("collision"))


def test_simulate_random_equals_cli(tmp_path):
    path = tmp_path / "r.grid"
    for i in range(scaled(40)):
        seed = SEED + i
        inst = gridlock.random_instance(nodes=12, ops=5, max_coupling=2, extra_edge_percent=20, seed=seed)
        inst.write(str(path))
        order = sorted(inst.couplings)
        got = gridlock.simulate(inst, order=order)
        assert same_collision(got, check_cli(path, order=order).get("collision")), f"seed {seed}"


def test_random_instance_is_seeded():
    a = gridlock.random_instance(nodes=20, ops=6, max_coupling=3, seed=5)
    assert a == gridlock.random_instance(nodes=20, ops=6, max_coupling=3, seed=5)
    assert a != gridlock.random_instance(nodes=20, ops=6, max_coupling=3, seed=6)
    assert gridlock.random_instance(nodes=15, horizontal_only=True, seed=1).horizontal_only


def test_exact_times():
    inst = gridlock.Instance.read(str(INSTANCES[0]))
    names = list(inst.couplings)
    as_str = gridlock.simulate(inst, times={q: "1/3" for q in names})
    as_fraction = gridlock.simulate(inst, times={q: Fraction(1, 3) for q in names})
    assert as_str == as_fraction
    with pytest.raises(gridlock.Error, match="exact"):
        gridlock.simulate(inst, times={q: 0.5 for q in names})


def test_animate(instance_path):
    inst = gridlock.Instance.read(str(instance_path))
    page = gridlock.animate(inst, order=list(inst.couplings), title="t")
    assert page.lstrip().lower().startswith("<!doctype html") and "</html>" in page


def test_bad_grid_is_an_error_with_file_and_line(tmp_path):
    bad = tmp_path / "bad.grid"
    bad.write_text("p grid 1 0 0 0\nn 0 0\nn 0 0\n")
    code, _, err = cli("render", bad)
    assert code == 1
    with pytest.raises(gridlock.Error) as e:
        gridlock.Instance.read(str(bad))
    assert err.strip() == "gridlock: error: " + str(e.value)
    assert e.value.file == str(bad) and e.value.line == 3 and e.value.message
    with pytest.raises(gridlock.Error, match="no-such.grid"):
        gridlock.Instance.read(str(tmp_path / "no-such.grid"))
    with pytest.raises(gridlock.Error, match=r"^text.grid:1: "):
        gridlock.Instance.parse("hello\n", name="text.grid")


def test_bad_schedules_are_errors():
    inst = gridlock.Instance.read(str(INSTANCES[0]))
    names = list(inst.couplings)
    with pytest.raises(gridlock.Error):
        gridlock.simulate(inst)  # neither order nor times
    with pytest.raises(gridlock.Error):
        gridlock.simulate(inst, order=names[:-1])  # a coupling missing
    with pytest.raises(gridlock.Error, match="nope"):
        gridlock.simulate(inst, order=names + ["nope"])
    with pytest.raises(gridlock.Error):
        gridlock.simulate(inst, order=" ".join(names))  # one string, not a list
    with pytest.raises(gridlock.Error, match="no start time"):
        gridlock.simulate(inst, times={})
    with pytest.raises(gridlock.Error):
        gridlock.random_instance(nodes=0)
