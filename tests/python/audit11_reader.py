#!/usr/bin/env python3
"""audit11: a strict .grid validator written from docs/grid-format.md only,
and a mutation fuzzer that holds `gridlock solve` against it.

valid(text) -> None if the doc says the file is valid, else (line, why).
Usage: audit11_reader.py GRIDLOCK SEED COUNT
"""
import os
import random
import re
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import audit11_compare as C  # noqa: E402

NAME = re.compile(r"^[A-Za-z0-9_.:~'][A-Za-z0-9_.:~+'-]{0,63}$")
INT = re.compile(r"^-?[0-9]+$")
DIRS = C.DIRS


def num(tok):
    if not INT.match(tok):
        raise ValueError("not an integer")
    v = int(tok)
    if abs(v) > 10**9:
        raise ValueError("out of range")
    return v


def valid(text):  # noqa: C901 (a flat list of the doc's rules)
    raw = text.encode() if isinstance(text, str) else text
    if b"\0" in raw:
        return (0, "binary")
    lines = raw.split(b"\n")
    if lines and lines[-1] == b"":
        lines.pop()
    header = None
    nodes, edges, ops, qs, anchor = {}, set(), {}, {}, None
    inop = {}
    counts = [0, 0, 0, 0]
    qops = {}
    for no, bl in enumerate(lines, 1):
        if bl.endswith(b"\r"):
            bl = bl[:-1]
        try:
            line = bl.decode("ascii")
        except UnicodeDecodeError:
            w0 = bl.split()
            if w0 and (w0[0] == b"c" or w0[0].startswith(b"#")):
                continue
            return (no, "non-ascii")
        if any(ch not in " \t" and not ch.isprintable() for ch in line):
            return (no, "control char")
        w = line.split()
        if not w or w[0] == "c" or w[0].startswith("#"):
            continue
        t = w[0]
        try:
            if t == "p":
                if header is not None:
                    return (no, "second header")
                if len(w) != 6 or w[1] != "grid":
                    return (no, "bad header")
                header = [num(x) for x in w[2:]]
                if any(x < 0 or x > 2**26 for x in header):
                    return (no, "bad count")
                continue
            if header is None:
                return (no, "missing header")
            kinds = "neoq"
            if t in kinds:
                i = kinds.index(t)
                counts[i] += 1
                if counts[i] > header[i]:
                    return (no, "more lines than the header says")
            if t == "n":
                if len(w) != 3:
                    return (no, "fields")
                c = (num(w[1]), num(w[2]))
                if c in nodes:
                    return (no, "two nodes")
                nodes[c] = no
            elif t == "e":
                if len(w) != 5:
                    return (no, "fields")
                a, b = (num(w[1]), num(w[2])), (num(w[3]), num(w[4]))
                if a not in nodes or b not in nodes:
                    return (no, "edge end")
                if abs(a[0] - b[0]) + abs(a[1] - b[1]) != 1:
                    return (no, "non-adjacent")
                if frozenset((a, b)) in edges:
                    return (no, "edge twice")
                edges.add(frozenset((a, b)))
            elif t == "o":
                if len(w) != 6:
                    return (no, "fields")
                name, kind = w[1], w[2]
                if not NAME.match(name):
                    return (no, "bad name")
                u = (num(w[3]), num(w[4]))
                if kind not in ("expand", "contract", "grow"):
                    return (no, "kind")
                if w[5] not in DIRS:
                    return (no, "dir")
                if u not in nodes:
                    return (no, "no node")
                d = DIRS[w[5]]
                c = (u[0] + d[0], u[1] + d[1])
                joined = frozenset((u, c)) in edges
                if kind == "grow" and joined:
                    return (no, "grow along edge")
                if kind != "grow" and not joined:
                    return (no, "no edge")
                if u in inop or (kind != "grow" and c in inop):
                    return (no, "node in two ops")
                if name in ops:
                    return (no, "op twice")
                ops[name] = no
                inop[u] = name
                if kind != "grow":
                    inop[c] = name
            elif t == "q":
                if len(w) < 3:
                    return (no, "empty coupling")
                if not NAME.match(w[1]):
                    return (no, "bad name")
                if w[1] in qs:
                    return (no, "coupling twice")
                for o in w[2:]:
                    if o not in ops:
                        return (no, "unknown op")
                    if o in qops:
                        return (no, "op in two couplings")
                    qops[o] = w[1]
                qs[w[1]] = no
            elif t == "a":
                if len(w) != 3:
                    return (no, "fields")
                if anchor is not None:
                    return (no, "two anchors")
                anchor = (num(w[1]), num(w[2]))
                if anchor not in nodes:
                    return (no, "anchor")
            else:
                return (no, "unknown line")
        except ValueError as e:
            return (no, str(e))
    if header is None:
        return (len(lines), "empty")
    if counts != header:
        return (len(lines), "truncated")
    if not nodes:
        return (len(lines), "no nodes")
    for o, no in ops.items():
        if o not in qops and o in qs:
            return (no, "implicit name taken")
    # connectivity
    start = next(iter(nodes))
    seen, stack = {start}, [start]
    while stack:
        a = stack.pop()
        for d in DIRS.values():
            b = (a[0] + d[0], a[1] + d[1])
            if b not in seen and frozenset((a, b)) in edges:
                seen.add(b)
                stack.append(b)
    if len(seen) != len(nodes):
        return (min(nodes[c] for c in nodes if c not in seen), "disconnected")
    return None


def mutate(rng, text):
    lines = text.split("\n")
    body = [i for i, ln in enumerate(lines) if ln and not ln.startswith("c")]
    i = rng.choice(body)
    w = lines[i].split()
    m = rng.randrange(9)
    if m == 0:
        del lines[i]
    elif m == 1:
        lines.insert(rng.randrange(len(lines) + 1), lines[i])
    elif m == 2:
        j = rng.choice(body)
        lines[i], lines[j] = lines[j], lines[i]
    elif m == 3 and len(w) > 1:
        k = rng.randrange(1, len(w))
        w[k] = rng.choice(["0", "1", "-1", "2", "+x", "-y", "o0", "Q0", "grow",
                           "expand", "contract", "1000000000", "-1000000001",
                           "x", "", "o0 o0", "Q1", "a", "00", "-0"])
        lines[i] = " ".join(w)
    elif m == 4:
        lines[i] = lines[i] + rng.choice([" 0", " c", " # x", "\t", " "])
    elif m == 5 and len(w) > 1:
        del w[rng.randrange(1, len(w))]
        lines[i] = " ".join(w)
    elif m == 6:
        lines.insert(rng.randrange(len(lines) + 1),
                     rng.choice(["a 0 0", "a 5 5", "q Z o0", "n 9 9", "e 0 0 0 1",
                                 "o z grow 0 0 +x", "#", "c", "q o0 o0",
                                 "n 1000000000 0", "p grid 1 0 0 0"]))
    elif m == 7 and w[0] == "p":
        k = rng.randrange(2, 6)
        w[k] = str(int(w[k]) + rng.choice([-1, 1]))
        lines[i] = " ".join(w)
    elif m == 8 and len(w) > 1:
        lines[i] = lines[i].replace(" ", rng.choice(["  ", "\t", " \t "]), 1)
    return "\n".join(lines)


ERR = re.compile(r"^gridlock: error: (.*):(\d+): \S")


def main():
    g, seed, count = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
    d = tempfile.mkdtemp(prefix="a11r-")
    bad = 0
    agree = {"accept": 0, "reject": 0}
    for i in range(count):
        rng = random.Random(seed * 999983 + i)
        text = C.random_grid(rng, nmax=5, opmax=3)
        for _ in range(rng.randint(1, 2)):
            text = mutate(rng, text)
        path = os.path.join(d, "m%d.grid" % i)
        with open(path, "w") as f:
            f.write(text)
        p = subprocess.run([g, "solve", path], capture_output=True, text=True, timeout=60)
        mine = valid(text)
        cli_ok = p.returncode in (0, 10, 20)
        msg = p.stderr.strip()
        why = None
        if cli_ok != (mine is None):
            why = "CLI %s, doc-validator %s" % ("accepts" if cli_ok else "rejects: " + msg, mine)
        elif not cli_ok:
            m = ERR.match(msg)
            if p.returncode != 1 or not m or "\n" in msg or m.group(1) != path:
                why = "bad diagnostic rc=%d %r" % (p.returncode, msg)
            elif int(m.group(2)) != mine[0]:
                print("LINE", path, msg, mine, flush=True)
        if why:
            bad += 1
            print("MISMATCH", path, why, flush=True)
        else:
            agree["accept" if cli_ok else "reject"] += 1
            os.unlink(path)
    print("agree", agree, "mismatches", bad)


if __name__ == "__main__":
    main()
