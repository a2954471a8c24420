"""gridlock: collision detection for modular robots, from Python.

The C++ library's public facade (docs/python.md): instances and the exact
simulator, the discrete and continuous solvers, Colliding Schedule, the gap
checker, formulas (DIMACS, generators, LSAT, CaDiCaL), the reduction with its
certificates, verify and fuzz campaigns, and the animation page.

Exact values stay exact (int, fractions.Fraction); bad input raises
gridlock.Error ("FILE:LINE: what is wrong"); long calls release the GIL and
stop on Ctrl-C (KeyboardInterrupt).
"""
from __future__ import annotations

from dataclasses import dataclass, field
from fractions import Fraction
from typing import Callable, Dict, List, Optional, Sequence, Tuple, Union

from . import _core
from ._core import (  # noqa: F401  (re-exported)
    Compiled,
    Error,
    Formula,
    Instance,
    LsatReduction,
    animate,
    compile,
    fuzz_formula,
    planted_ksat,
    random_instance,
    random_ksat,
    random_lsat,
    to_lsat,
)

__all__ = [
    "Collision", "SolveResult", "CertifyResult", "certify", "CollideResult", "GapsResult", "SatResult",
    "Compiled", "Error", "Formula", "Instance", "LsatReduction",
    "animate", "collide", "compile", "fuzz", "fuzz_formula", "gaps", "lift",
    "planted_ksat", "random_instance", "random_ksat", "random_lsat",
    "sat_solve", "simulate", "solve", "to_lsat", "verify",
]

Times = Dict[str, Fraction]


@dataclass
class Collision:
    """The first collision of a schedule (docs/model.md)."""

    kind: str                      # "node" or "cycle"
    time: Fraction                 # its first moment, exact
    moving: List[str]              # couplings running right after `time`
    regions: Optional[Tuple[str, str]] = None  # node collision: the two regions
    cycle: Optional[List[str]] = None          # cycle collision: the face walk


@dataclass
class SolveResult:
    """solve(): status "YES" (with order or times), "NO" or "UNKNOWN" (a limit)."""

    status: str
    model: str
    engine: str
    order: Optional[List[str]] = None  # discrete YES: every coupling once
    times: Optional[Times] = None      # continuous YES: a start time per coupling
    stats: Dict[str, float] = field(default_factory=dict)
    cycle_breaker: Optional[str] = None  # discrete NO because this coupling breaks a cycle
    lone_collider: Optional[str] = None  # NO because this coupling alone moves lone_pair into a collision
    lone_pair: Optional[str] = None      # e.g. "node (1,2) and node inserted by a"
    certificate: Optional[str] = None       # NO with certificate=True: the text certify() checks
    certificate_note: Optional[str] = None  # NO with certificate=True but none written: why

    def __bool__(self) -> bool:
        return self.status == "YES"


@dataclass
class CertifyResult:
    """certify(): proved is True when the certificate proves NO (docs/certificates.md)."""

    proved: bool
    kind: str                    # breaker, gaps, final-gap or final-cycle (once read)
    lemmas: int                  # gaps: lemma lines checked
    reason: Optional[str] = None  # not proved: what failed ("line N: ..." where a line is to blame)

    def __bool__(self) -> bool:
        return self.proved


@dataclass
class CollideResult:
    """collide(): status "YES" with a colliding schedule the simulator checked, or "NO"."""

    status: str
    model: str
    algorithm: str
    complexity: str
    collision: Optional[Collision] = None
    order: Optional[List[str]] = None
    times: Optional[Times] = None
    certificate: Optional[str] = None       # NO with certificate=True: the text certify() checks
    certificate_note: Optional[str] = None  # NO with certificate=True but none written: why
    # YES confirmed at this one moment (the pair overlaps in the simulator's
    # configuration) instead of a full simulation: one coupling, one axis
    checked_at: Optional[Fraction] = None

    def __bool__(self) -> bool:
        return self.status == "YES"


@dataclass
class GapsResult:
    """gaps(): the linear-time continuous check of horizontal-only instances."""

    status: str          # "YES": every coupling at time 0 is collision-free
    explanation: str
    gaps_checked: int
    negative_gaps: int
    cycles_checked: int
    open_cycles: int
    gap: Optional[dict] = None    # NO by a gap: row, left, right, sizes, widened_by, narrowed_by
    cycle: Optional[dict] = None  # NO by a cycle: nodes, mismatch

    def __bool__(self) -> bool:
        return self.status == "YES"


@dataclass
class SatResult:
    """sat_solve(): CaDiCaL's answer; model as DIMACS literals, checked against the formula."""

    status: str  # "SATISFIABLE", "UNSATISFIABLE", "UNKNOWN"
    model: Optional[List[int]]
    seconds: float
    solver: str

    def __bool__(self) -> bool:
        return self.status == "SATISFIABLE"


def _collision(d: Optional[dict]) -> Optional[Collision]:
    return None if d is None else Collision(**d)


def simulate(instance: Instance, order: Optional[Sequence[str]] = None,
             times: Optional[Dict[str, Union[int, Fraction, str]]] = None) -> Optional[Collision]:
    """Runs one schedule through the exact simulator: the first collision, or None.

    order: every coupling name once (discrete); times: {coupling: start time}
    with exact values (int, Fraction or "a/b"), continuous.
    """
    return _collision(_core.simulate(instance, order=_names(order), times=times))


def solve(instance: Instance, model: str = "discrete", engine: str = "auto",
          timeout: Optional[float] = None, max_states: int = 0,
          certificate: bool = False) -> SolveResult:
    """Decides Collision-free Schedule exactly (docs/solver.md).

    model "discrete" (an order) or "continuous" (start times); engine: discrete
    "auto", "states", "precedence", "sat" or "pairs", continuous "auto", "sat"
    or "z3"; timeout in seconds and max_states give "UNKNOWN" when reached.
    certificate=True: a NO carries the text of its NO certificate where one can
    be written (else certificate_note says why), for certify(). Ctrl-C raises
    KeyboardInterrupt.
    """
    return SolveResult(**_core.solve(instance, model=model, engine=engine, timeout=timeout,
                                     max_states=max_states, certificate=certificate))


def certify(instance: Instance, certificate: str, model: str = "discrete") -> CertifyResult:
    """Checks a NO certificate with the independent checker (certify/, which
    shares no code with the solvers): proved, or the reason it is rejected."""
    return CertifyResult(**_core.certify(instance, certificate, model=model))


def collide(instance: Instance, model: str = "discrete", method: str = "auto",
            certificate: bool = False) -> CollideResult:
    """Colliding Schedule (docs/collide.md): is there a schedule that collides?

    certificate=True: a NO carries the text of its certificate (no schedule
    collides; docs/certificates.md, "Collide certificates") for certify(), or
    certificate_note says why there is none (a limit reached; or a discrete
    NO whose continuous pair test found an overlap, which docs/collide.md,
    "Colliding Schedule: the models agree", proves to be a bug)."""
    d = _core.collide(instance, model=model, method=method, certificate=certificate)
    d["collision"] = _collision(d["collision"])
    d["checked_at"] = None if d["checked_at"] is None else Fraction(d["checked_at"])
    return CollideResult(**d)


def gaps(instance: Instance) -> GapsResult:
    """The linear-time gap check (continuous model, horizontal-only instances)."""
    return GapsResult(**_core.gaps(instance))


def sat_solve(formula: Formula, timeout: Optional[float] = None, conflicts: int = -1) -> SatResult:
    """CaDiCaL on the formula; a limit gives "UNKNOWN"."""
    return SatResult(**_core.sat_solve(formula, timeout=timeout, conflicts=conflicts))


def lift(compiled: Compiled, assignment: Optional[Sequence[int]] = None,
         order: Optional[Sequence[str]] = None, times: Optional[Dict] = None):
    """The reduction's certificates, both ways (reductions/compile.hpp).

    lift(c, assignment=[1, -2, 3]) -> the order (discrete) or start times
    (continuous) that the assignment gives; lift(c, order=...) or
    lift(c, times=...) -> the assignment (DIMACS literals) read off a
    schedule. The maps are not checked here: run the schedule with simulate()
    and the assignment with Formula.satisfies().
    """
    return compiled.lift(assignment=assignment, order=_names(order), times=times)


def verify(formulas: Sequence[Union[Formula, str]], names: Optional[Sequence[str]] = None,
           model: str = "discrete", timeout: float = 60.0, max_states: int = 0, direct: bool = False,
           jobs: Optional[int] = None, progress: Optional[Callable[[dict], None]] = None) -> dict:
    """Checks the reduction end to end on each formula (docs/verify.md).

    formulas: Formula objects or DIMACS paths. Returns the record of
    `gridlock verify --json` (rows under "formulas", the "summary");
    progress(row) is called after each formula, in order. jobs: worker
    threads (None: the cores available, like --jobs); the result is the
    same for every number.
    """
    return _core.verify(list(formulas), names=None if names is None else list(names), model=model,
                        timeout=timeout, max_states=max_states, direct=direct, jobs=jobs, progress=progress)


def fuzz(count: int = 1000, seed: int = 1, min_vars: int = 3, max_vars: int = 6,
         kinds: Sequence[str] = ("mix",), model: str = "discrete", timeout: float = 10.0,
         max_states: int = 2000000, direct: bool = False, keep_going: bool = False, time: float = 0.0,
         jobs: Optional[int] = None, progress: Optional[Callable[[dict], None]] = None) -> dict:
    """A fuzz campaign over formulas 0..count-1 of the seed (docs/verify.md).

    Returns the counts of `gridlock fuzz --json` (formulas, sat, unsat, unknown,
    certificates_checked, disagreements, findings, status); progress(tally) is
    called after each formula. jobs: worker threads (None: the cores
    available, like --jobs); the counts are the same for every number. The
    defaults are the command line's.
    """
    return _core.fuzz(count=count, seed=seed, min_vars=min_vars, max_vars=max_vars, kinds=list(kinds),
                      model=model, timeout=timeout, max_states=max_states, direct=direct,
                      keep_going=keep_going, time=time, jobs=jobs, progress=progress)


def _names(order):
    if order is None or isinstance(order, str):
        return order  # one string is refused by the module with a clear message
    return [str(n) for n in order]
