#!/usr/bin/env python3
"""Precision-recall plot from an evaluate_segmentation CSV, in the manner of Ecins et al.
(ICRA 2016) fig. 7: one curve per method over its parameter sweep at one IoU threshold sigma,
each method's best-F point marked and labelled, iso-F contours in the background.

Usage: plot_precision_recall.py results.csv --output pr.png [--sigma 0.9] [--kind overall]
Needs matplotlib (Debian: python3-matplotlib; run with /usr/bin/python3).
"""

import argparse
import csv
import sys


def parse_arguments():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("csv", help="CSV written by evaluate_segmentation --csv")
    parser.add_argument("--output", "-o", required=True, help="PNG file to write")
    parser.add_argument("--sigma", type=float, default=0.9, help="IoU threshold (default 0.9)")
    parser.add_argument("--kind", default="overall", help="scene kind (default: overall)")
    parser.add_argument("--title", default=None)
    return parser.parse_args()


def sort_key(value):
    # Numeric sweep values in numeric order, anything else after them as text.
    try:
        return (0, float(value), "")
    except ValueError:
        return (1, 0.0, value)


def read_curves(path, sigma, kind):
    """{(method, parameter): [(value, precision, recall, f)]} for the requested sigma and kind."""
    curves = {}
    with open(path, newline="") as handle:
        reader = csv.DictReader(handle)
        required = {"method", "parameter", "value", "kind", "sigma", "precision", "recall", "f"}
        missing = required - set(reader.fieldnames or [])
        if missing:
            raise ValueError("%s: missing column(s) %s" % (path, ", ".join(sorted(missing))))
        for row in reader:
            if row["kind"] != kind or abs(float(row["sigma"]) - sigma) > 1e-9:
                continue
            key = (row["method"], row["parameter"])
            curves.setdefault(key, []).append(
                (row["value"], float(row["precision"]), float(row["recall"]), float(row["f"])))
    for points in curves.values():
        points.sort(key=lambda point: sort_key(point[0]))
    return curves


def plot(curves, sigma, kind, output, title):
    import matplotlib
    matplotlib.use("Agg")  # headless: no display needed
    import matplotlib.pyplot as plt

    figure, axes = plt.subplots(figsize=(6.5, 6))
    # Iso-F contours: P = F R / (2 R - F) for R > F / 2.
    for f_level in (0.2, 0.4, 0.6, 0.8):
        recalls = [f_level / 2 + (1 - f_level / 2) * i / 200.0 for i in range(1, 201)]
        points = [(r, f_level * r / (2 * r - f_level)) for r in recalls]
        points = [(r, p) for r, p in points if p <= 1.0]
        axes.plot([r for r, _ in points], [p for _, p in points], color="0.85", linewidth=0.8,
                  zorder=0)
        if points:
            r, p = points[-1]
            axes.annotate("F=%.1f" % f_level, (r, p), fontsize=7, color="0.6",
                          xytext=(-28, 2), textcoords="offset points")

    for (method, parameter), points in sorted(curves.items()):
        label = method if not parameter else "%s (%s)" % (method, parameter)
        recalls = [point[2] for point in points]
        precisions = [point[1] for point in points]
        line, = axes.plot(recalls, precisions, marker="o", markersize=4, label=label)
        best = max(points, key=lambda point: point[3])  # first maximum, as the tool reports it
        axes.plot([best[2]], [best[1]], marker="*", markersize=16, color=line.get_color(),
                  markeredgecolor="black", zorder=5)
        text = "F=%.2f" % best[3]
        if parameter:
            text += " (%s)" % best[0]
        # Keep labels of points near the right or top edge inside the axes.
        right = best[2] > 0.75
        axes.annotate(text, (best[2], best[1]), xytext=(-8 if right else 8, -12 if best[1] > 0.9 else 6),
                      textcoords="offset points", ha="right" if right else "left",
                      fontsize=8, color=line.get_color())

    axes.set_xlim(0.0, 1.05)
    axes.set_ylim(0.0, 1.05)
    axes.set_xlabel("Recall")
    axes.set_ylabel("Precision")
    scope = "all scenes" if kind == "overall" else "%s scenes" % kind
    axes.set_title(title or "Precision-recall, IoU > %g (%s)" % (sigma, scope))
    axes.grid(True, linewidth=0.3)
    if curves:
        axes.legend(loc="lower left", fontsize=8)
    figure.tight_layout()
    figure.savefig(output, dpi=120)
    plt.close(figure)


def main():
    arguments = parse_arguments()
    try:
        curves = read_curves(arguments.csv, arguments.sigma, arguments.kind)
    except (OSError, ValueError, KeyError) as error:
        print("plot_precision_recall.py: %s" % error, file=sys.stderr)
        return 2
    if not curves:
        print("plot_precision_recall.py: %s: no rows with kind '%s' at sigma %g"
              % (arguments.csv, arguments.kind, arguments.sigma), file=sys.stderr)
        return 2
    try:
        plot(curves, arguments.sigma, arguments.kind, arguments.output, arguments.title)
    except ImportError as error:
        print("plot_precision_recall.py: matplotlib unavailable (%s); install python3-matplotlib"
              % error, file=sys.stderr)
        return 1
    except OSError as error:
        print("plot_precision_recall.py: %s" % error, file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
