"""The paper's navigation experiment from Python: the certified H-infinity filter (delta_bar =
0.05) beside the paper's published gains, the EKF, the EKF that ignores the thrust and the
REKF, on the nonlinear two-body truth under orbit control (configs/scenarios/paper-control.yaml;
docs/experiments.md). Draws each filter's position error against time as its RMS over a
sliding window (--window, s), run 0 as a line and, with --runs N > 1, the band between the
runs' smallest and largest.

    PYTHONPATH=build/python python3 examples/python/paper_navigation.py --runs 5 -o navigation.png
"""
import argparse
import os

import matplotlib
matplotlib.use("Agg")  # files only: no display needed
import matplotlib.pyplot as plt
import numpy as np

import hinf

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
FILTERS = ["hinf", "published", "ekf", "ekf_no_control", "rekf"]


def position_errors(trajectory):
    """|estimate - truth| of the position for each filter in the trajectory table (NaN after a divergence)."""
    truth = np.column_stack([trajectory["true_" + a] for a in "xyz"])
    out = {}
    for f in FILTERS:
        if f + "_x" in trajectory.dtype.names:
            est = np.column_stack([trajectory[f + "_" + a] for a in "xyz"])
            out[f] = np.linalg.norm(est - truth, axis=1)
    return out


def moving_rms(e, samples):
    """sqrt of the mean of e^2 over the trailing `samples` (fewer at the start); NaN stays NaN."""
    c = np.cumsum(np.concatenate([[0.0], e * e]))
    k = np.arange(1, len(e) + 1)
    lo = np.maximum(k - samples, 0)
    return np.sqrt((c[k] - c[lo]) / (k - lo))


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--scenario", default=os.path.join(ROOT, "configs", "scenarios", "paper-control.yaml"))
    ap.add_argument("--runs", type=int, default=1)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--duration", type=float, default=None, help="s (default: the scenario's)")
    ap.add_argument("--window", type=float, default=20.0, help="s, the sliding RMS window")
    ap.add_argument("-o", "--output", default="navigation.png")
    a = ap.parse_args()

    # One campaign of one run per seed S, S + 1, ... so that every run's trajectory is at hand
    # (a campaign of N runs keeps run 0's trajectory only, and derives its runs' seeds from S).
    runs = [hinf.simulate(a.scenario, runs=1, seed=a.seed + i, duration=a.duration) for i in range(a.runs)]
    t = runs[0].table("trajectory.csv")["t"]
    samples = max(1, int(round(a.window / (t[1] - t[0]))))
    errors = [{f: moving_rms(e, samples) for f, e in position_errors(c.table("trajectory.csv")).items()} for c in runs]

    fig, ax = plt.subplots(figsize=(9, 5.2))
    for f in errors[0]:
        line, = ax.semilogy(t, errors[0][f], lw=1.2, label=f)
        if len(errors) > 1:
            stack = np.vstack([e[f] for e in errors])
            ax.fill_between(t, np.nanmin(stack, axis=0), np.nanmax(stack, axis=0), color=line.get_color(), alpha=0.15)
    ax.axhline(1.0, color="k", ls=":", lw=1, label="1 m")
    ax.set_xlabel("t (s)")
    ax.set_ylabel("position error, RMS over %g s (m)" % a.window)
    ax.set_title("relative navigation, %s: %d run(s) from seed %d" % (os.path.basename(a.scenario), a.runs, a.seed))
    ax.grid(True, which="both", alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(a.output, dpi=120)
    summary = runs[0].summary
    print("wrote %s; run 0 steady-state position RMS (m):" % a.output,
          {f: summary["filters"][f]["position_rms_m"] for f in summary.get("filters", {})})


if __name__ == "__main__":
    main()
