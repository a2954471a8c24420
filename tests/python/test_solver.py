"""solve, collide and gaps: every bundled instance and seeded random
instances against the command line's --json, witnesses replayed by the
simulator, engines against each other, errors and Ctrl-C."""
import os
import signal
import threading
import time
from fractions import Fraction

import pytest

import gridlock
from conftest import INSTANCES, SEED, SOURCE, cli, cli_json, scaled


def cli_times(witness):
    """{name: Fraction} from the CLI's witness lines 'NAME TIME'."""
    return {w.split()[0]: Fraction(w.split()[1]) for w in witness}


def check_solve(inst, path, model="discrete", engine="auto"):
    args = ["solve", path, "--model", model, "--timeout", "60"]
    if engine != "auto":
        args += ["--engine", engine]
    want = cli_json(*args)
    got = gridlock.solve(inst, model=model, engine=engine, timeout=60)
    assert got.status == want["status"] and got.engine == want["engine"] and got.model == want["model"]
    for key in ("states", "refuted", "decisions", "constraints"):
        assert got.stats[key] == want["stats"][key], key
    lone = want.get("lone_collider")
    assert (got.lone_collider, got.lone_pair) == ((lone["coupling"], lone["pair"]) if lone else (None, None))
    if got.status != "YES":
        assert got.order is None and got.times is None
        return got
    if model == "discrete":
        assert got.order == want["witness"]
        assert gridlock.simulate(inst, order=got.order) is None
    else:
        assert got.times == cli_times(want["witness"])
        assert all(isinstance(t, Fraction) for t in got.times.values())
        assert gridlock.simulate(inst, times=got.times) is None
    return got


@pytest.mark.parametrize("model", ["discrete", "continuous"])
def test_solve_examples_equal_cli(instance_path, model):
    check_solve(gridlock.Instance.read(str(instance_path)), instance_path, model)


@pytest.mark.parametrize("model", ["discrete", "continuous"])
def test_lone_collider_equals_cli_and_is_certified(tmp_path, model):
    """A random shape of 300 couplings is NO because one coupling alone
    moves a pair into a collision: named like the CLI, and certified."""
    path = str(tmp_path / "tree.grid")
    cli("random", "--family", "tree", "--couplings", "300", "--seed", "1", "-o", path, expect=(0,))
    inst = gridlock.Instance.read(path)
    got = check_solve(inst, path, model)
    assert got.status == "NO" and got.lone_collider in inst.couplings
    cert = gridlock.solve(inst, model=model, certificate=True)
    assert cert.lone_collider == got.lone_collider
    assert gridlock.certify(inst, cert.certificate, model=model).proved


def check_collide(inst, path, model):
    want = cli_json("collide", path, "--model", model)
    got = gridlock.collide(inst, model=model)
    assert got.status == want["status"] and got.algorithm == want["algorithm"]
    if got.status == "YES":
        c = got.collision
        assert c.kind == want["collision"]["kind"] and c.time == Fraction(want["collision"]["time"])
        if model == "discrete":
            assert got.order == want["witness"]
            assert gridlock.simulate(inst, order=got.order) == c
        else:
            assert got.times == cli_times(want["witness"])
            assert gridlock.simulate(inst, times=got.times) == c
    return got


@pytest.mark.parametrize("model", ["discrete", "continuous"])
def test_collide_examples_equal_cli(instance_path, model):
    check_collide(gridlock.Instance.read(str(instance_path)), instance_path, model)


NAMED_YES = {  # one coupling: (the .grid text, the algorithm, checked_at, the first collision's time)
    "one-axis": ("p grid 5 4 2 1\nn 0 0\nn 2 0\nn 0 1\nn 1 1\nn 2 1\ne 0 0 0 1\ne 0 1 1 1\n"
                 "e 1 1 2 1\ne 2 1 2 0\no g1 grow 0 0 +x\no g2 grow 2 0 -x\nq G g1 g2\n",
                 "single-coupling-one-axis", Fraction(3, 4), Fraction(1, 2)),
    "fixed-axis": ("p grid 5 4 2 1\nn -1 0\nn 0 0\nn 1 0\nn 1 1\nn 0 1\ne -1 0 0 0\ne 0 0 1 0\ne 1 0 1 1\n"
                   "e 1 1 0 1\no x expand -1 0 +x\no c contract 1 0 +y\nq Q x c\n",
                   "single-coupling-fixed-axis", Fraction(1, 2), Fraction(0)),
    "separated": ("p grid 15 14 5 1\nn 0 0\nn 0 1\nn 1 1\nn 0 2\nn -1 2\nn -1 0\nn -1 1\nn -2 2\nn 0 3\n"
                  "n -1 -1\nn 2 1\nn -2 -1\nn -1 3\nn -2 3\nn -2 -2\ne 0 0 0 1\ne 0 1 1 1\ne 0 1 0 2\n"
                  "e 0 2 -1 2\ne 0 0 -1 0\ne 0 1 -1 1\ne -1 2 -2 2\ne 0 2 0 3\ne -1 0 -1 -1\ne 1 1 2 1\n"
                  "e -1 -1 -2 -1\ne 0 3 -1 3\ne -1 3 -2 3\ne -2 -1 -2 -2\no o1 expand -2 -1 +x\n"
                  "o o2 contract 0 1 -y\no o3 expand -1 2 +x\no o4 grow 2 1 -y\no o5 contract -1 3 +x\n"
                  "q Q1 o3 o4 o5 o1 o2\n",  # gridlock random --couplings 1 --max-coupling 8 --seed 20
                  "single-coupling-separated", Fraction(1, 2), Fraction(0)),
}


def stalactite_comb_hit(L):
    """bench/bench_families.hpp's stalactite_comb(L, false, true), as
    .grid text: teeth carried right under static stalactites, the middle
    one reaching into their path (YES at floor(L / 2) / k)."""
    m, k = L, 2 * (L + L) + 2
    left, right = -2 * k - 1, L + k + 1
    nodes, edges, ops = [], [], []
    nodes += [(x, 0) for x in range(-2 * k, L)]
    edges += [((x, 0), (x + 1, 0)) for x in range(-2 * k, L - 1)]
    ops += [(f"s{i}", -2 * k + 2 * i, 0, "+x") for i in range(k)]
    for x in range(L):
        for y in range(1, 5):
            nodes.append((x, y))
            edges.append(((x, y - 1), (x, y)))
        if x % 2 == 0:
            ops += [(f"t{x}_{y}", x, y, "+y") for y in (1, 3)]
    nodes += [(left, y) for y in range(9)]
    edges += [((left, y), (left, y + 1)) for y in range(8)] + [((left, 0), (left + 1, 0))]
    for x in range(left + 1, right + 1):
        nodes.append((x, 8))
        edges.append(((x - 1, 8), (x, 8)))
    for x in range(L, L + m):
        nodes += [(x, 7), (x, 6)]
        edges += [((x, 8), (x, 7)), ((x, 7), (x, 6))]
    x = L + m // 2
    nodes += [(x, 5), (x, 4)]
    edges += [((x, 6), (x, 5)), ((x, 5), (x, 4))]
    lines = [f"p grid {len(nodes)} {len(edges)} {len(ops)} 1"]
    lines += [f"n {x} {y}" for x, y in nodes]
    lines += [f"e {a[0]} {a[1]} {b[0]} {b[1]}" for a, b in edges]
    lines += [f"o {name} expand {x} {y} {d}" for name, x, y, d in ops]
    lines.append("q all " + " ".join(name for name, *_ in ops))
    return "\n".join(lines) + "\n"


# No cut over (0, 1), cut over its halves (first at 1/14: floor(3 / 2) / 14).
NAMED_YES["time-slabs"] = (stalactite_comb_hit(3), "single-coupling-time-slabs", Fraction(1, 7), Fraction(1, 14))


@pytest.mark.parametrize("model", ["discrete", "continuous"])
@pytest.mark.parametrize("case", sorted(NAMED_YES))
def test_collide_one_coupling_yes_checked_at_one_moment(tmp_path, model, case):
    """One coupling (one axis: the row groups; both axes, x keeping its
    order: one sweep along x, bisecting for the first moment; groups cut
    apart, each keeping an order: one sweep each; the same over time
    slabs): the
    first collision comes from the proof and is confirmed at one moment;
    it is the simulator's, and equals the CLI."""
    text, algorithm, checked_at, time = NAMED_YES[case]
    path = tmp_path / "g.grid"
    path.write_text(text)
    inst = gridlock.Instance.read(str(path))
    check_collide(inst, str(path), model)
    got = gridlock.collide(inst, model=model)
    assert got.algorithm == algorithm
    assert got.checked_at == checked_at and got.collision.time == time
    assert cli_json("collide", str(path), "--model", model)["checked_at"] == str(checked_at)
    assert gridlock.collide(gridlock.Instance.read(str(SOURCE / "examples" / "instances" / "tiny-sat.grid"))).checked_at is None


def test_gaps_examples_equal_cli(instance_path):
    inst = gridlock.Instance.read(str(instance_path))
    if not inst.horizontal_only:
        with pytest.raises(gridlock.Error, match="horizontal-only"):
            gridlock.gaps(inst)
        return
    want = cli_json("gaps", instance_path)
    got = gridlock.gaps(inst)
    assert got.status == want["status"]
    assert (got.gaps_checked, got.cycles_checked) == (want["gaps_checked"], want["cycles_checked"])
    if want.get("gap"):
        assert got.gap["final_size"] == want["gap"]["final_size"] and got.gap["left"] == want["gap"]["left"]
    # the continuous solver decides the same question
    assert gridlock.solve(inst, model="continuous").status == got.status


def test_random_instances_equal_cli(tmp_path):
    """Seeded random instances (cycles, couplings, growths, contractions)."""
    path = tmp_path / "r.grid"
    for i in range(scaled(25)):
        seed = SEED * 1000 + i
        inst = gridlock.random_instance(nodes=10, ops=4, max_coupling=2, extra_edge_percent=15, seed=seed)
        inst.write(str(path))
        try:
            check_solve(inst, path, "discrete")
            check_collide(inst, path, "discrete")
            check_collide(inst, path, "continuous")
        except AssertionError as e:
            raise AssertionError(f"random instance seed {seed}: {e}") from e


def test_engines_agree_on_horizontal_instances(tmp_path):
    path = tmp_path / "h.grid"
    for i in range(scaled(25)):
        seed = SEED * 2000 + i
        inst = gridlock.random_instance(nodes=14, ops=7, max_coupling=3, horizontal_only=True,
                                        allow_grow=True, seed=seed)
        inst.write(str(path))
        answers = {e: check_solve(inst, path, "discrete", e).status
                   for e in ("states", "precedence", "sat", "pairs")}
        assert len(set(answers.values())) == 1, f"seed {seed}: {answers}"
        assert gridlock.gaps(inst).status == check_solve(inst, path, "continuous").status, f"seed {seed}"


def test_limits_give_unknown():
    f = gridlock.random_ksat(n=60, m=256, seed=3)
    inst = gridlock.compile(f).instance
    r = gridlock.solve(inst, engine="states", max_states=50)
    assert r.status == "UNKNOWN" and r.order is None


def test_bad_arguments_are_errors():
    inst = gridlock.Instance.read(str(INSTANCES[0]))
    with pytest.raises(gridlock.Error, match="model"):
        gridlock.solve(inst, model="quantum")
    with pytest.raises(gridlock.Error, match="engine"):
        gridlock.solve(inst, engine="magic")
    with pytest.raises(gridlock.Error, match="timeout"):
        gridlock.solve(inst, timeout=-1)
    with pytest.raises(gridlock.Error, match="method"):
        gridlock.collide(inst, method="guess")


def interrupt_after(seconds):
    """Sends this process SIGINT (Ctrl-C) after `seconds`, from a timer thread."""
    t = threading.Timer(seconds, os.kill, (os.getpid(), signal.SIGINT))
    t.start()
    return t


def test_ctrl_c_interrupts_a_long_solve():
    # The chronological state search on a compiled 60-variable formula runs
    # for minutes; Ctrl-C must end it within a second or two.
    f = gridlock.random_ksat(n=60, m=256, seed=3)
    inst = gridlock.compile(f).instance
    timer = interrupt_after(0.5)
    start = time.monotonic()
    with pytest.raises(KeyboardInterrupt):
        gridlock.solve(inst, engine="states", timeout=120)
    timer.join()
    assert time.monotonic() - start < 10
    # the stop request is cleared: the next call runs normally
    small = gridlock.Instance.read(str(INSTANCES[0]))
    assert gridlock.solve(small).status in ("YES", "NO")


def test_solve_releases_the_gil():
    f = gridlock.random_ksat(n=60, m=256, seed=3)
    inst = gridlock.compile(f).instance
    ticks = []
    stop = threading.Event()

    def ticker():
        while not stop.is_set():
            ticks.append(time.monotonic())
            time.sleep(0.01)

    t = threading.Thread(target=ticker)
    t.start()
    gridlock.solve(inst, engine="states", timeout=1)
    stop.set()
    t.join()
    assert len(ticks) > 20  # the other thread ran while the solver did


def test_no_certificates_are_checked_and_mutations_refused(tmp_path):
    """Every NO of seeded random horizontal instances carries a certificate
    that certify() and `gridlock certify` accept; a certificate for another
    instance, or with its proof cut short, is refused."""
    path, cert = tmp_path / "h.grid", tmp_path / "h.nocert"
    nos = 0
    for i in range(scaled(40)):
        seed = SEED * 3000 + i
        inst = gridlock.random_instance(nodes=14, ops=7, max_coupling=3, horizontal_only=True,
                                        allow_grow=True, seed=seed)
        r = gridlock.solve(inst, certificate=True)
        if r.status != "NO":
            assert r.certificate is None, f"seed {seed}"
            continue
        nos += 1
        assert r.certificate, f"seed {seed}: {r.certificate_note}"
        assert gridlock.certify(inst, r.certificate), f"seed {seed}"
        inst.write(str(path))
        cert.write_text(r.certificate)
        code, out, _ = cli("certify", path, cert)
        assert code == 20 and "c certificate checked" in out, f"seed {seed}"
        if "\ngaps\n" in r.certificate:  # a lemma log: the final empty clause dropped
            bad = gridlock.certify(inst, r.certificate[: -len("l\n")])
            assert not bad and bad.reason, f"seed {seed}"
    assert nos > 0


def test_continuous_engines_agree():
    for path in INSTANCES:
        inst = gridlock.Instance.read(str(path))
        got = {e: gridlock.solve(inst, model="continuous", engine=e, timeout=60).status for e in ("dl", "sat", "z3")}
        assert len(set(got.values())) == 1, f"{path.name}: {got}"
    with pytest.raises(gridlock.Error, match="engine"):
        gridlock.solve(gridlock.Instance.read(str(INSTANCES[0])), model="continuous", engine="states")


@pytest.mark.parametrize("model", ["discrete", "continuous"])
def test_collide_no_certificates_equal_cli_and_are_checked(tmp_path, model):
    """Every NO of collide(certificate=True) on seeded random instances
    carries the same certificate `gridlock collide --certificate` writes,
    and certify() accepts it in both models; another instance's certificate
    and a YES never get one."""
    path, cert = tmp_path / "c.grid", tmp_path / "c.cert"
    nos = 0
    for i in range(scaled(40)):
        seed = SEED * 5000 + i
        inst = gridlock.random_instance(nodes=12, ops=6, max_coupling=3, allow_grow=True, seed=seed)
        r = gridlock.collide(inst, model=model, certificate=True)
        if r.status == "YES":
            assert r.certificate is None and r.certificate_note is None, f"seed {seed}"
            continue
        if model == "continuous":
            assert r.certificate, f"seed {seed}: {r.certificate_note}"
        if not r.certificate:
            assert r.certificate_note, f"seed {seed}"
            continue
        nos += 1
        for m in ("discrete", "continuous"):
            assert gridlock.certify(inst, r.certificate, model=m), f"seed {seed} {m}"
        inst.write(str(path))
        cert.unlink(missing_ok=True)
        code, _, _ = cli("collide", path, "--model", model, "--certificate", cert)
        assert code == 20 and cert.read_text() == r.certificate, f"seed {seed}"
        code, out, _ = cli("certify", path, cert)
        assert code == 20 and "c certificate checked" in out, f"seed {seed}"
        other = gridlock.random_instance(nodes=12, ops=6, max_coupling=3, seed=seed + 1)
        if gridlock.collide(other, model="continuous").status == "YES":
            bad = gridlock.certify(other, r.certificate, model=model)
            assert not bad and bad.reason, f"seed {seed}"
    assert nos > 0
