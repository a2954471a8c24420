"""An independent model of the semantics (docs/model.md, the paper's Model
section), in pure Python with exact fractions, for checking the command line.

Written from the documents only (the paper, MODEL.md, docs/model.md,
docs/grid-format.md), not from the C++ simulator, so that it can disagree
with it. It is deliberately simple and slow: every pair of regions, every
interval between events, positions on a depth-first spanning tree rooted at
the LAST node of the file (the C++ side uses a breadth-first tree from the
anchor), cycles from that tree's fundamental cycles.

What it decides, exactly:
- simulate(): one schedule (start times; a discrete order is the start
  times 0, 1, 2, ...) -> None or the first collision (moment, kind, every
  colliding pair / cycle at that moment, the couplings moving then).
- brute_discrete(): every order of the couplings (prefix search with the
  step verdicts memoized on (couplings done, coupling run)) -> is some order
  collision-free, is some order colliding.
- continuous_colliding(): Colliding Schedule, continuous. Any progress
  vector p in [0,1]^k is the configuration at time 1 of the start times
  1 - p, so a colliding schedule exists iff some p in the cube has a cycle
  mismatch or a pair of regions overlapping with positive area: a system of
  strict linear inequalities, decided by Fourier-Motzkin elimination.
Continuous Collision-free Schedule is NOT decided in general (no finite set
of start times is argued to suffice); free_schedule_candidates() gives a
sound one-sided test (a schedule found collision-free proves YES), and for
horizontal-only instances the paper's theorem (YES iff all at once is
collision-free) makes running everything at time 0 exact.
"""
from fractions import Fraction
import itertools

DIRS = {"+x": (1, 0), "-x": (-1, 0), "+y": (0, 1), "-y": (0, -1)}
SIGN = {"expand": 1, "contract": -1}


class GridError(ValueError):
    pass


class Instance:
    """A parsed .grid file (docs/grid-format.md)."""

    def __init__(self):
        self.nodes = []  # cells, in file order
        self.edges = []  # (cell, cell), in file order
        self.ops = {}  # name -> (kind, u cell, direction)
        self.op_order = []
        self.couplings = {}  # name -> [op names]
        self.anchor = None
        self.text = ""


def _int(tok):
    try:
        return int(tok)
    except ValueError:
        raise GridError(f"not an integer: {tok!r}")


def parse_grid(text):
    inst = Instance()
    inst.text = text
    header = None
    in_coupling = set()
    for raw in text.splitlines():
        line = raw.strip()
        if not line or line[0] in "c#":
            continue
        t = line.split()
        if t[0] == "p":
            if header is not None or t[1] != "grid" or len(t) != 6:
                raise GridError("bad header")
            header = [_int(x) for x in t[2:]]
        elif header is None:
            raise GridError("missing header")
        elif t[0] == "n":
            cell = (_int(t[1]), _int(t[2]))
            if cell in inst.nodes:
                raise GridError(f"two nodes in {cell}")
            inst.nodes.append(cell)
        elif t[0] == "e":
            a, b = (_int(t[1]), _int(t[2])), (_int(t[3]), _int(t[4]))
            if abs(a[0] - b[0]) + abs(a[1] - b[1]) != 1 or a not in inst.nodes or b not in inst.nodes:
                raise GridError(f"bad edge {a} {b}")
            inst.edges.append((a, b))
        elif t[0] == "o":
            name, kind, u, d = t[1], t[2], (_int(t[3]), _int(t[4])), t[5]
            if kind not in ("expand", "contract", "grow") or d not in DIRS or u not in inst.nodes:
                raise GridError(f"bad operation {line}")
            inst.ops[name] = (kind, u, d)
            inst.op_order.append(name)
        elif t[0] == "q":
            inst.couplings[t[1]] = list(t[2:])
            in_coupling.update(t[2:])
        elif t[0] == "a":
            inst.anchor = (_int(t[1]), _int(t[2]))
        else:
            raise GridError(f"unknown line {line}")
    if header is None or not inst.nodes:
        raise GridError("no header or no nodes")
    for name in inst.op_order:
        if name not in in_coupling:
            inst.couplings[name] = [name]
    return inst


# An affine form: (constant, {coupling: integer coefficient}).
def _add(f, g, scale=1):
    c = dict(f[1])
    for q, v in g[1].items():
        c[q] = c.get(q, 0) + scale * v
        if c[q] == 0:
            del c[q]
    return (f[0] + scale * g[0], c)


def _const(x):
    return (Fraction(x), {})


def _evaluate(f, progress):
    return f[0] + sum(v * progress[q] for q, v in f[1].items())


class Model:
    """Positions of every region as affine forms of the couplings' progress."""

    def __init__(self, inst):
        self.inst = inst
        self.coupling_of = {op: q for q, ops in inst.couplings.items() for op in ops}
        self.couplings = list(inst.couplings)
        adj = {c: [] for c in inst.nodes}
        for a, b in inst.edges:
            adj[a].append(b)
            adj[b].append(a)
        # Operation on an edge: key frozenset{u, v} -> (sign, coupling).
        self.edge_op = {}
        for name, (kind, u, d) in inst.ops.items():
            if kind != "grow":
                v = (u[0] + DIRS[d][0], u[1] + DIRS[d][1])
                self.edge_op[frozenset((u, v))] = (SIGN[kind], self.coupling_of[name])
        # Depth-first spanning tree from the last node: displacement forms.
        root = inst.nodes[-1]
        self.disp = {root: ((_const(0), _const(0)))}
        tree_edges = set()
        stack = [root]
        while stack:
            a = stack.pop()
            for b in adj[a]:
                if b in self.disp:
                    continue
                self.disp[b] = self._child(a, b)
                tree_edges.add(frozenset((a, b)))
                stack.append(b)
        if len(self.disp) != len(inst.nodes):
            raise GridError("shape not connected")
        # Fundamental cycles: mismatch of each non-tree edge, linear in p.
        self.cycles = []
        for a, b in inst.edges:
            if frozenset((a, b)) in tree_edges:
                continue
            via_edge = self._child(a, b)
            mismatch = tuple(_add(self.disp[b][i], via_edge[i], -1) for i in range(2))
            self.cycles.append(((a, b), mismatch))
        self.regions = self._regions()

    def _child(self, a, b):
        """Displacement of b from that of a across the edge ab."""
        dx, dy = self.disp[a]
        op = self.edge_op.get(frozenset((a, b)))
        if op is None:
            return (dx, dy)
        sign, q = op
        ux, uy = b[0] - a[0], b[1] - a[1]
        return (_add(dx, (Fraction(0), {q: sign * ux})), _add(dy, (Fraction(0), {q: sign * uy})))

    def _box(self, cell):
        dx, dy = self.disp[cell]
        return [_add(_const(cell[0]), dx), _add(_const(cell[0] + 1), dx),
                _add(_const(cell[1]), dy), _add(_const(cell[1] + 1), dy)]

    def _regions(self):
        """name -> [xlo, xhi, ylo, yhi] affine forms."""
        regions = {}
        for cell in self.inst.nodes:
            regions[f"node ({cell[0]},{cell[1]})"] = self._box(cell)
        for name in self.inst.op_order:
            kind, u, d = self.inst.ops[name]
            ddx, ddy = DIRS[d]
            axis = 0 if ddx else 1
            forward = (ddx + ddy) > 0
            ub = self._box(u)
            # u's face toward d: index of the side on that axis.
            face = ub[2 * axis + 1] if forward else ub[2 * axis]
            if kind == "grow":
                far = _add(face, (Fraction(0), {self.coupling_of[name]: 1 if forward else -1}))
                box = list(ub)
                box[2 * axis], box[2 * axis + 1] = (face, far) if forward else (far, face)
                regions[f"node grown by {name}"] = box
                continue
            v = (u[0] + ddx, u[1] + ddy)
            vb = self._box(v)
            if kind == "expand":
                near = vb[2 * axis] if forward else vb[2 * axis + 1]
                box = list(ub)
                box[2 * axis], box[2 * axis + 1] = (face, near) if forward else (near, face)
                regions[f"node inserted by {name}"] = box
            else:  # the contracting v: from u's face to v's far face
                far = vb[2 * axis + 1] if forward else vb[2 * axis]
                box = list(vb)
                box[2 * axis], box[2 * axis + 1] = (face, far) if forward else (far, face)
                regions[f"node ({v[0]},{v[1]})"] = box
        return regions

    def cycle_nets(self):
        """Every (edge, coupling, net vector) with a non-zero net."""
        out = []
        for edge, (mx, my) in self.cycles:
            for q in set(mx[1]) | set(my[1]):
                out.append((edge, q, (mx[1].get(q, 0), my[1].get(q, 0))))
        return out


class Collision:
    def __init__(self, time, kind, pairs, cycles, moving):
        self.time, self.kind, self.pairs, self.cycles, self.moving = time, kind, pairs, cycles, moving

    def __repr__(self):
        return f"Collision({self.kind} at {self.time}, pairs={sorted(map(sorted, self.pairs))}, moving={sorted(self.moving)})"


def _progress(starts, t):
    return {q: min(Fraction(1), max(Fraction(0), t - s)) for q, s in starts.items()}


def _boxes_at(model, progress):
    return {name: [_evaluate(f, progress) for f in box] for name, box in model.regions.items()}


def _overlap_start(a0, a1, b0, b1, t0, t1):
    """Earliest moment in (t0, t1) at which boxes A and B (linear in t from
    a0 at t0 to a1 at t1) overlap with positive area, or None. The strict
    inequalities lo < hi of the intersection hold on an open interval."""
    lo, hi = t0, t1
    length = t1 - t0
    # each condition: f(t) = g0 + (g1 - g0) (t - t0) / length > 0
    conds = []
    for k in (0, 2):
        conds.append((a0[k + 1] - b0[k], a1[k + 1] - b1[k]))  # A.hi > B.lo
        conds.append((b0[k + 1] - a0[k], b1[k + 1] - a1[k]))  # B.hi > A.lo
        conds.append((a0[k + 1] - a0[k], a1[k + 1] - a1[k]))  # A has width
        conds.append((b0[k + 1] - b0[k], b1[k + 1] - b1[k]))
    for g0, g1 in conds:
        slope = (g1 - g0) / length
        if slope == 0:
            if g0 <= 0:
                return None
            continue
        root = t0 - g0 / slope  # f(root) = 0
        if slope > 0:
            lo = max(lo, root)
        else:
            hi = min(hi, root)
        if lo >= hi:
            return None
    return lo if lo < hi else None


def _cycle_mismatch(model, progress):
    bad = []
    for edge, (mx, my) in model.cycles:
        if _evaluate(mx, progress) != 0 or _evaluate(my, progress) != 0:
            bad.append(edge)
    return bad


def _interval(model, starts, t0, t1):
    """The first collision starting in [t0, t1) given none before t0."""
    p0, p1 = _progress(starts, t0), _progress(starts, t1)
    moving = {q for q, s in starts.items() if s <= t0 < s + 1}
    mid = _progress(starts, (t0 + t1) / 2)
    cyc = _cycle_mismatch(model, mid)
    if cyc:
        return Collision(t0, "cycle", set(), cyc, moving)
    b0, b1 = _boxes_at(model, p0), _boxes_at(model, p1)
    names = list(model.regions)
    best, pairs = None, set()
    for i, a in enumerate(names):
        a0, a1 = b0[a], b1[a]
        for b in names[i + 1:]:
            c0, c1 = b0[b], b1[b]
            # the boxes swept over the interval must overlap (exact filter)
            if any(max(a0[k + 1], a1[k + 1]) <= min(c0[k], c1[k]) or
                   max(c0[k + 1], c1[k + 1]) <= min(a0[k], a1[k]) for k in (0, 2)):
                continue
            s = _overlap_start(a0, a1, c0, c1, t0, t1)
            if s is None:
                continue
            if best is None or s < best:
                best, pairs = s, {frozenset((a, b))}
            elif s == best:
                pairs.add(frozenset((a, b)))
    if best is None:
        return None
    moving = {q for q, st in starts.items() if st <= best < st + 1}
    return Collision(best, "node", pairs, [], moving)


def simulate(model, starts):
    """starts: coupling -> Fraction. None if collision-free, else the first
    collision (a cycle collision wins a tie with a node collision)."""
    starts = {q: Fraction(s) for q, s in starts.items()}
    events = sorted({s for s in starts.values()} | {s + 1 for s in starts.values()})
    for t0, t1 in zip(events, events[1:]):
        c = _interval(model, starts, t0, t1)
        if c is not None:
            return c
    return None


def order_starts(order):
    return {q: Fraction(i) for i, q in enumerate(order)}


def step_collides(model, done, q):
    """Discrete step: couplings in done at 1, q runs from 0 to 1."""
    starts = {c: Fraction(-5) for c in done}
    starts[q] = Fraction(0)
    for c in model.couplings:
        starts.setdefault(c, Fraction(10))
    return _interval(model, starts, Fraction(0), Fraction(1)) is not None


def brute_discrete(model):
    """Every order of the couplings. Returns (a collision-free order or
    None, a colliding order or None)."""
    memo = {}

    def collides(done, q):
        key = (done, q)
        if key not in memo:
            memo[key] = step_collides(model, done, q)
        return memo[key]

    free, colliding = None, None
    for order in itertools.permutations(model.couplings):
        done = frozenset()
        ok = True
        for q in order:
            if collides(done, q):
                ok = False
                break
            done = done | {q}
        if ok and free is None:
            free = list(order)
        if not ok and colliding is None:
            colliding = list(order)
        if free is not None and colliding is not None:
            break
    return free, colliding


# ---- continuous Colliding Schedule: strict linear systems, Fourier-Motzkin


def _fm_feasible(constraints, variables):
    """constraints: list of (coef dict, constant, strict) meaning
    sum coef*x + constant > 0 (strict) or >= 0. Exact feasibility over Q."""
    cons = [(dict(c), Fraction(k), s) for c, k, s in constraints]
    for x in variables:
        pos, neg, rest = [], [], []
        for c, k, s in cons:
            a = c.get(x, 0)
            if a > 0:
                pos.append((c, k, s, a))
            elif a < 0:
                neg.append((c, k, s, a))
            else:
                rest.append((c, k, s))
        seen = {}
        for cp, kp, sp, ap in pos:
            for cn, kn, sn, an in neg:
                # (cp x + ...)/ap and (cn ...)/(-an): sum eliminates x
                c = {}
                for v in set(cp) | set(cn):
                    if v == x:
                        continue
                    val = Fraction(cp.get(v, 0)) / ap + Fraction(cn.get(v, 0)) / (-an)
                    if val != 0:
                        c[v] = val
                k = kp / ap + kn / (-an)
                key = tuple(sorted(c.items()))
                strict = sp or sn
                old = seen.get(key)
                # keep the tightest: smaller constant, strict on ties
                if old is None or k < old[0] or (k == old[0] and strict and not old[1]):
                    seen[key] = (k, strict)
        cons = [(c, k, s) for c, k, s in rest] + [(dict(key), k, s) for key, (k, s) in seen.items()]
    for c, k, s in cons:
        if c:
            raise AssertionError("variable left after elimination")
        if (s and k <= 0) or (not s and k < 0):
            return False
    return True


def _pair_feasible(model, a, b):
    ra, rb = model.regions[a], model.regions[b]
    used = set()
    for f in ra + rb:
        used |= set(f[1])
    cons = []
    for k in (0, 2):
        for hi, lo in ((ra[k + 1], rb[k]), (rb[k + 1], ra[k]), (ra[k + 1], ra[k]), (rb[k + 1], rb[k])):
            g = _add(hi, lo, -1)
            cons.append((g[1], g[0], True))
    for q in used:
        cons.append(({q: 1}, Fraction(0), False))
        cons.append(({q: -1}, Fraction(1), False))
    return _fm_feasible(cons, sorted(used))


def continuous_colliding(model):
    """Exact Colliding Schedule, continuous: ('cycle', ...) / ('node', a, b) / None."""
    nets = model.cycle_nets()
    if nets:
        return ("cycle", nets[0])
    names = list(model.regions)
    for i, a in enumerate(names):
        for b in names[i + 1:]:
            if _pair_feasible(model, a, b):
                return ("node", a, b)
    return None


def is_horizontal(inst):
    return all(d in ("+x", "-x") for _, _, d in inst.ops.values())


def free_schedule_candidates(model, order_free=None, extra=()):
    """Sound test for continuous Collision-free Schedule: start times tried
    (all at once, a free discrete order, the extra ones); returns the first
    collision-free one or None (None proves nothing)."""
    tries = [{q: Fraction(0) for q in model.couplings}]
    if order_free is not None:
        tries.append(order_starts(order_free))
    tries.extend(extra)
    for st in tries:
        if simulate(model, st) is None:
            return st
    return None


def parse_times(lines):
    out = {}
    for line in lines:
        name, t = line.split()
        out[name] = Fraction(t)
    return out


# ---- continuous Collision-free Schedule for two couplings, exactly
#
# With two couplings A (start 0) and B (start d) only d matters, and
# |d| >= 1 is the same motion as d = +-1 (one after the other). For each
# phase of the motion (who runs), the progresses are affine in (d, time), so
# each pair of regions (and each sign of each cycle's mismatch) collides for
# d in an interval that Fourier-Motzkin elimination of the time gives
# exactly. The good set is [-1, 1] minus the union of these (open, in
# union) intervals: if it is not empty it holds an end point of one of them,
# -1, 1, or the midpoint of two consecutive end points; we try those.


def _phases(sign):
    """(pA, pB, bounds) for d of this sign; affine forms in d, t as dicts."""
    one, t, d = {"": Fraction(1)}, {"t": Fraction(1)}, {"d": Fraction(1)}
    zero = {}
    t_minus_d = {"t": Fraction(1), "d": Fraction(-1)}
    if sign > 0:  # A runs [0, 1], B runs [d, 1 + d], 0 <= d <= 1
        dom = [d, {"": Fraction(1), "d": Fraction(-1)}]
        return [(t, zero, dom + [t, {"d": Fraction(1), "t": Fraction(-1)}]),
                (t, t_minus_d, dom + [t_minus_d, {"": Fraction(1), "t": Fraction(-1)}]),
                (one, t_minus_d, dom + [{"t": Fraction(1), "": Fraction(-1)}, {"": Fraction(1), "d": Fraction(1), "t": Fraction(-1)}])]
    dom = [{"d": Fraction(-1)}, {"": Fraction(1), "d": Fraction(1)}]  # -1 <= d <= 0
    return [(zero, t_minus_d, dom + [t_minus_d, {"t": Fraction(-1)}]),
            (t, t_minus_d, dom + [t, {"": Fraction(1), "d": Fraction(1), "t": Fraction(-1)}]),
            (t, one, dom + [{"t": Fraction(1), "d": Fraction(-1), "": Fraction(-1)}, {"": Fraction(1), "t": Fraction(-1)}])]


def _lin(form, pa, pb, qa, qb):
    """An affine form of the progresses -> a dict over d, t, ''."""
    out = {"": Fraction(form[0])}
    for q, coef in form[1].items():
        src = pa if q == qa else pb
        for k, v in src.items():
            out[k] = out.get(k, 0) + coef * v
    return out


def _d_interval(strict_forms, bounds):
    """{d : exists t, all strict_forms > 0, all bounds >= 0} as (lo, lo_open,
    hi, hi_open) or None."""
    cons = [({k: v for k, v in f.items() if k != "" and v != 0}, f.get("", Fraction(0)), True) for f in strict_forms]
    cons += [({k: v for k, v in f.items() if k != "" and v != 0}, f.get("", Fraction(0)), False) for f in bounds]
    # eliminate t with the routine above, then read the bounds on d
    pos, neg, rest = [], [], []
    for c, k, s in cons:
        a = c.get("t", 0)
        (pos if a > 0 else neg if a < 0 else rest).append((c, k, s))
    for cp, kp, sp in pos:
        for cn, kn, sn in neg:
            ap, an = cp["t"], -cn["t"]
            rest.append(({"d": cp.get("d", 0) / ap + cn.get("d", 0) / an}, kp / ap + kn / an, sp or sn))
    lo, lo_open, hi, hi_open = Fraction(-2), False, Fraction(2), False
    for c, k, s in rest:
        a = c.get("d", 0)
        if a == 0:
            if (s and k <= 0) or (not s and k < 0):
                return None
            continue
        b = -k / a  # a d + k > 0  <=>  d > b (a > 0) or d < b (a < 0)
        if a > 0 and (b > lo or (b == lo and s)):
            lo, lo_open = b, s
        if a < 0 and (b < hi or (b == hi and s)):
            hi, hi_open = b, s
    if lo > hi or (lo == hi and (lo_open or hi_open)):
        return None
    return (lo, lo_open, hi, hi_open)


def _bad_intervals(model):
    qa, qb = model.couplings
    out = []
    names = list(model.regions)
    for sign in (1, -1):
        for pa, pb, bounds in _phases(sign):
            lin = [dict(b) for b in bounds]
            for _, (mx, my) in model.cycles:
                for f in (mx, my):
                    for s in (1, -1):
                        g = _lin((s * f[0], {q: s * v for q, v in f[1].items()}), pa, pb, qa, qb)
                        iv = _d_interval([g], lin)
                        if iv:
                            out.append(iv)
            for i, a in enumerate(names):
                ra = model.regions[a]
                for b in names[i + 1:]:
                    rb = model.regions[b]
                    forms = []
                    for k in (0, 2):
                        for hi, lo in ((ra[k + 1], rb[k]), (rb[k + 1], ra[k]), (ra[k + 1], ra[k]), (rb[k + 1], rb[k])):
                            forms.append(_lin(_add(hi, lo, -1), pa, pb, qa, qb))
                    iv = _d_interval(forms, lin)
                    if iv:
                        out.append(iv)
    return out


def _inside(d, iv):
    lo, lo_open, hi, hi_open = iv
    return (lo < d or (lo == d and not lo_open)) and (d < hi or (d == hi and not hi_open))


def continuous_free_two(model):
    """Exact continuous Collision-free Schedule for exactly two couplings:
    collision-free start times {A: 0, B: d}, or None (none exist)."""
    if len(model.couplings) != 2:
        raise ValueError("two couplings only")
    bad = _bad_intervals(model)
    points = {Fraction(-1), Fraction(0), Fraction(1)}
    for lo, _, hi, _ in bad:
        points.update(x for x in (lo, hi) if -1 <= x <= 1)
    pts = sorted(points)
    cands = pts + [(x + y) / 2 for x, y in zip(pts, pts[1:])]
    qa, qb = model.couplings
    for d in sorted(cands, key=lambda x: (abs(x), x)):
        if not any(_inside(d, iv) for iv in bad):
            return {qa: Fraction(0), qb: d}
    return None


def final_collides(model):
    """Does the configuration after every operation (p = 1 for all) hold an
    overlap or a broken cycle? Then every schedule collides (the overlap
    is open in time, so it begins before the end): a proof of NO for
    Collision-free Schedule in both models."""
    p = {q: Fraction(1) for q in model.couplings}
    if _cycle_mismatch(model, p):
        return True
    boxes = _boxes_at(model, p)
    names = list(boxes)
    for i, a in enumerate(names):
        for b in names[i + 1:]:
            x, y = boxes[a], boxes[b]
            if max(x[0], y[0]) < min(x[1], y[1]) and max(x[2], y[2]) < min(x[3], y[3]):
                return True
    return False
