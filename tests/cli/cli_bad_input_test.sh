#!/usr/bin/env bash
# lpd denoise on bad input: one error line on stderr, non-zero exit, no output file left.
# Degenerate but valid inputs (collinear, coplanar, duplicates) give finite output.
# Usage: cli_bad_input_test.sh PATH_TO_LPD
lpd=$1
source "$(dirname "$0")/cli_test_lib.sh"

# expect_error NAME ARGS...: the run must fail with exactly one stderr line and no output.
expect_error() {
  local name=$1; shift
  local out="$dir/out_$name.${EXT:-ply}"
  "$lpd" denoise "$@" -o "$out" >"$dir/stdout" 2>"$dir/stderr"
  local code=$?
  local lines
  lines=$(wc -l <"$dir/stderr")
  [ "$code" -ne 0 ] || fail "$name: exit code 0"
  [ "$lines" -eq 1 ] || fail "$name: $lines stderr lines: $(cat "$dir/stderr")"
  ls "$dir" | grep -q "out_$name" && fail "$name: output file left behind"
  echo "ok   $name: $(cat "$dir/stderr")"
}

# expect_finite NAME FILE [FLAGS...]: the run must succeed and write only finite coordinates.
expect_finite() {
  denoise_finite "$1" "$2" --k=8 "${@:3}" && echo "ok   $1: $finite_count finite points"
}

python3 - "$dir" <<'PY'
import math, random, sys
d = sys.argv[1]
random.seed(1)
def write(name, rows):
    with open(f"{d}/{name}", "w") as f:
        f.writelines(" ".join(repr(c) for c in r) + "\n" for r in rows)
plane = [(random.random(), random.random(), 0.001 * random.gauss(0, 1)) for _ in range(300)]
write("good.xyz", plane)
write("nan.xyz", plane[:50] + [(0.5, float("nan"), 0.0)] + plane[50:])
write("inf.xyz", plane[:50] + [(0.5, float("inf"), 0.0)] + plane[50:])
write("few.xyz", plane[:20])
write("tiny.xyz", plane[:5])
write("same.xyz", [(1.0, 2.0, 3.0)] * 100)
write("collinear.xyz", [(0.01 * i, 0.02 * i, -0.03 * i) for i in range(200)])
write("coplanar.xyz", [(random.random(), random.random(), 0.0) for _ in range(300)])
write("duplicates.xyz", plane + plane + [plane[0]] * 30)
with open(f"{d}/malformed.xyz", "w") as f:
    f.write("0 0 0\n1 1 oops\n")
open(f"{d}/empty.xyz", "w").close()
PY

expect_error missing "$dir/does_not_exist.xyz"
expect_error empty "$dir/empty.xyz"
expect_error malformed "$dir/malformed.xyz"
expect_error nan "$dir/nan.xyz"
expect_error inf "$dir/inf.xyz"
expect_error too_few "$dir/few.xyz" --k=20
expect_error too_few_for_auto_k "$dir/tiny.xyz"
expect_error bad_k_text "$dir/good.xyz" --k=auto20
expect_error unknown_preset "$dir/good.xyz" --preset=fast
expect_error zero_passes "$dir/good.xyz" --outlier_passes=0
expect_error negative_fit_balance "$dir/good.xyz" --fit_balance=-1
expect_error zero_k_radius "$dir/good.xyz" --k_radius_sigmas=0
expect_error max_k_below_min "$dir/good.xyz" --max_k=2
expect_error unknown_projection "$dir/good.xyz" --projection=cube
expect_error identical "$dir/same.xyz" --k=8
expect_error negative_lambda "$dir/good.xyz" --lambda=-1
expect_error zero_k "$dir/good.xyz" --k=0
expect_error zero_mu_l "$dir/good.xyz" --mu_l=0
expect_error zero_iters "$dir/good.xyz" --max_iters=0
expect_error both_mu_m "$dir/good.xyz" --mu_m=0.2 --mu_m_deg=20
expect_error unknown_flag "$dir/good.xyz" --no_such_flag=3
expect_error bad_flag_value "$dir/good.xyz" --k=abc
EXT=abc expect_error bad_extension "$dir/good.xyz"
expect_error unknown_solver "$dir/good.xyz" --solver=newton
expect_error ceres_from_zero "$dir/good.xyz" --solver=ceres --initialization=zero
expect_error unknown_initialization "$dir/good.xyz" --initialization=spiral
expect_error normals_without_normals "$dir/good.xyz" --initialization=input_normals
expect_error unknown_gnc "$dir/good.xyz" --gnc=mu_x
expect_error gnc_factor_one "$dir/good.xyz" --gnc=both --gnc_factor=1
expect_error gnc_start_below_target "$dir/good.xyz" --gnc=both --gnc_start_ratio=0.5
expect_error negative_noise_sigmas "$dir/good.xyz" --mu_l_noise_sigmas=-1
expect_error gnc_with_ceres "$dir/good.xyz" --solver=ceres --gnc=mu_m
expect_error dense_joint_solver "$dir/good.xyz" --solver=ceres --ceres_linear_solver=dense_qr
expect_error schedule_with_ceres "$dir/good.xyz" --solver=ceres --inner_iters=3
expect_error ceres_flag_with_alternating "$dir/good.xyz" --ceres_max_iters=3
expect_error zero_ceres_seconds "$dir/good.xyz" --solver=ceres --ceres_max_seconds=0

expect_error snap_angle_zero "$dir/good.xyz" --snap_features --snap_cluster_angle_deg=0
expect_error snap_min_planes_zero "$dir/good.xyz" --snap_features --snap_min_cluster_planes=0
expect_finite collinear "$dir/collinear.xyz"
expect_finite coplanar "$dir/coplanar.xyz"
expect_finite duplicates "$dir/duplicates.xyz"
for shape in collinear coplanar duplicates; do
  expect_finite "${shape}_ceres" "$dir/$shape.xyz" --solver=ceres
  expect_finite "${shape}_auto_k" "$dir/$shape.xyz" --k=auto
done
expect_finite few_points_auto_k "$dir/few.xyz" --k=auto

# An existing output file is never overwritten without --overwrite, and is refused before
# any work (no iteration is printed).
echo "precious" >"$dir/keep.xyz"
if "$lpd" denoise "$dir/good.xyz" -o "$dir/keep.xyz" --k=8 >"$dir/stdout" 2>"$dir/stderr"; then
  fail "existing output was overwritten"
fi
[ "$(cat "$dir/keep.xyz")" = "precious" ] || fail "existing output was modified"
grep -q "iter" "$dir/stdout" "$dir/stderr" && fail "existing output refused only after the run"
grep -q "already exists" "$dir/stderr" && echo "ok   existing output: $(cat "$dir/stderr")" ||
  fail "existing output: $(cat "$dir/stderr")"
# Output equal to input is refused.
"$lpd" denoise "$dir/good.xyz" -o "$dir/good.xyz" --overwrite >/dev/null 2>&1 && fail "input overwritten"

# Warm restart from the command line: 2 + 2 iterations through a state file give the same
# output bytes as 4 in one go (hyphenated flag spellings work too).
"$lpd" denoise "$dir/good.xyz" -o "$dir/full.xyz" --k=8 --quiet --threads=2 --max_iters=4 \
  --energy_tolerance=0 >/dev/null 2>&1 || fail "uninterrupted run failed"
"$lpd" denoise "$dir/good.xyz" -o "$dir/half.xyz" --k=8 --quiet --threads=2 --max_iters=2 \
  --energy_tolerance=0 --save-state="$dir/state.lpds" >/dev/null 2>&1 || fail "saving run failed"
"$lpd" denoise --resume "$dir/state.lpds" -o "$dir/resumed.xyz" --quiet --max_iters=2 \
  >/dev/null 2>"$dir/resume.err" || fail "resume failed: $(cat "$dir/resume.err")"
cmp -s "$dir/full.xyz" "$dir/resumed.xyz" && echo "ok   resume: 2 + 2 iterations = 4, byte for byte" ||
  fail "resumed output differs from the uninterrupted run"
expect_error resume_with_input "$dir/good.xyz" --resume="$dir/state.lpds"
expect_error resume_new_k --resume="$dir/state.lpds" --k=10
expect_error resume_missing --resume="$dir/none.lpds"
expect_error resume_not_a_state --resume="$dir/good.xyz"
head -c 3000 "$dir/state.lpds" >"$dir/cut.lpds"
expect_error resume_truncated --resume="$dir/cut.lpds"
cp "$dir/state.lpds" "$dir/state_copy.lpds"
if "$lpd" denoise --resume="$dir/state.lpds" --save-state="$dir/state_copy.lpds" --quiet \
  >/dev/null 2>&1; then
  fail "an existing state file was overwritten"
fi
cmp -s "$dir/state.lpds" "$dir/state_copy.lpds" || fail "an existing state file was modified"

# lpd reconstruct: bad input gives one error line, a non-zero exit and no mesh file.
expect_reconstruct_error() {
  local name=$1; shift
  "$lpd" reconstruct "$@" >"$dir/stdout" 2>"$dir/stderr"
  local code=$?
  [ "$code" -ne 0 ] || fail "reconstruct $name: exit code 0"
  [ "$(wc -l <"$dir/stderr")" -eq 1 ] || fail "reconstruct $name: $(cat "$dir/stderr")"
  ls "$dir" | grep -q "mesh_$name" && fail "reconstruct $name: output file left behind"
  echo "ok   reconstruct $name: $(cat "$dir/stderr")"
}
expect_reconstruct_error missing_file "$dir/none.xyz" -o "$dir/mesh_missing_file.off"
expect_reconstruct_error no_output "$dir/good.xyz"
expect_reconstruct_error nan "$dir/nan.xyz" -o "$dir/mesh_nan.off"
echo "precious" >"$dir/mesh_kept.off"
expect_reconstruct_error existing_mesh "$dir/good.xyz" -o "$dir/mesh_kept.off"
[ "$(cat "$dir/mesh_kept.off")" = "precious" ] || fail "reconstruct modified an existing mesh"
rm "$dir/mesh_kept.off"
expect_reconstruct_error obj_extension "$dir/good.xyz" -o "$dir/mesh_obj_extension.obj"
expect_reconstruct_error unknown_method "$dir/good.xyz" -o "$dir/mesh_unknown_method.off" \
  --reconstruction=poisson
expect_reconstruct_error bad_extension "$dir/good.xyz" -o "$dir/mesh_bad_extension.stl"
expect_reconstruct_error collinear "$dir/collinear.xyz" -o "$dir/mesh_collinear.off"
expect_reconstruct_error coincident "$dir/same.xyz" -o "$dir/mesh_coincident.off" \
  --reconstruction=scale_space
head -3 "$dir/good.xyz" >"$dir/three.xyz"
expect_reconstruct_error three_points "$dir/three.xyz" -o "$dir/mesh_three_points.off"
"$lpd" reconstruct "$dir/good.xyz" -o "$dir/mesh.off" >/dev/null 2>"$dir/stderr" ||
  fail "reconstruct failed: $(cat "$dir/stderr")"
cp "$dir/mesh.off" "$dir/mesh_copy.off"
"$lpd" reconstruct "$dir/good.xyz" -o "$dir/mesh.off" --reconstruction=scale_space \
  >/dev/null 2>&1 && fail "reconstruct overwrote an existing mesh"
cmp -s "$dir/mesh.off" "$dir/mesh_copy.off" || fail "reconstruct modified an existing mesh"
finish "CLI checks"
