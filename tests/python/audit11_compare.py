#!/usr/bin/env python3
"""audit11: random tiny .grid instances (own generator), the CLI against
audit11_model.py.  Usage: audit11_compare.py GRIDLOCK SEED COUNT [OUTDIR]"""
import json
import os
import random
import subprocess
import sys
import tempfile
from fractions import Fraction as F

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import audit11_model as M  # noqa: E402

KINDS = ["expand", "contract", "grow"]
DIRS = {"+x": (1, 0), "-x": (-1, 0), "+y": (0, 1), "-y": (0, -1)}


def random_grid(rng, nmax=7, opmax=4, kmax=None, kmin=1):
    n = rng.randint(min(2 * kmin, nmax), nmax)
    cells = [(0, 0)]
    while len(cells) < n:
        x, y = rng.choice(cells)
        d = rng.choice(list(DIRS.values()))
        c = (x + d[0], y + d[1])
        if c not in cells:
            cells.append(c)
    cs = set(cells)
    # random spanning tree (random order) + extra edges
    edges, seen = set(), {cells[0]}
    todo = [cells[0]]
    while todo:
        a = todo.pop(rng.randrange(len(todo)))
        nb = [(a[0] + d[0], a[1] + d[1]) for d in DIRS.values()]
        rng.shuffle(nb)
        for b in nb:
            if b in cs and b not in seen:
                seen.add(b)
                edges.add(frozenset((a, b)))
                todo.append(b)
    pe = rng.choice([0, 0, 0.3, 0.7])
    for a in cells:
        for d in ((1, 0), (0, 1)):
            b = (a[0] + d[0], a[1] + d[1])
            if b in cs and rng.random() < pe:
                edges.add(frozenset((a, b)))
    used, ops = set(), []
    order = cells[:]
    rng.shuffle(order)
    nops = rng.randint(1, min(opmax, n))
    for u in order * 3:
        if len(ops) >= nops or u in used:
            continue
        dn = rng.choice(list(DIRS))
        d = DIRS[dn]
        c = (u[0] + d[0], u[1] + d[1])
        joined = frozenset((u, c)) in edges
        kind = rng.choice(KINDS) if joined else "grow"
        if joined and kind == "grow":
            continue
        if joined and c in used:
            continue
        used.add(u)
        if joined:
            used.add(c)
        ops.append(("o%d" % len(ops), kind, u, dn))
    k = rng.randint(min(kmin, len(ops)), min(len(ops), kmax or len(ops))) if ops else 0
    groups = [[] for _ in range(k)]
    names = [o[0] for o in ops]
    rng.shuffle(names)
    for i, o in enumerate(names):
        groups[i if i < k else rng.randrange(k)].append(o)
    rng.shuffle(cells)
    el = [tuple(e) for e in edges]
    rng.shuffle(el)
    lines = ["c audit11 random", "p grid %d %d %d %d" % (n, len(el), len(ops), k)]
    lines += ["n %d %d" % c for c in cells]
    lines += ["e %d %d %d %d" % (a[0], a[1], b[0], b[1]) for a, b in el]
    lines += ["o %s %s %d %d %s" % (nm, kd, u[0], u[1], dn) for nm, kd, u, dn in ops]
    lines += ["q Q%d %s" % (i, " ".join(g)) for i, g in enumerate(groups)]
    return "\n".join(lines) + "\n"


def run(g, args):
    p = subprocess.run([g] + args, capture_output=True, text=True, timeout=120)
    status, v = None, []
    for line in p.stdout.splitlines():
        w = line.split()
        if w and w[0] == "s":
            status = w[1]
        elif w and w[0] == "v":
            v.append(w[1:])
    return p.returncode, status, v, p.stdout + p.stderr


def order_of(inst, v):
    names = [x for w in v for x in w]
    return [inst.names.index(x) for x in names]


def times_of(inst, v):
    t = [None] * inst.k
    for name, tm in v:
        t[inst.names.index(name)] = F(tm)
    return t


def compare(g, path, inst, stats, bad_out):
    k = inst.k
    tab = M.discrete_tables(inst)
    exp = {"solve-d": M.discrete_free(inst, tab)[0],
           "collide-d": M.discrete_colliding(inst, tab),
           "collide-c": M.continuous_colliding(inst)}
    cf = M.continuous_free(inst)[0] if k <= 3 else None
    exp["solve-c"] = cf
    cmds = {"solve-d": ["solve", path],
            "solve-c": ["solve", path, "--model", "continuous"],
            "collide-d": ["collide", path, "--model", "discrete"],
            "collide-c": ["collide", path]}
    if os.environ.get("A11_ENGINES"):  # every engine / method, same checks
        extra = {}
        for key, args in cmds.items():
            if key == "solve-d":
                horiz = all(d[1] == 0 for _, _, d in inst.ops.values())
                opts = ["states", "pairs"] + (["precedence", "sat"] if horiz else [])
            elif key == "solve-c":
                opts = ["dl", "sat", "z3"]
            else:
                opts = ["pairwise"] + (["tree", "tree-pairwise"]
                                       if all(len(l) == 1 for _, l in inst.qs) else [])
            flag = "--engine" if key.startswith("solve") else "--method"
            for o in opts:
                extra[key + ":" + o] = args + [flag, o]
                exp[key + ":" + o] = exp[key]
        cmds.update(extra)
    problems = []
    sig = "".join("Y" if exp[x] else ("N" if exp[x] is False else "?")
                  for x in ("solve-d", "solve-c", "collide-d", "collide-c"))
    stats["pattern " + sig] = stats.get("pattern " + sig, 0) + 1
    for key, args in cmds.items():
        kk = key.split(":")[0]
        model = "discrete" if kk.endswith("-d") else "continuous"
        cert = path + "." + key + ".cert"
        rc, st, v, out = run(g, args + ["--certificate", cert])
        if rc not in (10, 20):
            problems.append((key, "rc %d" % rc, out[-300:]))
            continue
        got = rc == 10
        sk = key + (" exact" if exp[key] is not None else " unproved")
        stats[sk] = stats.get(sk, 0) + 1
        e = exp[key]
        if e is not None and got != e:
            problems.append((key, "expected %s got %s" % (e, got), out[-400:]))
        if got:  # witness
            try:
                if kk.endswith("-d"):
                    ok = M.check_order(inst, order_of(inst, v))
                else:
                    ok = M.check_times(inst, times_of(inst, v))
            except Exception as ex:  # noqa: BLE001
                problems.append((key, "witness unreadable %r" % ex, out[-300:]))
                continue
            want = kk.startswith("solve")
            stats["witness"] += 1
            if ok != want:
                problems.append((key, "witness wrong (model says free=%s)" % ok, out[-300:]))
        else:
            rc2, st2, _, out2 = run(g, ["certify", path, cert, "--model", model])
            stats["certify"] += 1
            if rc2 != 20:
                problems.append((key, "certify rc %d" % rc2, out2[-300:]))
        if os.path.exists(cert):
            os.unlink(cert)
    if problems:
        bad_out.append((path, problems))
    return problems


# A11_CFG="nmax opmax kmin kmax kinds": e.g. "8 6 3 3 expand,grow"
CFG = {}
if os.environ.get("A11_CFG"):
    _w = os.environ["A11_CFG"].split()
    CFG = dict(nmax=int(_w[0]), opmax=int(_w[1]), kmin=int(_w[2]), kmax=int(_w[3]))
    if len(_w) > 4:
        KINDS[:] = _w[4].split(",")


def main():
    g, seed, count = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
    outdir = sys.argv[4] if len(sys.argv) > 4 else tempfile.mkdtemp(prefix="a11-")
    os.makedirs(outdir, exist_ok=True)
    stats = {}
    for key in ("solve-d", "solve-c", "collide-d", "collide-c"):
        stats[key + " exact"] = 0
        stats[key + " unproved"] = 0
    stats["witness"] = stats["certify"] = 0
    sizes = {}
    bad = []
    for i in range(count):
        rng = random.Random(seed * 1000003 + i)
        text = random_grid(rng, **CFG)
        path = os.path.join(outdir, "r%d-%d.grid" % (seed, i))
        with open(path, "w") as f:
            f.write(text)
        inst = M.parse_grid(text)
        sizes[(len(inst.nodes), len(inst.ops), inst.k)] = sizes.get(
            (len(inst.nodes), len(inst.ops), inst.k), 0) + 1
        probs = compare(g, path, inst, stats, bad)
        if probs:
            print("DISCREPANCY", path, probs, flush=True)
        else:
            os.unlink(path)
    print(json.dumps(stats))
    print("sizes (nodes, ops, couplings):", sorted(sizes.items()))
    print("discrepancies:", len(bad))


if __name__ == "__main__":
    main()
