#!/usr/bin/env python3
"""How does the exact solvers' time grow with formula size?

Random 3-SAT at clause/variable ratio 4.26 (the threshold, so both answers
occur), n variables, several seeds per n. Each formula is compiled by the
paper's reduction as it is (no to-lsat first, as `gridlock verify --direct`
does: the instances stay small), for discrete time and for continuous time
(with its separation gadget), and the compiled instance is solved exactly;
CaDiCaL's answer on the formula labels it SAT or UNSAT and the solvers'
answers must agree with it. Plots every solve time and the median per size,
SAT and UNSAT apart, into a PNG.

    PYTHONPATH=build/python /usr/bin/python3 examples/python/solve_time_growth.py [--quick] [OUT.png]

--quick: two sizes per solver and two seeds (a few seconds; the tests run it).

About a minute on one core (the continuous solver stays at 3-5 variables:
beyond that Z3 needs much longer today; docs/python.md). Seeded: the same
formulas on every machine.
"""
import statistics
import sys
import time

import matplotlib

matplotlib.use("Agg")  # files only, no display needed
import matplotlib.pyplot as plt  # noqa: E402

import gridlock  # noqa: E402

SEEDS = {"discrete": range(1, 11), "continuous": range(1, 6)}
SIZES = {"discrete": [5, 10, 20, 30, 40, 50, 60, 80, 100], "continuous": [3, 4, 5, 6]}
TIMEOUT = 20.0


def measure(model, n, seed):
    """(SAT?, seconds of solve) for one formula, its answer checked."""
    f = gridlock.random_ksat(n=n, m=round(4.26 * n), seed=seed)
    sat = bool(gridlock.sat_solve(f))
    compiled = gridlock.compile(f, model=model)
    start = time.perf_counter()
    r = gridlock.solve(compiled.instance, model=model, timeout=TIMEOUT)
    seconds = time.perf_counter() - start
    if r.status == "UNKNOWN":
        return sat, None
    assert (r.status == "YES") == sat, f"{model} n={n} seed={seed}: solver {r.status}, CaDiCaL {sat}"
    return sat, seconds


def main(out):
    fig, ax = plt.subplots(figsize=(7.5, 4.8))
    colors = {"discrete": "tab:blue", "continuous": "tab:red"}
    for model, sizes in SIZES.items():
        runs = {True: {}, False: {}}  # SAT? -> n -> [seconds]
        unknown = 0
        for n in sizes:
            for seed in SEEDS[model]:
                sat, secs = measure(model, n, seed)
                if secs is None:
                    unknown += 1
                else:
                    runs[sat].setdefault(n, []).append(secs)
        for answer, marker, style in ((True, "o", "-"), (False, "s", "--")):
            word = "SAT" if answer else "UNSAT"
            points = runs[answer]
            xs = sorted(points)
            ys = [statistics.median(points[n]) for n in xs]
            for n in xs:
                print(f"{model:10} n={n:2} {word:5} median {statistics.median(points[n]) * 1e3:9.2f} ms "
                      f"over {len(points[n])} formulas", flush=True)
            ax.scatter([n for n in xs for _ in points[n]], [t for n in xs for t in points[n]], marker=marker,
                       s=14, alpha=0.35, color=colors[model])
            ax.plot(xs, ys, style, marker=marker, color=colors[model], label=f"{model}, {word} (median)")
        if unknown:
            print(f"{model}: {unknown} formulas hit the {TIMEOUT:.0f} s limit (left out)")
    ax.set_yscale("log")
    ax.set_xscale("log")
    ticks = sorted({n for sizes in SIZES.values() for n in sizes})
    ax.set_xticks(ticks, [str(n) for n in ticks])
    ax.minorticks_off()
    ax.set_xlabel("variables n of the random 3-SAT formula (m = round(4.26 n), compiled directly)")
    ax.set_ylabel("exact solve time (s); dots: one formula each")
    ax.set_title("gridlock: exact Collision-free Schedule solvers on compiled 3-SAT")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(out, dpi=100)
    print(f"wrote {out}")


if __name__ == "__main__":
    args = sys.argv[1:]
    if "--quick" in args:
        args.remove("--quick")
        SEEDS = {"discrete": range(1, 3), "continuous": range(1, 3)}
        SIZES = {"discrete": [5, 10], "continuous": [3]}
    main(args[0] if args else "solve-time-growth.png")
