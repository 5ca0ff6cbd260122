#!/usr/bin/env python3
"""Plots of the benchmark from bench/results/results.tsv (written by `moa_bench report`).

    python3 bench/plot.py RESULTS.tsv OUTDIR

writes OUTDIR/time_vs_points.png, OUTDIR/memory_vs_points.png and OUTDIR/min_angle.png.
Needs python3-matplotlib; run_bench.sh calls it and skips the plots without it.
"""
import csv
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")  # no display on a build machine
import matplotlib.pyplot as plt  # noqa: E402

METHODS = [  # key in results.tsv, label, colour
    ("moa", "libmoa", "tab:red"),
    ("cgal", "CGAL advancing front", "tab:blue"),
    ("o3d_bpa", "Open3D ball pivoting", "tab:green"),
    ("o3d_poisson", "Open3D Poisson (depth 9)", "tab:purple"),
    ("pcl_gp3", "PCL greedy projection", "tab:orange"),
]
SERIES = "bunny00"  # the inputs joined by lines: this mesh's vertices and uniform samples
ANGLE_INPUTS = ["bunny00-vertices", "bunny00-uniform-100k", "bunny00-noise-100k"]
DPI = 110


def number(text):
    try:
        return float(text)
    except (TypeError, ValueError):
        return None


def read(path):
    with open(path, newline="") as f:
        lines = list(csv.reader(f, delimiter="\t"))
    header = [c.lstrip("#") for c in lines[0]]
    return [dict(zip(header, row)) for row in lines[1:] if row]


def successful(rows, method):
    return [r for r in rows if r["method"] == method and r["status"] in ("ok", "not analysed")]


def legend(ax):
    if ax.get_legend_handles_labels()[0]:  # nothing drawn: no legend (and no warning)
        ax.legend(fontsize=8, loc="upper left")


def scaling_plot(ax, rows, value, ylabel, title):
    """One line per method through the SERIES inputs, every other input as a faint dot."""
    for key, label, colour in METHODS:
        runs = [r for r in successful(rows, key) if number(value(r))]
        if not runs:
            continue
        line = sorted((float(r["points"]), value(r)) for r in runs
                      if r["source"] == SERIES and r["kind"] in ("vertices", "uniform"))
        others = [(float(r["points"]), value(r)) for r in runs
                  if not (r["source"] == SERIES and r["kind"] in ("vertices", "uniform"))]
        if line:
            ax.plot([p for p, _ in line], [v for _, v in line], "o-", color=colour, label=label)
        if others:  # labelled only when the method has no line
            ax.plot([p for p, _ in others], [v for _, v in others], ".", color=colour, alpha=0.35,
                    label=None if line else label)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("input points")
    ax.set_ylabel(ylabel)
    ax.set_title(title, fontsize=10)
    ax.grid(True, which="both", alpha=0.3)


def time_plot(rows, out):
    fig, axes = plt.subplots(1, 2, figsize=(12, 4.8), sharey=True)
    scaling_plot(axes[0], rows, lambda r: number(r["recon_s"]), "wall time (s)",
                 "reconstruction only")
    scaling_plot(axes[1], rows, lambda r: number(r["total_s"]), "wall time (s)",
                 "reconstruction + normal estimation (when the method needs normals)")
    legend(axes[0])
    fig.suptitle(f"Time against input size (lines: {SERIES} vertices and uniform samples; "
                 "dots: the other inputs)", fontsize=11)
    fig.tight_layout()
    fig.savefig(out / "time_vs_points.png", dpi=DPI)
    plt.close(fig)


def memory_plot(rows, out):
    fig, ax = plt.subplots(figsize=(7, 4.8))
    scaling_plot(ax, rows, lambda r: number(r["peak_mb"]), "peak resident memory (MB)",
                 f"Peak memory of each run's process (lines: {SERIES}; dots: other inputs)")
    legend(ax)
    fig.text(0.01, 0.01, "Open3D Poisson reuses the ball-pivoting run's normals: its peak leaves "
             "the normal estimation out.", fontsize=7, color="dimgray")
    fig.tight_layout(rect=(0, 0.03, 1, 1))
    fig.savefig(out / "memory_vs_points.png", dpi=DPI)
    plt.close(fig)


def histogram(row):
    counts = [float(c) for c in row.get("angle_histogram", "").split()]
    total = sum(counts)
    return [c / total for c in counts] if total else None


def angle_plot(rows, out):
    present = [name for name in ANGLE_INPUTS
               if any(r["input"] == name and r["method"] != "reference" for r in rows)]
    columns = 2 if len(present) >= 2 else len(present) + 1
    grid_rows = (len(present) + 1 + columns - 1) // columns
    fig, grid = plt.subplots(grid_rows, columns, figsize=(6.2 * columns, 4.6 * grid_rows), squeeze=False)
    axes = list(grid.flat)
    for ax in axes[len(present) + 1:]:
        ax.set_visible(False)
    axes = axes[:len(present) + 1]
    edges = [5 * i for i in range(13)]
    for ax, name in zip(axes, present):
        for key, label, colour in [("reference", "reference mesh", "black")] + METHODS:
            row = next((r for r in rows if r["input"] == name and r["method"] == key), None)
            # The reference's angles compare only with meshes of its own vertices.
            if key == "reference" and row and row["kind"] != "vertices":
                continue
            shares = histogram(row) if row else None
            if not shares:
                continue
            style = "--" if key == "reference" else "-"
            ax.stairs(shares, edges, color=colour, linestyle=style, linewidth=1.6, label=label)
        ax.set_title(name, fontsize=10)
        ax.set_xlabel("smallest angle of the triangle (degrees)")
        ax.set_ylabel("share of triangles per 5° bin")
        ax.set_xticks(range(0, 61, 10))
        ax.grid(True, alpha=0.3)
    legend(axes[0])

    # Shares below 10, 20 and 30 degrees pooled over the inputs every method meshed.
    ax = axes[-1]
    inputs = {r["input"] for r in rows if r["method"] == "moa"}
    for key, _, _ in METHODS:
        have = {r["input"] for r in successful(rows, key) if histogram(r)}
        if have:
            inputs &= have
    width = 0.8 / len(METHODS)
    for i, (key, label, colour) in enumerate(METHODS):
        pooled = [0.0] * 12
        for r in successful(rows, key):
            if r["input"] in inputs and r["angle_histogram"]:
                pooled = [a + float(b) for a, b in zip(pooled, r["angle_histogram"].split())]
        total = sum(pooled)
        if not total:
            continue
        shares = [100 * sum(pooled[:k]) / total for k in (2, 4, 6)]
        ax.bar([j + i * width for j in range(3)], shares, width, color=colour, label=label)
    ax.set_xticks([j + 0.4 - width / 2 for j in range(3)], ["< 10°", "< 20°", "< 30°"])
    ax.set_ylabel("% of triangles")
    ax.set_title(f"all {len(inputs)} inputs every method meshed, pooled", fontsize=10)
    ax.grid(True, axis="y", alpha=0.3)
    fig.suptitle("Smallest angle per triangle", fontsize=11)
    fig.tight_layout()
    fig.savefig(out / "min_angle.png", dpi=DPI)
    plt.close(fig)


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    rows = read(sys.argv[1])
    out = Path(sys.argv[2])
    out.mkdir(parents=True, exist_ok=True)
    time_plot(rows, out)
    memory_plot(rows, out)
    angle_plot(rows, out)
    print(f"wrote {out}/time_vs_points.png, memory_vs_points.png, min_angle.png")


if __name__ == "__main__":
    main()
