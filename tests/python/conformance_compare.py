"""Compares the command line with the independent model (conformance_model.py)
on seeded random instances from `gridlock random`.

    /usr/bin/python3 tests/python/conformance_compare.py [--per-config N] [--seed S]

Per instance: `gridlock check` on discrete orders and continuous start times
(verdict, moment, kind, pair, cycle, moving couplings) against simulate();
`gridlock solve` (discrete) and `gridlock collide` (both models) against the
brute force; `gridlock solve --model continuous` and `gridlock gaps` against
what the model can prove; every YES witness the command line prints run
through simulate(). Every disagreement is reported with the seed, the
command and the instance text.
"""
import argparse
import collections
import json
import os
import random
import subprocess
import sys
import tempfile
import time
from fractions import Fraction

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import conformance_model as cm  # noqa: E402

# (family, couplings, max coupling, kinds, horizontal)
CONFIGS = [
    ("tree", 3, 2, "expand,contract,grow", False),
    ("tree", 4, 1, "expand,contract,grow", False),
    ("cycles", 3, 2, "expand,contract,grow", False),
    ("cycles", 2, 3, "expand", False),
    ("dense", 3, 2, "expand,contract,grow", False),
    ("sparse", 3, 2, "expand,contract,grow", False),
    ("path", 4, 2, "expand,contract,grow", False),
    ("tree", 3, 2, "expand,contract,grow", True),
    ("cycles", 3, 2, "expand,grow", True),
    ("tree", 4, 2, "contract,grow", False),
    ("tree", 2, 3, "expand,contract,grow", False),
    ("dense", 2, 2, "expand,contract,grow", False),
    ("tree", 3, 4, "expand,contract", False),
    ("cycles", 3, 3, "expand,contract,grow", False),
    ("tree", 4, 2, "expand,contract,grow", False, "planted"),
]


class Runner:
    def __init__(self, binary, workdir):
        self.binary = binary
        self.workdir = workdir
        self.calls = 0

    def json(self, *args):
        self.calls += 1
        p = subprocess.run([self.binary, *map(str, args), "--json"], capture_output=True, text=True, timeout=120)
        if p.returncode not in (0, 10, 20):
            raise RuntimeError(f"gridlock {' '.join(map(str, args))}: exit {p.returncode}: {p.stderr}")
        return json.loads(p.stdout)

    def make(self, family, k, m, kinds, horizontal, seed, count, planted=False):
        """Writes `count` (at least 2: one would be a file, not a folder)
        instances, seeds seed..seed+count-1; returns their paths."""
        count = max(2, count)
        folder = os.path.join(self.workdir,
                              f"{family}-{k}-{m}-{kinds.replace(',', '')}-{int(horizontal)}-{int(planted)}-{seed}")
        args = [self.binary, "random", "--family", family, "--couplings", k, "--max-coupling", m, "--kinds", kinds,
                "--seed", seed, "--count", count, "-o", folder]
        if horizontal:
            args.append("--horizontal")
        if planted:
            args.append("--planted")
        self.calls += 1
        subprocess.run(list(map(str, args)), check=True, capture_output=True)
        return sorted(os.path.join(folder, f) for f in os.listdir(folder) if f.endswith(".grid"))


def _seed_of(path):
    name = os.path.basename(path)
    return name.split("-s")[-1].split(".")[0] if "-s" in name else "?"


class Report:
    def __init__(self):
        self.counts = collections.Counter()
        self.disagreements = []

    def count(self, key):
        self.counts[key] += 1

    def disagree(self, path, what, detail):
        text = open(path).read()
        self.disagreements.append(f"DISAGREEMENT [{what}] seed {_seed_of(path)} file {path}\n{detail}\n{text}")


def _cycle_ok(model, cycle_cells, t, starts):
    """The CLI's cycle is a closed walk of edges whose mismatch is non-zero
    just after t."""
    cells = [tuple(int(v) for v in c.strip("()").split(",")) for c in cycle_cells]
    edges = {frozenset(e) for e in model.inst.edges}
    later = sorted({s for s in starts.values()} | {s + 1 for s in starts.values()} | {t + 1})
    t1 = min(x for x in later if x > t)
    p = cm._progress(starts, (t + t1) / 2)
    total = [Fraction(0), Fraction(0)]
    for a, b in zip(cells, cells[1:] + cells[:1]):
        if frozenset((a, b)) not in edges:
            return False
        op = model.edge_op.get(frozenset((a, b)))
        if op:
            sign, q = op
            total[0] += sign * p[q] * (b[0] - a[0])
            total[1] += sign * p[q] * (b[1] - a[1])
    return total != [0, 0]


def _translate(text, shift):
    """The instance moved by shift: every cell of n, e, o and a lines."""
    out = []
    for line in text.splitlines():
        t = line.split()
        if t and t[0] in ("n", "e", "a"):
            nums = [int(x) for x in t[1:]]
            t = [t[0]] + [str(v + shift[j % 2]) for j, v in enumerate(nums)]
        elif t and t[0] == "o":
            t = t[:3] + [str(int(t[3]) + shift[0]), str(int(t[4]) + shift[1])] + t[5:]
        out.append(" ".join(t) if t and t[0] in ("n", "e", "o", "a") else line)
    return "\n".join(out) + "\n"


def _name_back(name, shift):
    if name.startswith("node (") and shift != (0, 0):
        x, y = name[len("node ("):-1].split(",")
        return f"node ({int(x) - shift[0]},{int(y) - shift[1]})"
    return name


def compare_check(run, rep, variant, model, label, args, starts):
    path, shift = variant
    got = run.json("check", path, *args)
    mine = cm.simulate(model, starts)
    rep.count(f"check {label}")
    detail = f"gridlock check {path} {' '.join(args)}\nCLI: {json.dumps(got.get('collision'))} status {got['status']}\nmodel: {mine}"
    if (got["status"] == "YES") != (mine is None):
        rep.disagree(path, f"check {label} verdict", detail)
        return
    if mine is None:
        return
    c = got["collision"]
    if Fraction(c["time"]) != mine.time or c["kind"] != mine.kind or set(c["moving"]) != mine.moving:
        rep.disagree(path, f"check {label} moment/kind/moving", detail)
        return
    if mine.kind == "node" and frozenset(_name_back(r, shift) for r in c["regions"]) not in mine.pairs:
        rep.disagree(path, f"check {label} pair", detail)
    if mine.kind == "cycle" and not _cycle_ok(model, [_name_back("node " + x, shift)[5:] for x in c["cycle"]],
                                              mine.time, starts):
        rep.disagree(path, f"check {label} cycle", detail)


def rng_prefix(q, t):
    """A deterministic choice per line between the plain and the v form."""
    return (len(q) + len(str(t))) % 2 == 0


def _times_file(run, starts):
    fd, name = tempfile.mkstemp(suffix=".times", dir=run.workdir)
    with os.fdopen(fd, "w") as f:
        for q, t in starts.items():
            # plain "NAME TIME" lines, also for couplings named c, s or v:
            # the instance's names win over the comment and status words
            # (docs/grid-format.md, "Schedules"); also the CLI's own "v"
            # prefix every other line, so both readings are exercised
            prefix = "v " if rng_prefix(q, t) else ""
            f.write(f"{prefix}{q} {t}\n")
    return name


def compare_instance(run, rep, path, rng, solve_continuous=True, engines_too=True):
    inst = cm.parse_grid(open(path).read())
    model = cm.Model(inst)
    qs = model.couplings
    free, colliding = cm.brute_discrete(model)
    text = open(path).read()
    if "c planted: YES, collision-free order:" in text:
        hidden = text.split("c planted: YES, collision-free order:")[1].split("\n")[0].split()
        rep.count("planted order")
        bad = cm.simulate(model, cm.order_starts(hidden))
        if bad is not None or free is None:
            rep.disagree(path, "planted order", f"order {hidden} collides in the model: {bad}")
    # The same instance with a random anchor: the model has none (only
    # relative motion matters), so every answer must stay the same.
    anchored = path[:-5] + "-anchored.grid"
    with open(anchored, "w") as f:
        f.write(open(path).read() + "a %d %d\n" % rng.choice(inst.nodes))
    # ... and moved far from the origin (the model's answers only move with it)
    shift = (rng.randint(-10**9 + 100, 10**9 - 100), rng.randint(-10**9 + 100, 10**9 - 100))
    shifted = path[:-5] + "-shifted.grid"
    with open(shifted, "w") as f:
        f.write(_translate(open(path).read(), shift))
    variants = [(path, (0, 0)), (anchored, (0, 0)), (shifted, shift)]
    # check: discrete orders (the free one, the colliding one, random ones)
    orders = [o for o in (free, colliding) if o] + [rng.sample(qs, len(qs)) for _ in range(2)]
    for i, order in enumerate(orders):
        compare_check(run, rep, variants[i % 3], model, "discrete", ["--order", " ".join(order)],
                      cm.order_starts(order))
    # check: continuous start times on a coarse grid (coinciding and
    # overlapping runs likely), denominators 2, 3, 4 or 6, some negative
    for i in range(3):
        den = rng.choice((2, 3, 4, 6))
        starts = {q: Fraction(rng.randint(-den, 2 * den), den) for q in qs}
        compare_check(run, rep, variants[(i + 1) % 3], model, "continuous",
                      ["--times", _times_file(run, starts)], starts)
    horizontal = cm.is_horizontal(inst)
    singletons = all(len(ops) == 1 for ops in inst.couplings.values())
    # solve, discrete: exact brute force; every engine that takes the instance
    engines = [None] + (["states", "pairs"] if engines_too else [])
    if engines_too and horizontal:
        engines += ["precedence", "sat"]
    for engine in engines:
        compare_solve_discrete(run, rep, path, model, free, engine)
    # collide, both models: exact; every method that takes the instance
    methods = [None] + (["pairwise"] if engines_too else [])
    if engines_too and singletons:
        methods += ["tree", "tree-pairwise"]
    mine = cm.continuous_colliding(model)
    if mine is None and colliding is not None:
        rep.disagree(path, "model itself", "discrete collides but continuous cannot")
    if singletons and (mine is None) != (colliding is None):
        # the paper: without couplings the reachable regions of the two models agree
        rep.count("uncoupled: discrete and continuous Colliding differ in the model")
    for method in methods:
        compare_collide(run, rep, path, model, "discrete", colliding, method)
        compare_collide(run, rep, path, model, "continuous", mine, method)
    if not solve_continuous:
        return
    # solve, continuous: exact for two couplings (continuous_free_two) and,
    # by the paper's theorem, for horizontal-only instances; else one-sided.
    exact = len(qs) == 2
    if exact:
        found = cm.continuous_free_two(model)
    else:
        extra = [{q: Fraction(rng.randint(0, 2 * len(qs)), 2) for q in qs} for _ in range(4)]
        found = cm.free_schedule_candidates(model, free, extra)
    answers = set()
    for engine in [None] + (["dl", "sat", "z3"] if engines_too else []):
        answers.add(compare_solve_continuous(run, rep, path, model, found, exact, horizontal, engine))
    if horizontal:
        gaps = run.json("gaps", path)
        rep.count("gaps")
        at_once = cm.simulate(model, {q: 0 for q in qs})
        if (gaps["status"] == "YES") != (at_once is None):
            rep.disagree(path, "gaps", f"CLI gaps {gaps['status']}; model all at once: {at_once}")
        answers.add(gaps["status"])
    answers.discard("UNKNOWN")
    if len(answers) > 1:
        rep.disagree(path, "continuous engines disagree", f"answers {answers}")


def _engine(label, engine, flag="--engine"):
    return (f"{label} {engine}" if engine else label), ([flag, engine] if engine else [])


def _decide(run, rep, label, command, path, *args):
    """One decision command (--json, 20 s limit), counted under label (and
    its UNKNOWNs apart): the CLI's JSON answer."""
    got = run.json(command, path, *args, "--timeout", "20")
    rep.count(label)
    if got["status"] == "UNKNOWN":
        rep.count(f"{label} UNKNOWN")
    return got


def compare_solve_discrete(run, rep, path, model, free, engine):
    label, extra = _engine("solve discrete", engine)
    got = _decide(run, rep, label, "solve", path, *extra)
    if got["status"] == "UNKNOWN":
        return
    if (got["status"] == "YES") != (free is not None):
        rep.disagree(path, label, f"CLI {got['status']} {got['witness']}; brute force free order: {free}")
    elif got["status"] == "YES":
        rep.count(f"witness {label}")
        bad = cm.simulate(model, cm.order_starts(got["witness"]))
        if bad is not None:
            rep.disagree(path, f"{label} witness", f"order {got['witness']} collides in the model: {bad}")


def compare_collide(run, rep, path, model, time_model, mine, method):
    """mine: the model's exact answer (a colliding order / pair, or None)."""
    label, extra = _engine(f"collide {time_model}", method, "--method")
    got = _decide(run, rep, label, "collide", path, "--model", time_model, *extra)
    if got["status"] == "UNKNOWN":
        return
    if (got["status"] == "YES") != (mine is not None):
        rep.disagree(path, label, f"CLI {got['status']} {got['witness']}; model: {mine}")
    elif got["status"] == "YES":
        rep.count(f"witness {label}")
        if time_model == "discrete":
            starts = cm.order_starts(got["witness"])
        else:
            starts = {q: Fraction(t) for q, t in got["times"].items()}
        if cm.simulate(model, starts) is None:
            rep.disagree(path, f"{label} witness", f"schedule {got['witness']} is collision-free in the model")


def compare_solve_continuous(run, rep, path, model, found, exact, horizontal, engine):
    label, extra = _engine("solve continuous", engine)
    got = _decide(run, rep, label, "solve", path, "--model", "continuous", *extra)
    qs = model.couplings
    if got["status"] == "UNKNOWN":
        return got["status"]
    if got["status"] == "YES":
        rep.count(f"witness {label}")
        starts = {}
        for line in got["witness"]:
            q, t = line.split()
            starts[q] = Fraction(t)
        bad = cm.simulate(model, starts)
        if bad is not None:
            rep.disagree(path, f"{label} witness", f"times {got['witness']} collide in the model: {bad}")
        if horizontal and cm.simulate(model, {q: 0 for q in qs}) is not None:
            rep.disagree(path, f"{label} horizontal", "CLI YES but all at once collides (paper: then NO)")
        if exact and found is None:
            rep.disagree(path, label, f"CLI YES {got['witness']}; model (two couplings, exact): NO")
        if cm.final_collides(model):
            rep.disagree(path, label, f"CLI YES {got['witness']}; model: the final configuration collides")
    elif found is not None:
        rep.disagree(path, label, f"CLI NO but the model finds collision-free times {found}")
    elif exact or horizontal:
        rep.count(f"{label} NO proved by the model")
    elif cm.final_collides(model):
        rep.count(f"{label} NO proved by the model (final configuration)")
    else:
        rep.count(f"{label} NO not proved by the model")
    return got["status"]


def run_files(binary, paths, seed, engines_too=True):
    """compare_instance on given files (the bundled examples)."""
    rep = Report()
    rng = random.Random(seed)
    with tempfile.TemporaryDirectory(prefix="conformance-") as work:
        run = Runner(binary, work)
        for p in paths:
            copy = os.path.join(work, os.path.basename(p))
            with open(copy, "w") as f:
                f.write(open(p).read())
            rep.count("instances bundled")
            try:
                compare_instance(run, rep, copy, rng, True, engines_too)
            except RuntimeError as e:
                rep.disagree(copy, "CLI error", str(e))
        rep.calls = run.calls
    return rep


def run_all(binary, per_config, seed, configs=CONFIGS, solve_continuous=True, engines_too=True):
    rep = Report()
    rng = random.Random(seed)
    with tempfile.TemporaryDirectory(prefix="conformance-") as work:
        run = Runner(binary, work)
        for i, (family, k, m, kinds, horizontal, *planted) in enumerate(configs):
            base = seed * 1000 + i * 100000
            paths = run.make(family, k, m, kinds, horizontal, base, per_config, bool(planted))
            for p in paths:
                rep.count(f"instances {family} k{k} m{m} {kinds}{' horizontal' if horizontal else ''}"
                          f"{' planted' if planted else ''}")
                try:
                    compare_instance(run, rep, p, rng, solve_continuous, engines_too)
                except RuntimeError as e:  # an exit code other than 0, 10, 20
                    rep.disagree(p, "CLI error", str(e))
        rep.calls = run.calls
    return rep


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--binary", default=os.environ.get("GRIDLOCK_BINARY", os.path.join(
        os.path.dirname(__file__), "..", "..", "build", "gridlock")))
    ap.add_argument("--per-config", type=int, default=50)
    ap.add_argument("--seed", type=int, default=int(os.environ.get("GRIDLOCK_TEST_SEED", "2026")))
    ap.add_argument("--no-continuous-solve", action="store_true")
    a = ap.parse_args()
    t = time.time()
    rep = run_all(a.binary, a.per_config, a.seed, solve_continuous=not a.no_continuous_solve)
    for d in rep.disagreements:
        print(d)
    for key in sorted(rep.counts):
        print(f"{rep.counts[key]:7d}  {key}")
    print(f"{len(rep.disagreements)} disagreements, {rep.calls} CLI calls, {time.time() - t:.1f} s, seed {a.seed}")
    return 1 if rep.disagreements else 0


if __name__ == "__main__":
    sys.exit(main())
