"""Tables and plots of the ablation configs (configs/ablation_*.yaml), called by make_all.py.

Each function reads results/<config>/results.csv or .jsonl as written by `lpd sweep` and
writes out/<config>.md (and .png); a config without results is skipped with a message.
"""
import math

import figure_common as common
from figure_common import label, plt, save_plot, table, write
from render_clouds import read_records

QUALITY = [("MSE (1e-5)", "mse_normalized", 1e-5, 3),
           ("MCD (1e-3)", "mcd_normalized", 1e-3, 3)]
RUN = [("final energy", "final_energy", 1, 4), ("iterations", "iterations", 1, 0),
       ("seconds", "seconds", 1, 2)]


def value(record, key, scale=1.0, digits=3):
    v = record.get(key)
    if v is None or v == "" or (isinstance(v, float) and math.isnan(v)):
        return "-"
    if isinstance(v, str):
        return v
    return f"{v / scale:.{digits}f}" if digits else f"{v / scale:.0f}"


def comparison_table(results, out, name, title, metrics, note=""):
    """One row per (dataset, noise, method) with `metrics`."""
    rows = read_records(results, name)
    if rows is None:
        return None
    rows.sort(key=lambda r: (r["dataset"], str(r.get("noise_sigma")),
                             str(r.get("noise_description", r.get("num_outliers"))),
                             r["method"] != "none", common.natural(label(r))))
    body = [[r["dataset"], value(r, "noise_sigma"), value(r, "num_outliers", 1, 0), label(r)] +
            [value(r, key, scale, digits) for _, key, scale, digits in metrics]
            for r in rows]
    columns = ["model", "noise", "outliers", "method"] + [m[0] for m in metrics]
    text = common.header(rows, title, name) + note + table(columns, body)
    write(out, name, text)


def fig5_energy(results, out):
    rows = read_records(results, "fig5_energy")
    if rows is None:
        return
    rows.sort(key=lambda r: common.natural(r["dataset"]))
    figure, axes = plt.subplots(1, len(rows), figsize=(4.2 * len(rows), 3.6), squeeze=False)
    body = []
    for axis, r in zip(axes[0], rows):
        terms = [[float(x) for x in item.split(":")] for item in r["energy_terms_trace"].split()]
        iterations = range(1, len(terms) + 1)
        for index, term in enumerate(["fitting", "smoothness", "stitching"]):
            axis.plot(iterations, [t[index] for t in terms], label=term)
        axis.plot(iterations, [sum(t) for t in terms], "k", label="total")
        axis.set_yscale("log")
        axis.set_title(r["dataset"], fontsize=9)
        axis.set_xlabel("outer iteration")
        axis.grid(alpha=0.3)
        total = [sum(t) for t in terms]
        rises = sum(b > a * (1 + 1e-12) for a, b in zip(total, total[1:]))
        body.append([r["dataset"], f"{total[0]:.4e}", f"{total[4]:.4e}", f"{total[-1]:.4e}",
                     str(rises), value(r, "mean_distance_normalized", 1e-3)])
    axes[0][0].set_ylabel("energy of Eq. (5)")
    axes[0][0].legend(fontsize=7)
    save_plot(out, "fig5_energy", figure)
    text = common.header(rows, "Fig. 5: energy per outer iteration", "fig5_energy")
    text += ("Energy of Eq. (5) after outer iterations 1, 5 and 20 (per-term curves in "
             "fig5_energy.png) and how many iterations raised it (Alg. 1 must never).\n\n")
    text += table(["model", "after 1", "after 5", "after 20", "rises",
                   "mean distance after 20 (1e-3)"], body)
    write(out, "fig5_energy", text)


def fig9_parameters(results, out):
    rows = read_records(results, "fig9_parameters")
    if rows is None:
        return
    runs = [r for r in rows if r["method"] == "lpd"]
    for r in runs:  # mu_m = 1 - cos(angle)
        r["angle"] = round(math.degrees(math.acos(1.0 - float(r["mu_m"]))))
    angles = sorted({r["angle"] for r in runs})
    lambdas = sorted({float(r["lambda"]) for r in runs})
    grid = {(r["angle"], float(r["lambda"])): r for r in runs}
    text = common.header(rows, "Fig. 9: mu_m and lambda on a noisy cube (1%)", "fig9_parameters")
    for title, key, scale, digits in [("mean distance (1e-3)", "mean_distance_normalized", 1e-3, 3),
                                      ("feature recall", "feature_recall", 1, 3),
                                      ("feature precision", "feature_precision", 1, 3)]:
        body = [[f"{a:g}"] + [value(grid[(round(a), l)], key, scale, digits) for l in lambdas]
                for a in angles]
        text += f"\n{title}, rows mu_m as an angle (degrees), columns lambda\n\n"
        text += table(["mu_m (deg)"] + [f"lambda {l:g}" for l in lambdas], body)
    none = [r for r in rows if r["method"] == "none"]
    if none:
        text += f"\nInput mean distance: {value(none[0], 'mean_distance_normalized', 1e-3)} (1e-3).\n"
    write(out, "fig9_parameters", text)
    figure, axes = plt.subplots(1, 2, figsize=(9, 3.6))
    for axis, (title, key) in zip(axes, [("mean distance / diagonal", "mean_distance_normalized"),
                                         ("feature recall", "feature_recall")]):
        for a in angles:
            axis.plot(lambdas, [grid[(round(a), l)].get(key) or math.nan for l in lambdas],
                      marker="o", label=f"mu_m {a:g} deg")
        axis.set_xscale("log")
        axis.set_xlabel("lambda")
        axis.set_title(title)
        axis.grid(alpha=0.3)
    axes[0].legend(fontsize=7)
    save_plot(out, "fig9_parameters", figure)


def ablation_gnc(results, out):
    rows = read_records(results, "ablation_gnc")
    if rows is None:
        return
    converged = [r for r in rows if r["method"] == "lpd" and int(r["max_iters"]) == 200]
    inputs = {(r["dataset"], r["noise_sigma"]): r for r in rows if r["method"] == "none"}
    body = []
    for r in sorted(converged, key=lambda r: (r["dataset"], r["noise_sigma"], r["gnc"])):
        source = inputs.get((r["dataset"], r["noise_sigma"]), {})
        body.append([r["dataset"], value(r, "noise_sigma"), r["gnc"],
                     value(source, "mse_normalized", 1e-5), value(r, "mse_normalized", 1e-5),
                     value(r, "mean_distance_normalized", 1e-3), f"{r['final_energy']:.4e}",
                     value(r, "iterations", 1, 0), r["termination"], value(r, "seconds", 1, 2)])
    text = common.header(rows, "Graduated non-convexity against none", "ablation_gnc")
    text += ("Run to convergence (energy change below 1% over 3 iterations at the targets, at "
             "most 200 outer iterations; GNC stages count). Energies of Eq. (5) at the target "
             "selectivities.\n\n")
    text += table(["model", "noise", "gnc", "input MSE (1e-5)", "MSE (1e-5)",
                   "mean distance (1e-3)", "final energy", "iterations", "termination",
                   "seconds"], body)
    write(out, "ablation_gnc", text)
    curves = [r for r in rows if r["method"] == "lpd" and int(r["max_iters"]) != 200]
    settings = sorted({(r["dataset"], r["noise_sigma"]) for r in curves})
    figure, axes = plt.subplots(2, len(settings), figsize=(3.4 * len(settings), 6.2),
                                squeeze=False)
    for column, (dataset, sigma) in enumerate(settings):
        for gnc in ["none", "mu_m", "both"]:
            points = sorted((int(r["max_iters"]), r) for r in curves
                            if (r["dataset"], r["noise_sigma"], r["gnc"]) == (dataset, sigma, gnc))
            xs = [x for x, _ in points]
            axes[0][column].plot(xs, [r["final_energy"] for _, r in points], marker=".", label=gnc)
            axes[1][column].plot(xs, [r["mse_normalized"] / 1e-5 for _, r in points],
                                 marker=".", label=gnc)
        axes[0][column].set_title(f"{dataset}, noise {sigma:g}", fontsize=9)
        axes[0][column].set_yscale("log")
        axes[1][column].set_xlabel("outer iterations")
        for row in range(2):
            axes[row][column].grid(alpha=0.3)
    axes[0][0].set_ylabel("energy of Eq. (5)")
    axes[1][0].set_ylabel("MSE / diagonal^2 (1e-5)")
    axes[0][0].legend(fontsize=7)
    save_plot(out, "ablation_gnc", figure)


def make_ablations(results, out):
    fig5_energy(results, out)
    fig9_parameters(results, out)
    ablation_gnc(results, out)
    comparison_table(results, out, "fig4_orientations", "Fig. 4: s_ij optimized against held at 1",
                     QUALITY + [("mean distance (1e-3)", "mean_distance_normalized", 1e-3, 3),
                                ("feature precision", "feature_precision", 1, 3),
                                ("feature recall", "feature_recall", 1, 3)] + RUN)
    comparison_table(results, out, "ablation_mu_l", "Scale-aware mu_l against the fixed 5e-9",
                     QUALITY + [("mu_l used", "mu_l_used", 1e-6, 3),
                                ("outlier precision", "outlier_precision", 1, 3),
                                ("outlier recall", "outlier_recall", 1, 3),
                                ("points out", "num_output", 1, 0)] + RUN,
                     note="mu_l used in units of 1e-6 (the fixed default is 0.005).\n\n")
    comparison_table(results, out, "ablation_schedule",
                     "Schedule and initialization ablations of Alg. 1",
                     QUALITY + [("mean distance (1e-3)", "mean_distance_normalized", 1e-3, 3)] +
                     RUN)
    comparison_table(results, out, "ablation_final_steps",
                     "The default's final steps, one off at a time",
                     QUALITY + [("mean distance (1e-3)", "mean_distance_normalized", 1e-3, 3)] +
                     RUN)
    comparison_table(results, out, "fig6_indicators", "Figs. 6, 7, 15: indicators and error maps",
                     QUALITY + [("outlier precision", "outlier_precision", 1, 3),
                                ("outlier recall", "outlier_recall", 1, 3),
                                ("feature precision", "feature_precision", 1, 3),
                                ("feature recall", "feature_recall", 1, 3)] + RUN,
                     note="Renderings: paper_figures/out/fig6_indicators_*.png "
                          "(python3 paper_figures/render_clouds.py fig6_indicators).\n\n")
