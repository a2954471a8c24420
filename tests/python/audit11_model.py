#!/usr/bin/env python3
"""audit11: a second, independent brute-force model of the semantics (docs/model.md).

Written from MODEL.md, docs/model.md and docs/grid-format.md only (not from
lattice/, solver/, collide/ nor tests/python/conformance_model.py).
Standard library only; every number is an int or a Fraction.

Progress of coupling j is p_j in [0, 1]. Every region side is an affine form
in p (list: [const, coef_1, ..., coef_k]). A pair of regions overlaps with
positive area iff 8 strict linear inequalities hold; a cycle collides iff
the mismatch of some non-tree edge is non-zero.

Deciders:
  discrete_free / discrete_colliding : exact (all subsets / orders)
  continuous_colliding               : exact (Fourier-Motzkin on the cube)
  continuous_free                    : exact for k <= 3 couplings (arrangement
                                       of the projected bad sets in start-time
                                       space), else None
"""
from fractions import Fraction as F
from itertools import product
import sys

DIRS = {"+x": (1, 0), "-x": (-1, 0), "+y": (0, 1), "-y": (0, -1)}


class GridError(Exception):
    pass


# ---------------------------------------------------------------- parsing
def parse_grid(text):
    nodes, edges, ops, qs = [], set(), {}, []
    cells = set()
    header = None
    for line in text.splitlines():
        w = line.split()
        if not w or w[0] in ("c", "#") or w[0].startswith("#"):
            continue
        t = w[0]
        if t == "p":
            header = tuple(int(x) for x in w[2:6])
        elif t == "n":
            c = (int(w[1]), int(w[2]))
            if c in cells:
                raise GridError("two nodes in a cell")
            cells.add(c)
            nodes.append(c)
        elif t == "e":
            a, b = (int(w[1]), int(w[2])), (int(w[3]), int(w[4]))
            edges.add(frozenset((a, b)))
        elif t == "o":
            ops[w[1]] = (w[2], (int(w[3]), int(w[4])), DIRS[w[5]])
        elif t == "q":
            qs.append((w[1], w[2:]))
        elif t == "a":
            pass
    assert header is not None
    inq = {o for _, l in qs for o in l}
    for o in ops:  # singleton couplings, in operation order
        if o not in inq:
            qs.append((o, [o]))
    return Instance(nodes, edges, ops, qs)


def add(a, b):
    return [x + y for x, y in zip(a, b)]


def scale(a, s):
    return [x * s for x in a]


class Instance:
    def __init__(self, nodes, edges, ops, qs):
        self.nodes, self.edges, self.ops, self.qs = nodes, edges, ops, qs
        self.k = len(qs)
        self.names = [q for q, _ in qs]
        self.qof = {o: i for i, (_, l) in enumerate(qs) for o in l}
        self._positions()
        self._regions()

    def zero(self):
        return [0] * (self.k + 1)

    def unit(self, j, s):
        v = self.zero()
        v[j + 1] = s
        return v

    def edge_motion(self, a, b):
        """Displacement of b relative to a across edge ab, per axis."""
        for o, (kind, u, d) in self.ops.items():
            if kind == "grow":
                continue
            v = (u[0] + d[0], u[1] + d[1])
            if {a, b} == {u, v}:
                sgn = 1 if kind == "expand" else -1
                if a != u:
                    sgn = -sgn
                j = self.qof[o]
                return (self.unit(j, sgn * d[0]), self.unit(j, sgn * d[1]))
        return (self.zero(), self.zero())

    def _positions(self):
        adj = {c: [] for c in self.nodes}
        for e in self.edges:
            a, b = tuple(e)
            adj[a].append(b)
            adj[b].append(a)
        # depth-first tree from the LAST node (different from the CLI's anchor)
        root = self.nodes[-1]
        self.disp = {root: (self.zero(), self.zero())}
        tree = set()
        stack = [root]
        while stack:
            a = stack.pop()
            for b in sorted(adj[a], reverse=True):
                if b not in self.disp:
                    mx, my = self.edge_motion(a, b)
                    self.disp[b] = (add(self.disp[a][0], mx), add(self.disp[a][1], my))
                    tree.add(frozenset((a, b)))
                    stack.append(b)
        assert len(self.disp) == len(self.nodes), "disconnected"
        self.cycles = []  # mismatch forms (x, y) per non-tree edge
        for e in self.edges - tree:
            a, b = tuple(e)
            mx, my = self.edge_motion(a, b)
            dx = add(add(self.disp[b][0], scale(self.disp[a][0], -1)), scale(mx, -1))
            dy = add(add(self.disp[b][1], scale(self.disp[a][1], -1)), scale(my, -1))
            for f in (dx, dy):
                if any(f):
                    self.cycles.append(f)

    def side(self, c, axis, hi):
        """Affine form of a cell's face: axis 0/1, hi: the +side."""
        f = list(self.disp[c][axis])
        f[0] += c[axis] + (1 if hi else 0)
        return f

    def box(self, c):
        return [self.side(c, 0, False), self.side(c, 0, True),
                self.side(c, 1, False), self.side(c, 1, True)]

    def _regions(self):
        contracted = {}
        for o, (kind, u, d) in self.ops.items():
            if kind == "contract":
                contracted[(u[0] + d[0], u[1] + d[1])] = (u, d)
        regs = []
        for c in self.nodes:
            b = self.box(c)
            if c in contracted:
                u, d = contracted[c]
                ax = 0 if d[0] else 1
                pos = (d[0] + d[1]) > 0
                # near face (toward u) pinned to u's face; far face is v's own
                if pos:
                    b[2 * ax] = self.side(u, ax, True)
                else:
                    b[2 * ax + 1] = self.side(u, ax, False)
            regs.append(("node %s" % (c,), b))
        for o, (kind, u, d) in self.ops.items():
            if kind == "contract":
                continue
            j = self.qof[o]
            b = self.box(u)
            ax = 0 if d[0] else 1
            pos = (d[0] + d[1]) > 0
            if pos:
                face = self.side(u, ax, True)
                b[2 * ax], b[2 * ax + 1] = face, add(face, self.unit(j, 1))
            else:
                face = self.side(u, ax, False)
                b[2 * ax], b[2 * ax + 1] = add(face, self.unit(j, -1)), face
            regs.append(("new %s" % o, b))
        self.regions = regs
        self.pairs = []
        for i in range(len(regs)):
            for jj in range(i + 1, len(regs)):
                forms = overlap_forms(regs[i][1], regs[jj][1])
                # sound pruning: a form that is <= 0 on the whole cube
                if all(f[0] + sum(c for c in f[1:] if c > 0) > 0 for f in forms):
                    self.pairs.append((regs[i][0], regs[jj][0], forms))


def sub(a, b):
    return [x - y for x, y in zip(a, b)]


def overlap_forms(A, B):
    """Affine forms f, all > 0 iff A and B overlap with positive area."""
    out = []
    for ax in (0, 1):
        alo, ahi, blo, bhi = A[2 * ax], A[2 * ax + 1], B[2 * ax], B[2 * ax + 1]
        out += [sub(bhi, alo), sub(ahi, blo), sub(ahi, alo), sub(bhi, blo)]
    return out


# ------------------------------------------------------ one-variable tests
def exists_1d(lin, lo, hi):
    """lin: list of (a, b); is there s in [lo, hi] with a + b s > 0 for all?"""
    pts = {F(lo), F(hi)}
    for a, b in lin:
        if b != 0:
            r = F(-a, 1) / b
            if lo < r < hi:
                pts.add(r)
    pts = sorted(pts)
    cand = pts + [(x + y) / 2 for x, y in zip(pts, pts[1:])]
    return any(all(a + b * s > 0 for a, b in lin) for s in cand)


def ev(f, p):
    return f[0] + sum(c * x for c, x in zip(f[1:], p))


def restrict(f, fixed, j):
    """f with p fixed (p[j] free) -> (a, b)."""
    p = list(fixed)
    p[j] = 0
    return (ev(f, p), f[j + 1])


# ----------------------------------------------------------- discrete time
def step_collides(inst, done, j):
    fixed = [1 if i in done else 0 for i in range(inst.k)]
    for f in inst.cycles:
        a, b = restrict(f, fixed, j)
        if a != 0 or b != 0:
            return "cycle"
    for n1, n2, forms in inst.pairs:
        if exists_1d([restrict(f, fixed, j) for f in forms], 0, 1):
            return (n1, n2)
    return None


def discrete_tables(inst):
    k = inst.k
    bad = {}
    for mask in range(1 << k):
        done = {i for i in range(k) if mask >> i & 1}
        for j in range(k):
            if j not in done:
                bad[(mask, j)] = step_collides(inst, done, j)
    return bad


def discrete_colliding(inst, bad=None):
    bad = bad or discrete_tables(inst)
    return any(v is not None for v in bad.values())


def discrete_free(inst, bad=None):
    bad = bad if bad is not None else discrete_tables(inst)
    k = inst.k
    reach = {0: []}
    for mask in sorted(range(1 << k), key=lambda m: bin(m).count("1")):
        if mask not in reach:
            continue
        for j in range(k):
            if not mask >> j & 1 and bad[(mask, j)] is None:
                reach.setdefault(mask | 1 << j, reach[mask] + [j])
    full = (1 << k) - 1
    return full in reach, reach.get(full)


def check_order(inst, order):
    """order: coupling indices. True iff collision-free."""
    done = set()
    for j in order:
        if step_collides(inst, done, j) is not None:
            return False
        done.add(j)
    return True


# --------------------------------------------------------- continuous time
def check_times(inst, t):
    """t: list of start times (Fractions). True iff collision-free."""
    ev_pts = sorted({F(x) for x in t} | {F(x) + 1 for x in t})
    for e in ev_pts:  # cycles: mismatch is affine between events
        p = [min(max(e - x, 0), 1) for x in t]
        if any(ev(f, p) != 0 for f in inst.cycles):
            return False
    for lo, hi in zip(ev_pts, ev_pts[1:]):
        mid = (lo + hi) / 2
        # p_j(s) = c_j + m_j s on [lo, hi]
        cm = []
        for x in t:
            if x <= lo and mid < x + 1 and hi <= x + 1:
                cm.append((-x, 1))
            elif mid > x + 1:
                cm.append((1, 0))
            else:
                cm.append((0, 0))
        for _, _, forms in inst.pairs:
            lin = []
            for f in forms:
                a = f[0] + sum(c * q[0] for c, q in zip(f[1:], cm))
                b = sum(c * q[1] for c, q in zip(f[1:], cm))
                lin.append((a, b))
            if exists_1d(lin, lo, hi):
                return False
    return True


def fm_feasible(cons, nvars):
    """cons: list of (coefs[nvars], const, strict): sum c x + c0 (>|>=) 0."""
    cons = [(list(c), F(c0), s) for c, c0, s in cons]
    for v in range(nvars):
        cons = fm_eliminate(cons, v)
        if cons is None:
            return False
    return all((c0 > 0) if s else (c0 >= 0) for _, c0, s in cons)


def _norm(c, c0, s):
    m = max([abs(x) for x in c] + [abs(c0)])
    if m == 0:
        return (tuple(c), c0, s)
    return (tuple(F(x) / m for x in c), F(c0) / m, s)


def fm_eliminate(cons, v):
    pos, neg, rest = [], [], []
    for c, c0, s in cons:
        (pos if c[v] > 0 else neg if c[v] < 0 else rest).append((c, c0, s))
    out = set()
    for c, c0, s in rest:
        if all(x == 0 for x in c):
            if (c0 <= 0) if s else (c0 < 0):
                return None
            continue
        out.add(_norm(c, c0, s))
    for cp, p0, ps in pos:
        for cn, n0, ns in neg:
            a, b = -cn[v], cp[v]
            c = [a * x + b * y for x, y in zip(cp, cn)]
            c0 = a * p0 + b * n0
            s = ps or ns
            if all(x == 0 for x in c):
                if (c0 <= 0) if s else (c0 < 0):
                    return None
                continue
            out.add(_norm(c, c0, s))
    return [(list(c), c0, s) for c, c0, s in out]


def continuous_colliding(inst):
    if any(any(f[1:]) for f in inst.cycles):
        return True
    k = inst.k
    box = []
    for j in range(k):
        e = [0] * k
        e[j] = 1
        box.append((e, 0, False))
        box.append(([-x for x in e], 1, False))
    for _, _, forms in inst.pairs:
        cons = [(f[1:], f[0], True) for f in forms] + box
        if fm_feasible(cons, k):
            return True
    return False


def bad_polys_in_t(inst):
    """Bad start-time sets, t_0 = 0, variables (s, t_1..t_{k-1}) -> t."""
    k = inst.k
    nv = k  # s, t_1 .. t_{k-1}
    polys = []

    def tvec(j):  # affine form (coef over nv vars, const) of t_j
        c = [0] * nv
        if j > 0:
            c[j] = 1
        return c

    for pat in product("ADN", repeat=k):  # active, done, not started
        base = []
        pform = []  # p_j as (coefs, const)
        for j, st in enumerate(pat):
            tj = tvec(j)
            s_minus_t = [(1 if i == 0 else 0) - tj[i] for i in range(nv)]
            if st == "A":
                base.append((s_minus_t, 0, False))
                base.append(([-x for x in s_minus_t], 1, False))
                pform.append((s_minus_t, 0))
            elif st == "D":
                base.append((s_minus_t, -1, False))
                pform.append(([0] * nv, 1))
            else:
                base.append(([-x for x in s_minus_t], 0, False))
                pform.append(([0] * nv, 0))

        def subst(f):
            c = [0] * nv
            c0 = f[0]
            for j in range(k):
                c = [x + f[j + 1] * y for x, y in zip(c, pform[j][0])]
                c0 += f[j + 1] * pform[j][1]
            return c, c0

        groups = []
        for f in inst.cycles:
            c, c0 = subst(f)
            groups.append([(c, c0, True)])
            groups.append([([-x for x in c], -c0, True)])
        for _, _, forms in inst.pairs:
            groups.append([subst(f) + (True,) for f in forms])
        for g in groups:
            proj = fm_eliminate([(list(c), F(c0), s) for c, c0, s in g + base], 0)
            if proj is None:
                continue
            proj = [(c[1:], c0, s) for c, c0, s in proj]
            if fm_feasible(proj, nv - 1):
                polys.append(proj)
    return polys


def interval_1d(cons, lo, hi):
    """cons over one var y: (c, c0, strict). -> (lo, loc, hi, hic) or None."""
    L, Lc, H, Hc = lo, True, hi, True
    for c, c0, s in cons:
        if c == 0:
            if (c0 <= 0) if s else (c0 < 0):
                return None
            continue
        r = F(-c0) / c
        if c > 0:  # y > r
            if r > L or (r == L and s):
                L, Lc = r, not s
        else:  # y < r
            if r < H or (r == H and s):
                H, Hc = r, not s
    if L > H or (L == H and not (Lc and Hc)):
        return None
    return (L, Lc, H, Hc)


def uncovered(ivs, lo, hi):
    """A point of [lo, hi] in no interval, or None."""
    ivs = sorted(ivs, key=lambda v: (v[0], not v[1]))
    r, rc = lo, False  # covered: [lo, r) (+ r if rc)
    for L, Lc, H, Hc in ivs:
        if L > r:
            return r if not rc else (r + L) / 2
        if L == r and not rc and not Lc:
            return r
        if H > r or (H == r and Hc):
            r, rc = H, Hc
    if r < hi or not rc:
        return r if not rc else (r + hi) / 2
    return None


def continuous_free(inst):
    """(answer, witness start times) exact for k <= 3; (None, None) otherwise."""
    k = inst.k
    if k == 0:
        return True, []
    if k == 1:
        t = [F(0)]
        return check_times(inst, t), t
    if k > 3:
        return None, None
    R = F(k - 1)  # gap compression: |t_j - t_0| <= k - 1
    polys = bad_polys_in_t(inst)
    if k == 2:
        ivs = [iv for iv in (interval_1d([(c[0], c0, s) for c, c0, s in P], -R, R)
                             for P in polys) if iv]
        x = uncovered(ivs, -R, R)
        if x is None:
            return False, None
        t = [F(0), x]
        assert check_times(inst, t), ("model bug", t)
        return True, t
    # k == 3: variables (x, y) = (t_1, t_2)
    lines = set()
    for P in polys:
        for c, c0, s in P:
            if c[0] != 0 or c[1] != 0:
                m = c[1] if c[1] != 0 else c[0]
                lines.add((F(c[0]) / m, F(c[1]) / m, F(c0) / m))
    xs = {-R, R}
    nonv = [ln for ln in lines if ln[1] != 0]
    for a, b, c in lines:
        if b == 0:
            xs.add(-c / a)
    for i in range(len(nonv)):
        a1, _, c1 = nonv[i]
        for a2, _, c2 in nonv[i + 1:]:
            if a1 != a2:  # y = -a x - c
                xs.add((c2 - c1) / (a1 - a2))
    xs = sorted(x for x in xs if -R <= x <= R)
    cands = xs + [(p + q) / 2 for p, q in zip(xs, xs[1:])]
    for x0 in cands:
        ivs = []
        for P in polys:
            iv = interval_1d([(c[1], c[0] * x0 + c0, s) for c, c0, s in P], -R, R)
            if iv:
                ivs.append(iv)
        y = uncovered(ivs, -R, R)
        if y is not None:
            t = [F(0), x0, y]
            assert check_times(inst, t), ("model bug", t)
            return True, t
    return False, None


if __name__ == "__main__":
    inst = parse_grid(open(sys.argv[1]).read())
    bad = discrete_tables(inst)
    print("couplings", inst.names)
    print("discrete free", discrete_free(inst, bad))
    print("discrete colliding", discrete_colliding(inst, bad))
    print("continuous colliding", continuous_colliding(inst))
    print("continuous free", continuous_free(inst))
