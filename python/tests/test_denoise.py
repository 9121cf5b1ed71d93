"""The Python module against the lpd program and against its own promises."""
import os
import subprocess
import threading
import time

import numpy as np
import pytest

import lpd
from conftest import noisy_box


def read_binary_ply(path):
    """The vertex properties of a binary little-endian PLY, by name (an independent reader)."""
    with open(path, "rb") as f:
        header = []
        while True:
            line = f.readline().decode("ascii").strip()
            header.append(line)
            if line == "end_header":
                break
        body = f.read()
    assert "format binary_little_endian 1.0" in header
    types = {"double": "<f8", "float": "<f4", "uint": "<u4", "int": "<i4", "uchar": "u1"}
    count, fields = 0, []
    for line in header:
        words = line.split()
        if words[:2] == ["element", "vertex"]:
            count = int(words[2])
        elif words[:1] == ["property"]:
            fields.append((words[2], types[words[1]]))
    return np.frombuffer(body, dtype=np.dtype(fields), count=count)


def test_numpy_in_out_is_the_cli_bit_for_bit(tmp_path, lpd_binary, shared_data):
    source = os.path.join(shared_data, "noisy", "fandisk_noise_0.01.xyz")
    output = tmp_path / "cli.ply"
    subprocess.run([lpd_binary, "denoise", source, "-o", str(output), "--threads=2", "--quiet"],
                   check=True, capture_output=True)
    cli = read_binary_ply(output)
    points = np.loadtxt(source)[:, :3]
    result = lpd.denoise(points, threads=2)
    assert result.points.dtype == np.float64
    np.testing.assert_array_equal(result.index, cli["source_index"])
    np.testing.assert_array_equal(result.points, np.stack([cli["x"], cli["y"], cli["z"]], 1))
    np.testing.assert_array_equal(result.outlier_score, cli["outlier_score"])
    assert result.summary["output_points"] == len(cli)


def test_float32_and_float64_give_the_same_run():
    points = noisy_box(3000, 0.005, seed=1).astype(np.float32)
    single = lpd.denoise(points, threads=1)
    double = lpd.denoise(points.astype(np.float64), threads=1)
    assert single.points.dtype == np.float32 and double.points.dtype == np.float64
    np.testing.assert_array_equal(single.index, double.index)
    np.testing.assert_array_equal(single.points, double.points.astype(np.float32))


def test_result_rows_follow_the_kept_input_rows():
    points = noisy_box(3000, 0.005, seed=2)
    result = lpd.denoise(points, threads=1)
    n = len(result.points)
    assert result.normals.shape == (n, 3) and result.index.shape == (n,)
    assert np.all(np.diff(result.index) > 0)
    # each output point stays close to the input point it comes from: the even spacing moves
    # it along the surface by about one spacing (0.022 here), at most about three
    assert np.max(np.linalg.norm(result.points - points[result.index], axis=1)) < 0.1
    np.testing.assert_allclose(np.linalg.norm(result.normals, axis=1), 1.0, atol=1e-9)
    summary = result.summary
    assert summary["input_points"] == 3000 and summary["output_points"] == n
    assert summary["removed"] == 3000 - n
    assert summary["termination"] in ("CONVERGENCE", "NO_CONVERGENCE")
    stages = summary["stage_seconds"]
    assert list(stages)[:6] == ["far points and repeats", "order and probe", "graph",
                                "initial state", "solve", "projection"], stages
    assert min(stages.values()) >= 0 and sum(stages.values()) <= summary["seconds"] + 1e-6


def test_repeated_rows_take_their_first_occurrences_result():
    points = noisy_box(2000, 0.005, seed=4)
    once = lpd.denoise(points, threads=1)
    twice = lpd.denoise(np.vstack([points, points[::-1]]), threads=1)
    assert twice.summary["duplicates"] == 2000 and once.summary["duplicates"] == 0
    first = twice.index < 2000
    np.testing.assert_array_equal(twice.index[first], once.index)
    np.testing.assert_array_equal(twice.points[first], once.points)
    # row 2000 + r repeats row 1999 - r
    np.testing.assert_array_equal(twice.points[~first][::-1],
                                  once.points)



def test_a_copy_a_hair_away_is_solved_with_its_original():
    points = noisy_box(2000, 0.005, seed=4)
    copy = points + 1e-7 * np.random.default_rng(5).standard_normal(points.shape)
    once = lpd.denoise(points, threads=1)
    twice = lpd.denoise(np.vstack([points, copy]), threads=1)
    assert twice.summary["near_repeats"] >= 2000 and twice.summary["duplicates"] == 0
    assert twice.summary["k"] == once.summary["k"]
    assert abs(twice.summary["lambda"] / once.summary["lambda"] - 1) < 0.05
    unmerged = lpd.denoise(np.vstack([points, copy]), threads=1, merge_duplicates=False)
    assert unmerged.summary["near_repeats"] == 0
    assert unmerged.summary["lambda"] < 0.1 * once.summary["lambda"]

def test_denoising_brings_the_box_closer_to_its_faces():
    clean_distance = lambda p: np.min(np.abs(np.concatenate([p, 1.0 - p], 1)), axis=1)
    points = noisy_box(6000, 0.01, seed=3)
    result = lpd.denoise(points, threads=2)
    before = np.mean(clean_distance(points))
    after = np.mean(clean_distance(result.points))
    assert after < 0.6 * before


def test_options_are_the_cli_flags():
    points = noisy_box(2000, 0.005, seed=4)
    result = lpd.denoise(points, threads=1, k=15, max_iters=3, snap_features=True,
                         mu_m_deg=25.0, projection="plane")
    assert result.summary["k"] == 15 and result.summary["iterations"] <= 3
    np.testing.assert_allclose(result.summary["mu_m"], 1 - np.cos(np.radians(25.0)))
    paper = lpd.denoise(points, threads=1, preset="paper")
    assert paper.summary["k"] == 20 and paper.summary["lambda"] == 1.0
    names = [p["name"] for p in lpd.parameters()]
    assert "lambda" in names and "isolation_factor" in names
    assert next(p for p in lpd.parameters() if p["name"] == "lambda")["default"] == "auto"


@pytest.mark.parametrize("points, message", [
    (np.full((100, 3), np.nan), "not finite"),
    (np.zeros((100, 2)), "shape (N, 3)"),
    (np.zeros(300), "shape (N, 3)"),
    (np.array([["a", "b", "c"]]), "array of numbers"),
    (noisy_box(5, 0.01, seed=5), "need at least"),
])
def test_bad_points_raise_value_error(points, message):
    with pytest.raises(ValueError) as error:
        lpd.denoise(points)
    assert message in str(error.value)


@pytest.mark.parametrize("options, message", [
    ({"lambdaa": 1.0}, "unknown parameter 'lambdaa'"),
    ({"k": "many"}, "parameter k"),
    ({"max_iters": 0}, "max_iters"),
    ({"gnc": "sometimes"}, "gnc"),
    ({"eta": 10.0, "fit_balance": 2.0}, "not both"),
    ({"preset": "fast"}, "preset"),
    ({"threads": -1}, "num_threads"),
    ({"ceres_max_iters": 5}, "no effect"),
])
def test_bad_options_raise_value_error(options, message):
    with pytest.raises(ValueError) as error:
        lpd.denoise(noisy_box(500, 0.01, seed=6), **options)
    assert message in str(error.value)


def test_open3d_cloud_round_trip_keeps_colours():
    o3d = pytest.importorskip("open3d")
    points = noisy_box(3000, 0.005, seed=7)
    colours = np.clip(points, 0.0, 1.0)
    cloud = o3d.geometry.PointCloud()
    cloud.points = o3d.utility.Vector3dVector(points)
    cloud.colors = o3d.utility.Vector3dVector(colours)
    out = lpd.denoise(cloud, threads=1)
    assert isinstance(out, o3d.geometry.PointCloud)
    reference = lpd.denoise(points, threads=1)
    np.testing.assert_array_equal(np.asarray(out.points), reference.points)
    np.testing.assert_array_equal(np.asarray(out.colors), colours[reference.index])
    np.testing.assert_array_equal(np.asarray(out.normals), reference.normals)


def test_ctrl_c_raises_keyboard_interrupt_and_stops_the_solve():
    import _thread

    points = noisy_box(60000, 0.005, seed=8)
    timer = threading.Timer(1.0, _thread.interrupt_main)
    start = time.monotonic()
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            lpd.denoise(points, threads=2, max_iters=1000, energy_tolerance=0,
                        progress_tolerance=0, motion_tolerance=0)
    finally:
        timer.cancel()
    assert time.monotonic() - start < 30.0


def test_the_gil_is_released_during_the_solve():
    points = noisy_box(30000, 0.005, seed=9)
    ticks = []
    stop = threading.Event()

    def tick():
        while not stop.is_set():
            ticks.append(time.monotonic())
            time.sleep(0.01)

    ticker = threading.Thread(target=tick)
    ticker.start()
    try:
        lpd.denoise(points, threads=1, max_iters=10, energy_tolerance=0, progress_tolerance=0,
                    motion_tolerance=0)
    finally:
        stop.set()
        ticker.join()
    # a thread waiting for the GIL would tick once per iteration at best
    assert len(ticks) > 20


def test_the_cli_reads_and_writes_pcd_as_open3d_does(tmp_path, lpd_binary):
    o3d = pytest.importorskip("open3d")
    points = noisy_box(3000, 0.005, seed=6)
    colours = np.random.default_rng(7).integers(0, 256, (3000, 3))
    cloud = o3d.geometry.PointCloud(o3d.utility.Vector3dVector(points))
    cloud.colors = o3d.utility.Vector3dVector(colours / 255.0)
    for name, options in [("ascii", {"write_ascii": True}), ("binary", {}),
                          ("compressed", {"compressed": True})]:
        source = tmp_path / f"{name}.pcd"
        assert o3d.io.write_point_cloud(str(source), cloud, **options)
        output = tmp_path / f"{name}_out.pcd"
        subprocess.run([lpd_binary, "denoise", str(source), "-o", str(output), "--quiet"],
                       check=True, capture_output=True)
        written = o3d.io.read_point_cloud(str(output))  # Open3D reads what lpd wrote
        kept = len(written.points)
        assert 2900 < kept <= 3000 and written.has_normals()
        # each output point keeps the colour of its own input point, which the even spacing
        # leaves among the output point's 3 nearest inputs (99% of them here)
        tree = o3d.geometry.KDTreeFlann(cloud)
        nearest = np.array([tree.search_knn_vector_3d(p, 3)[1] for p in np.asarray(written.points)])
        written_colours = np.round(np.asarray(written.colors) * 255)
        agree = np.any(np.all(written_colours[:, None, :] == colours[nearest], axis=2), axis=1)
        assert agree.mean() > 0.95


def test_two_sheets_merged_by_the_solve_are_told_apart():
    # Two unit squares 1.9 noise deviations apart: the solve merges them, and the summary
    # counts the points moved back to their side (solvers/merged_sides.h).
    rng = np.random.default_rng(5)
    sigma, half_gap = 0.021, 0.02
    side = np.where(rng.random(10000) < 0.5, -half_gap, half_gap)
    points = np.column_stack([rng.random(10000), rng.random(10000), side])
    points += rng.normal(0.0, sigma, points.shape)
    told_apart = lpd.denoise(points, threads=2)
    merged = lpd.denoise(points, threads=2, separate_sides=False)
    assert told_apart.summary["separated"] > 3000 and merged.summary["separated"] == 0
    distance = lambda p: np.mean(np.abs(np.abs(p[:, 2]) - half_gap))
    assert distance(told_apart.points) < distance(points) < distance(merged.points)
