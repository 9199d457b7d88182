#!/usr/bin/env python3
"""Draws a convergence CSV of `glint converge` as a log-log chart of RMSE against time,
with the 1/sqrt(t) slope for comparison, and prints each variant's fitted slope."""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def main(csv_path, png_path, metric="rmse"):
    rows = list(csv.DictReader(open(csv_path)))
    variants = []
    for r in rows:
        if r["variant"] not in variants:
            variants.append(r["variant"])
    fig, ax = plt.subplots(figsize=(6.4, 4.8), dpi=100)
    anchor = None
    for name in variants:
        t = np.array([float(r["seconds"]) for r in rows if r["variant"] == name])
        e = np.array([float(r[metric]) for r in rows if r["variant"] == name])
        ok = (t > 0) & (e > 0)
        t, e = t[ok], e[ok]
        slope = np.polyfit(np.log(t), np.log(e), 1)[0] if len(t) >= 2 else float("nan")
        ax.loglog(t, e, "o-", label=f"{name} (slope {slope:.2f})")
        print(f"{name}: slope {slope:.3f} of log {metric} against log seconds")
        if anchor is None and len(t):
            anchor = (t[0], e[0])
    if anchor is not None:
        t0, e0 = anchor
        times = np.array([float(r["seconds"]) for r in rows if float(r["seconds"]) > 0])
        ts = np.array([times.min(), times.max()])
        ax.loglog(ts, e0 * np.sqrt(t0 / ts), "k--", label="1/sqrt(t)")
    ax.set_xlabel("render time (s)")
    ax.set_ylabel(metric.upper() + " against the reference")
    ax.set_title("glint: error against time")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(png_path)


if __name__ == "__main__":
    if len(sys.argv) < 3:
        sys.exit("usage: plot_convergence.py CSV PNG [metric]")
    main(*sys.argv[1:])
