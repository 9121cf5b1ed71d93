#!/usr/bin/env python3
"""Far-point table of docs/method.md: stray points far from a cloud, with and without the
far-point test. Input: the first 10,000 points of FANDISK 0.01 (LPD_DATA or ../shared/data);
far points are added along a random direction at OFFSET x the cloud's extent, spread through
the input. For each case: how many far points were flagged, and how much the other points'
output moved against the run without far points (max and median, / the diagonal).
Usage: PYTHONPATH=build/python python3 scripts/far_points_table.py [--threads=2]"""
import argparse
import os

import numpy as np

import lpd


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--threads", type=int, default=2)
    args = parser.parse_args()
    data = os.environ.get("LPD_DATA", os.path.join(os.path.dirname(__file__), "../../shared/data"))
    clean = np.loadtxt(os.path.join(data, "noisy", "fandisk_noise_0.01.xyz"))[:10000, :3]
    extent = np.linalg.norm(clean.max(0) - clean.min(0))
    reference = lpd.denoise(clean, threads=args.threads)
    by_row = dict(zip(reference.index, reference.points))
    print("| far points | offset / extent | far_factor | far flagged | others kept (clean run: "
          f"{len(reference.points)}) | others' move, max / median (/ diagonal) |")
    print("|---|---|---|---|---|---|")
    rng = np.random.default_rng(1)
    for count in (1, 10, 100):
        for offset in (1e3, 1e6, 1e12):
            direction = rng.normal(size=(count, 3))
            direction /= np.linalg.norm(direction, axis=1, keepdims=True)
            far = clean.mean(0) + offset * extent * direction
            rows = np.sort(rng.choice(len(clean) + count, count, replace=False))
            points = np.insert(clean, rows - np.arange(count), far, axis=0)
            is_far = np.zeros(len(points), bool)
            is_far[rows] = True
            clean_row = np.cumsum(~is_far) - 1  # the row in `clean` of each non-far point
            for factor in (100, 0):
                result = lpd.denoise(points, threads=args.threads, far_factor=factor)
                kept_far = is_far[result.index].sum()
                moves = [np.linalg.norm(p - by_row[clean_row[i]]) / extent
                         for i, p in zip(result.index, result.points)
                         if not is_far[i] and clean_row[i] in by_row]
                others = (~is_far[result.index]).sum()
                print(f"| {count} | {offset:.0e} | {factor} | {result.summary['far']} "
                      f"({kept_far} kept) | {others} | {max(moves):.2e} / "
                      f"{np.median(moves):.2e} |")


if __name__ == "__main__":
    main()
