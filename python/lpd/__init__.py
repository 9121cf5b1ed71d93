"""lpd: robust denoising of point sets of piecewise-smooth surfaces through line processes.

Wei, Chen, Rohmer, Memari, Desbrun: Robust Pointset Denoising of Piecewise-Smooth Surfaces
through Line Processes (Eurographics 2023).

    import numpy as np, lpd
    points = np.loadtxt("scan.xyz")[:, :3]
    result = lpd.denoise(points)                 # every weight derived from the data
    clean = result.points                        # the kept points, denoised, in input order
    print(result.summary["k"], result.index[:5])  # index: the input row of each output point
    lpd.denoise(points, preset="paper")          # the paper's literal setting
    lpd.denoise(points, max_iters=60, smoothing_balance=2)  # any flag of `lpd denoise`

An open3d.geometry.PointCloud in gives a PointCloud out, with the denoised normals and the
colours of the kept points. Options are the flags of `lpd denoise --help`; lpd.parameters()
lists them with their defaults. Bad input or options raise ValueError; Ctrl-C stops the
solve at the next iteration with KeyboardInterrupt.
"""
import os
from typing import NamedTuple

import numpy as np

# Waiting OpenMP threads spin briefly, then sleep, so that lpd degrades gracefully beside
# other work (docs/performance.md); GNU libgomp reads this once, when it is first loaded.
if "OMP_WAIT_POLICY" not in os.environ:
    os.environ.setdefault("GOMP_SPINCOUNT", "1000")

from . import _lpd  # noqa: E402

__version__ = _lpd.__version__
__all__ = ["denoise", "parameters", "Result", "__version__"]


class Result(NamedTuple):
    """What lpd.denoise returns for numpy input; one row per kept (output) point."""

    points: np.ndarray         # (M, 3), the input's float type
    normals: np.ndarray        # (M, 3), unit normals of the fitted planes
    index: np.ndarray          # (M,) int64, the input row of each output point
    outlier_score: np.ndarray  # (M,) float32 in [0, 1]
    feature_score: np.ndarray  # (M,) float32 in [0, 1]
    is_outlier: np.ndarray     # (M,) bool; True only when removal was off or refused
    is_feature: np.ndarray     # (M,) bool
    summary: dict              # k, noise estimate, weights used, counts, iterations, times


def parameters():
    """Every option of denoise: name, group, help, default, auto rule and paper value."""
    return _lpd.parameters()


def _is_open3d_cloud(value):
    cls = type(value)
    return cls.__name__ == "PointCloud" and cls.__module__.startswith("open3d")


def denoise(points, normals=None, *, preset="default", solver="alternating", threads=0,
            **options):
    """Denoises points: an (N, 3) float32/float64 array, or an open3d PointCloud.

    normals (N, 3) are read with initialization="input_normals" only. preset is "default"
    or "paper"; solver "alternating" (Alg. 1) or "ceres"; threads 0 uses every core.
    Returns a Result for an array, a PointCloud for a PointCloud.
    """
    if _is_open3d_cloud(points):
        return _denoise_open3d(points, normals, preset, solver, threads, options)
    if not isinstance(points, np.ndarray):
        points = np.asarray(points)
    out = _lpd.denoise(points, normals, preset=preset, solver=solver, threads=threads,
                       **options)
    return Result(**out)


def _denoise_open3d(cloud, normals, preset, solver, threads, options):
    import open3d as o3d

    if normals is None and cloud.has_normals():
        normals = np.asarray(cloud.normals)
    out = _lpd.denoise(np.asarray(cloud.points), normals, preset=preset, solver=solver,
                       threads=threads, **options)
    result = o3d.geometry.PointCloud()
    result.points = o3d.utility.Vector3dVector(out["points"])
    result.normals = o3d.utility.Vector3dVector(out["normals"])
    if cloud.has_colors():
        result.colors = o3d.utility.Vector3dVector(np.asarray(cloud.colors)[out["index"]])
    return result
