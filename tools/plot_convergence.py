#!/usr/bin/env python3
"""Draws a convergence CSV of `glint converge` as two log-log charts against time: RMSE
(with the 1/sqrt(t) slope) and relative MSE, the mean of (a - r)^2 / (r^2 + 0.01) (with the
1/t slope), and prints each variant's fitted slopes. Relative MSE is the measure to compare
by: plain RMSE of an HDR image is dominated by the few pixels on the light's edge."""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def panel(ax, rows, variants, metric, label, power):
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
        ax.loglog(ts, e0 * (t0 / ts) ** power, "k--", label=f"1/t^{power:g}")
    ax.set_xlabel("render time (s)")
    ax.set_ylabel(label + " against the reference")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)


def main(csv_path, png_path):
    rows = list(csv.DictReader(open(csv_path)))
    variants = []
    for r in rows:
        if r["variant"] not in variants:
            variants.append(r["variant"])
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.6), dpi=100)
    panel(axes[0], rows, variants, "rel_mse", "relative MSE", 1.0)
    panel(axes[1], rows, variants, "rmse", "RMSE", 0.5)
    fig.suptitle("glint: error against time")
    fig.tight_layout()
    fig.savefig(png_path)


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit("usage: plot_convergence.py CSV PNG")
    main(*sys.argv[1:])
