#!/usr/bin/env python3
"""Writes the small-formula sweeps of docs/verify.md as DIMACS files.

  scripts/sweep-formulas.py 2 DIR         every formula over 2 variables with 1-4
                                          distinct non-tautological clauses (162)
  scripts/sweep-formulas.py 3 DIR --orbits  one formula per orbit of the
                                          3-variable sweep (17 901 formulas) under
                                          renaming and negating variables (503)

then e.g.  gridlock verify --model continuous --direct DIR
"""
import itertools
import os
import sys


def clauses_over(n):
    out = []
    for mask in range(1, 3 ** n):
        cl, x = [], mask
        for v in range(1, n + 1):
            if x % 3:
                cl.append(v if x % 3 == 1 else -v)
            x //= 3
        out.append(tuple(cl))
    return out


def canonical(f, n):
    best = None
    for perm in itertools.permutations(range(1, n + 1)):
        for signs in itertools.product([1, -1], repeat=n):
            g = tuple(sorted(tuple(sorted(perm[abs(l) - 1] * signs[abs(l) - 1] * (1 if l > 0 else -1) for l in c))
                             for c in f))
            best = g if best is None or g < best else best
    return best


def main():
    if len(sys.argv) < 3 or sys.argv[1] not in ("2", "3"):
        sys.exit(__doc__)
    n, out, orbits = int(sys.argv[1]), sys.argv[2], "--orbits" in sys.argv[3:]
    os.makedirs(out, exist_ok=True)
    seen, i = set(), 0
    for k in range(1, 5):
        for f in itertools.combinations(clauses_over(n), k):
            if orbits:
                c = canonical(f, n)
                if c in seen:
                    continue
                seen.add(c)
            i += 1
            with open(os.path.join(out, "s%05d.cnf" % i), "w") as fh:
                fh.write("p cnf %d %d\n" % (n, len(f)))
                for c in f:
                    fh.write(" ".join(map(str, c)) + " 0\n")
    print("wrote %d formulas to %s" % (i, out))


if __name__ == "__main__":
    main()
