#!/usr/bin/env bash
# Runs every paper sweep in configs/ (resumable: finished cells are skipped), then turns the
# results into tables and plots in paper_figures/out/.
# Usage: scripts/reproduce_paper.sh [CONFIG_NAME...]   (default: all of them)
set -euo pipefail
cd "$(dirname "$0")/.."
[ -x build/lpd ] || scripts/build.sh
configs=("$@")
if [ ${#configs[@]} -eq 0 ]; then
  configs=(table1_comparison table2_parameters table3_timings fig12_outliers fig13_noise_levels
           fig17_cones solver_validation fig4_orientations fig5_energy fig6_indicators
           fig9_parameters ablation_gnc ablation_mu_l ablation_schedule
           ablation_final_steps)
fi
for name in "${configs[@]}"; do
  echo "== $name"
  /usr/bin/time -f "$name: %e s wall" build/lpd sweep "configs/$name.yaml"
done
python=/usr/bin/python3
[ -x "$python" ] || python=python3
"$python" paper_figures/make_all.py
