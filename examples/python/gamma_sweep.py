"""The certified bound against the uncertainty: gamma versus delta_bar for the paper's plant
(configs/paper-dbar0.05.yaml), each point a full synthesis with its certificate
(`hinf-synth sweep --param delta_bar=...`); points that are not certified are marked.

    PYTHONPATH=build/python python3 examples/python/gamma_sweep.py --points 21 -o gamma-vs-dbar.png
"""
import argparse
import os

import matplotlib
matplotlib.use("Agg")  # files only: no display needed
import matplotlib.pyplot as plt
import numpy as np

import hinf

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--config", default=os.path.join(ROOT, "configs", "paper-dbar0.05.yaml"))
    ap.add_argument("--lo", type=float, default=0.0)
    ap.add_argument("--hi", type=float, default=1.0)
    ap.add_argument("--points", type=int, default=11)
    ap.add_argument("-o", "--output", default="gamma-vs-dbar.png")
    a = ap.parse_args()

    s = hinf.sweep(a.config, "delta_bar", np.linspace(a.lo, a.hi, a.points))
    ok = np.isfinite(s["gamma"])
    fig, ax = plt.subplots(figsize=(8, 4.8))
    ax.semilogy(s["value"][ok], s["gamma"][ok], "o-", color="#d62728", label="certified gamma")
    floor = np.nanmin(s["gamma"]) if ok.any() else 1.0
    if (~ok).any():
        ax.semilogy(s["value"][~ok], np.full((~ok).sum(), floor), "x", color="k", ms=9,
                    label="not certified (exit %s)" % sorted(set(s["exit_code"][~ok].tolist())))
    ax.set_xlabel("delta_bar (relative error of the orbital rate)")
    ax.set_ylabel("certified gamma")
    ax.set_title("%s: certified H-infinity bound" % os.path.basename(a.config))
    ax.grid(True, which="both", alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(a.output, dpi=120)
    for v, g, c in zip(s["value"], s["gamma"], s["exit_code"]):
        print("delta_bar = %-6g gamma = %-12.10g exit %d" % (v, g, c))
    print("wrote", a.output)


if __name__ == "__main__":
    main()
