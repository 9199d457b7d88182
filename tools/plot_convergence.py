#!/usr/bin/env python3
"""Draws a convergence CSV of `glint converge` as two log-log charts against time: relative
MSE, the mean of (a - r)^2 / (r^2 + 0.01), and RMSE. Each variant's rungs are drawn with
their spread (the fastest and slowest repeat of a rung), its fitted line with a band of
one standard error of the slope (pivoting about the points' centroid, through which the
fit passes), and two guides: Monte Carlo's rate (error^2 ~ 1/N, RMSE ~ N^-1/2) and the
rate a low-discrepancy sampler reaches where the integrand is smooth (error^2 ~ 1/N^2,
RMSE ~ 1/N). Relative MSE is the measure to compare by: plain RMSE of an HDR image is
dominated by the few pixels on the light's edge. The slopes are glint converge's own."""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def panel(ax, rows, variants, metric, slope_key, label, power):
    """power: the error's exponent of N under plain Monte Carlo (1 for MSE, 0.5 for RMSE)."""
    anchor = None
    t_all = np.array([float(r["seconds"]) for r in rows if float(r["seconds"]) > 0])
    for i, name in enumerate(variants):
        sel = [r for r in rows if r["variant"] == name]
        t = np.array([float(r["seconds"]) for r in sel])
        e = np.array([float(r[metric]) for r in sel])
        ok = (t > 0) & (e > 0)
        if not ok.any():
            continue
        t, e = t[ok], e[ok]
        lo = np.array([float(r["seconds_min"]) for r in sel])[ok]
        hi = np.array([float(r["seconds_max"]) for r in sel])[ok]
        slope = float(sel[0][slope_key])
        se = float(sel[0][slope_key + "_se"])
        colour = f"C{i}"
        ax.errorbar(t, e, xerr=[t - lo, hi - t], fmt="o", color=colour, ms=4, capsize=2,
                    label=f"{name}: slope {slope:.2f} ± {se:.2f}")
        if len(t) >= 2 and np.isfinite(slope):
            cx, cy = np.log(t).mean(), np.log(e).mean()
            xs = np.linspace(np.log(t).min(), np.log(t).max(), 50)
            ax.plot(np.exp(xs), np.exp(cy + slope * (xs - cx)), "-", color=colour, lw=1.2)
            # On a busy machine the slope's error can be huge (thousands): the band is
            # kept within the data's decades, not sent to overflow (exp of 1e5).
            floor, ceiling = np.log(e.min()) - 3.0, np.log(e.max()) + 3.0
            band = [np.exp(np.clip(cy + (slope + s * se) * (xs - cx), floor, ceiling))
                    for s in (-1, 1)]
            ax.fill_between(np.exp(xs), np.minimum(*band), np.maximum(*band), color=colour,
                            alpha=0.2, lw=0)
        if anchor is None:
            anchor = (t[0], e[0])
    if anchor is not None and len(t_all):
        t0, e0 = anchor
        ts = np.array([t_all.min(), t_all.max()])
        ax.loglog(ts, e0 * (t0 / ts) ** power, "k--", lw=1,
                  label=f"Monte Carlo's rate: t^-{power:g}")
        ax.loglog(ts, e0 * (t0 / ts) ** (2 * power), "k:", lw=1,
                  label=f"smooth integrand, low discrepancy: t^-{2 * power:g}")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("render time (s): median of a rung's repeats, bars from fastest to slowest")
    ax.set_ylabel(label + " against the reference")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7)


def main(csv_path, png_path):
    rows = list(csv.DictReader(open(csv_path)))
    variants = []
    for r in rows:
        if r["variant"] not in variants:
            variants.append(r["variant"])
    fig, axes = plt.subplots(1, 2, figsize=(12, 5), dpi=100)
    panel(axes[0], rows, variants, "rel_mse", "slope_rel_mse_time", "relative MSE", 1.0)
    panel(axes[1], rows, variants, "rmse", "slope_rmse_time", "RMSE", 0.5)
    busy = max((float(r["other_cores"]) for r in rows), default=0.0)
    note = (f"; the machine was busy: other processes took up to {busy:.0%} of a core"
            if busy > 0.25 else "")
    fig.suptitle("glint: error against time (fit ± one standard error of its slope)" + note,
                 fontsize=10)
    fig.tight_layout()
    fig.savefig(png_path)


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit("usage: plot_convergence.py CSV PNG")
    main(*sys.argv[1:])
