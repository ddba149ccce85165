#!/usr/bin/env python3
"""Plots clrender_error_bench's JSON (docs/error-benchmark.json) as docs/error-benchmark.png.

One panel per scene: median kernel time against RMSE, both on log scales, float and double
marked differently, and the Pareto front (the settings no other setting beats on both time
and RMSE) drawn as a line whose points are labelled with their samples per pixel. The right
axis reads the same heights as PSNR.

    scripts/plot_error_bench.py docs/error-benchmark.json docs/error-benchmark.png
"""
import argparse
import json
import math

import matplotlib

matplotlib.use("Agg")  # files only: no display on build machines
import matplotlib.pyplot as plt  # noqa: E402  (after the backend is chosen)
import numpy as np  # noqa: E402  (comes with matplotlib)
from matplotlib.lines import Line2D  # noqa: E402
from matplotlib.ticker import FuncFormatter, LogLocator, MultipleLocator, NullLocator  # noqa: E402

STYLE = {
    "float": {"marker": "o", "color": "tab:blue"},
    "double": {"marker": "s", "color": "tab:orange"},
}


# The right axis: PSNR = 20 log10(255 / RMSE). matplotlib passes arrays, whose values may lie
# outside the data (0 included), so the RMSE is kept above 0.
def rmse_to_psnr(values):
    values = np.maximum(np.asarray(values, dtype=float), 1e-12)
    return 20 * np.log10(255 / values)


def psnr_to_rmse(values):
    return 255 / 10 ** (np.clip(np.asarray(values, dtype=float), -200, 200) / 20)


# Log axes labelled 1, 2, 5, 10, 20, ... in plain numbers, which read faster than powers of ten
# over the two or three decades a panel spans.
PLAIN = FuncFormatter(lambda value, _: f"{value:g}")


def plain_log_axis(axis):
    axis.set_major_locator(LogLocator(base=10, subs=(1, 2, 5)))
    axis.set_major_formatter(PLAIN)
    axis.set_minor_formatter(FuncFormatter(lambda *_: ""))


def plottable(settings):
    """The settings that a log scale can show: an RMSE of 0 (identical to the reference) cannot."""
    return [s for s in settings if s["rmse"] > 0 and s["kernel_ms"] > 0]


def plot_points(ax, settings):
    for precision, style in STYLE.items():
        points = [s for s in settings if s["precision"] == precision]
        ax.scatter(
            [s["kernel_ms"] for s in points],
            [s["rmse"] for s in points],
            marker=style["marker"],
            color=style["color"],
            s=[46 if s["pareto"] else 22 for s in points],
            alpha=[1.0 if s["pareto"] else 0.45 for s in points],
            zorder=3,
        )


def plot_front(ax, settings):
    front = sorted((s for s in settings if s["pareto"]), key=lambda s: s["kernel_ms"])
    ax.plot([s["kernel_ms"] for s in front], [s["rmse"] for s in front], color="black", linewidth=1, zorder=2)
    for s in front:
        # "d" marks a double-precision point, so that the label alone names the setting.
        # Float labels go above a point and double ones below it, so that a float and a double
        # point at the same place stay readable.
        double = s["precision"] == "double"
        label = f'{s["spp"]}' + ("d" if double else "")
        ax.annotate(label, (s["kernel_ms"], s["rmse"]), textcoords="offset points", xytext=(5, -11 if double else 4),
                    fontsize=8)


def plot_scene(ax, scene, reference_spp):
    settings = plottable(scene["settings"])
    plot_points(ax, settings)
    plot_front(ax, settings)
    ax.set_xscale("log")
    ax.set_yscale("log")
    plain_log_axis(ax.xaxis)
    plain_log_axis(ax.yaxis)
    ax.set_title(scene["scene"], fontsize=11)
    ax.set_xlabel("kernel time per frame (ms)")
    ax.set_ylabel(f"RMSE vs {reference_spp}-spp double (0..255)")
    ax.grid(True, which="both", linewidth=0.3, alpha=0.6)
    psnr_axis = ax.secondary_yaxis("right", functions=(rmse_to_psnr, psnr_to_rmse))
    psnr_axis.set_ylabel("PSNR (dB)")
    psnr_axis.yaxis.set_major_locator(MultipleLocator(5))
    psnr_axis.yaxis.set_major_formatter(PLAIN)
    psnr_axis.yaxis.set_minor_locator(NullLocator())


def legend_entries():
    """Stand-in artists for the legend: the scatter plots' own vary in size and shade per point."""

    def marker(precision, **style):
        return Line2D([], [], linestyle="none", marker=STYLE[precision]["marker"], color=STYLE[precision]["color"],
                      **style)

    handles = [marker("float", markersize=8), marker("double", markersize=8),
               marker("float", markersize=5, alpha=0.45), Line2D([], [], color="black", linewidth=1)]
    labels = ["float", "double", "off the front (faint, smaller)", "Pareto front"]
    return handles, labels


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("json", help="clrender_error_bench --json output")
    parser.add_argument("png", help="the plot to write")
    args = parser.parse_args()
    with open(args.json) as file:
        data = json.load(file)

    scenes = data["scenes"]
    cells = len(scenes) + 1  # one panel for the legend, which then covers no data
    columns = min(3, cells)
    rows = math.ceil(cells / columns)
    fig, axes = plt.subplots(rows, columns, figsize=(5.2 * columns, 4.0 * rows + 0.6), squeeze=False,
                             layout="constrained")
    for ax, scene in zip(axes.flat, scenes):
        plot_scene(ax, scene, data["reference_spp"])
    spare = list(axes.flat)[len(scenes):]
    for ax in spare:
        ax.axis("off")
    handles, labels = legend_entries()
    spare[0].legend(handles, labels, loc="center", frameon=False, fontsize=10, title_fontsize=10,
                    title="Pareto points labelled with\nsamples per pixel (d: double)")
    fig.suptitle(
        f'clrender: kernel time against error, {data["width"]}x{data["height"]}, '
        f'median of {data["repeat"]} frames\n({data["machine"]["opencl_device"]})',
        fontsize=12, x=0.02, ha="left",
    )
    fig.savefig(args.png, dpi=110)


if __name__ == "__main__":
    main()
