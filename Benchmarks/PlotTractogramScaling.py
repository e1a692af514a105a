# SPDX-License-Identifier: BSD-3-Clause
"""The scaling figure of docs/performance.md from SplineVizTractogramBenchmark's
CSV: still frame, frame while rotating and peak RSS against the number of
segments, one curve per renderer (synthetic tractograms only). Needs
matplotlib (Debian: python3-matplotlib).

    build/bin/SplineVizTractogramBenchmark --streamlines 10000,50000,100000,200000 \\
        --data synthetic --csv /tmp/tractograms.csv
    /usr/bin/python3 Benchmarks/PlotTractogramScaling.py /tmp/tractograms.csv \\
        docs/images/tractogram-scaling.png ["title"]
"""
import csv
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

NAMES = {
    "lines": "VTK lines",
    "linesastubes": "VTK RenderLinesAsTubes",
    "tubefilter": "vtkTubeFilter (8 sides)",
    "raycast": "ray-cast tubes",
    "tessellated": "tessellated tubes",
    "stylized": "stylized lines",
}


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    series = defaultdict(list)
    with open(sys.argv[1], newline="") as f:
        for row in csv.DictReader(f):
            if not row["data"].endswith(" streamlines"):  # cb_2 (real data): not a curve
                continue
            series[row["renderer"]].append(
                (int(row["segments"]) / 1e6, float(row["still_s"]),
                 float(row["interactive_s"]), float(row["peak_rss_gb"])))
    if not series:
        sys.exit("no synthetic tractogram rows in " + sys.argv[1])
    fig, axes = plt.subplots(1, 3, figsize=(12, 3.6))
    panels = [("still frame (s)", 1, False), ("frame while rotating (s)", 2, True),
              ("peak RSS (GB)", 3, False)]
    for ax, (title, column, log) in zip(axes, panels):
        for renderer, points in series.items():
            points.sort()
            ax.plot([p[0] for p in points], [p[column] for p in points], marker="o",
                    label=NAMES.get(renderer, renderer))
        ax.set_title(title)
        ax.set_xlabel("segments (millions)")
        ax.grid(alpha=0.3)
        if log:
            ax.set_yscale("log")
    axes[0].legend(fontsize=8)
    if len(sys.argv) > 3:
        fig.suptitle(sys.argv[3])
    fig.tight_layout()
    fig.savefig(sys.argv[2], dpi=100)
    print("wrote", sys.argv[2])


if __name__ == "__main__":
    main()
