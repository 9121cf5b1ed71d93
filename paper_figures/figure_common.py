"""Helpers shared by the figure scripts: reading sweep results, formatting numbers and
labels, Markdown tables, and writing tables and plots. Needs only Debian's python3 and
python3-matplotlib.
"""
import csv
import math
import os
import re
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402,F401  (the scripts plot through this module)


def number(row, key):
    text = row.get(key, "")
    return float(text) if text not in ("", None) else math.nan


def fmt(value, scale=1.0, digits=3):
    if value is None or math.isnan(value):
        return "-"
    return f"{value / scale:.{digits}f}"


def natural(text):
    """Sort key that orders "k=20" before "k=100"."""
    return [float(part) if re.fullmatch(r"[0-9.]+(e-?[0-9]+)?", part) else part
            for part in re.split(r"([0-9.]+(?:e-?[0-9]+)?)", text) if part]


def label(row):
    parameters = row["method_parameters"]
    return row["method"] + (f" ({parameters})" if parameters else "")


def noise_label(row):
    if row["noise_model"] == "as given":
        return "as given"
    text = f"{row['noise_model']} {100 * number(row, 'noise_sigma'):g}% of {row['noise_scale']}"
    outliers = row.get("num_outliers", "0")
    if outliers not in ("", "0"):
        text += f" + {outliers} outliers"
    return text


def mean_over_repetitions(rows, keys):
    """Averages `keys` over rows that differ only by repetition."""
    groups = defaultdict(list)
    for row in rows:
        groups[(row["dataset"], noise_label(row), label(row))].append(row)
    merged = []
    for group in groups.values():
        row = dict(group[0])
        for key in keys:
            values = [number(r, key) for r in group]
            row[key] = str(sum(values) / len(values))
        row["repetitions"] = str(len(group))
        merged.append(row)
    return merged


def read(results, name):
    path = os.path.join(results, name, "results.csv")
    if not os.path.exists(path):
        print(f"skip {name}: no results in {path} (run: build/lpd sweep configs/{name}.yaml)")
        return None
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    metric_keys = ["mse_normalized", "mcd_normalized", "snr_db", "mean_distance_normalized",
                   "outlier_precision", "outlier_recall", "outlier_bound_precision",
                   "outlier_bound_recall", "feature_precision",
                   "feature_recall", "seconds", "local_seconds_per_iteration",
                   "global_seconds_per_iteration", "num_output"]
    return mean_over_repetitions(rows, metric_keys)


def header(rows, title, config):
    machine = rows[0].get("machine", "?") if rows else "?"
    revision = rows[0].get("git_revision", "?") if rows else "?"
    return (f"# {title}\n\nFrom `build/lpd sweep configs/{config}.yaml` (lpd {revision}, "
            f"{machine}). MSE in units of 1e-5 and MCD, mean distance in 1e-3, all divided by "
            f"the bounding-box diagonal (squared for MSE); SNR in dB.\n\n")


def table(columns, body):
    lines = ["| " + " | ".join(columns) + " |", "|" + "---|" * len(columns)]
    lines += ["| " + " | ".join(row) + " |" for row in body]
    return "\n".join(lines) + "\n"


def write(out, name, text):
    path = os.path.join(out, name + ".md")
    with open(path, "w") as f:
        f.write(text)
    print(f"wrote {path}")


def save_plot(out, name, figure):
    path = os.path.join(out, name + ".png")
    figure.savefig(path, dpi=120, bbox_inches="tight")
    plt.close(figure)
    print(f"wrote {path}")
