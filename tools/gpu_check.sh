#!/usr/bin/env bash
# raylab on a machine with a GPU: builds, lists the Vulkan devices, then renders the showcase (slides
# integrator) and a path-traced scene (the Cornell box with its quad light) with each backend the device offers,
# and prints a table of times and ray throughput. Nothing is installed: run `tools/setup.sh deps` first on a
# fresh Debian machine (it also installs lavapipe, which raylab only uses when no GPU is capable).
#
#   tools/gpu_check.sh [--device N] [--width W] [--height H] [--spp N]
set -euo pipefail

device=() width=1280 height=720 spp=64
while [[ $# -gt 0 ]]; do
  case "$1" in
    --device) device=(--device "$2"); shift 2 ;;
    --width) width=$2; shift 2 ;;
    --height) height=$2; shift 2 ;;
    --spp) spp=$2; shift 2 ;;
    -h|--help) sed -n '2,8p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "gpu_check: unknown option $1 (see --help)" >&2; exit 2 ;;
  esac
done

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$root"
if [[ ! -f build/release/build.ninja ]]; then cmake --preset release >/dev/null; fi
cmake --build --preset release >/dev/null
raylab=build/release/raylab
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

"$raylab" devices 2>/dev/null || true
echo

printf '%-18s %-9s %12s %14s %12s %12s\n' scene backend "first sample" "per sample" "rays/s" "NaN dropped"
for scene in showcase assets/scenes/cornell_box_area.gltf; do
  name=$(basename "$scene" .gltf)
  args=()
  [[ $scene != showcase ]] && args=("$scene")
  for backend in query pipeline; do
    report=$out/$name-$backend.json
    if "$raylab" render "${args[@]}" "${device[@]}" --backend "$backend" --width "$width" --height "$height" \
        --spp "$spp" --no-exr --no-png --report "$report" >"$out/log" 2>&1; then
      python3 - "$report" "$name" "$backend" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
print(f"{sys.argv[2]:<18} {sys.argv[3]:<9} {r['first_sample_s']:>10.3f} s {r['per_sample_s'] * 1e3:>11.2f} ms "
      f"{r['rays_per_s'] / 1e6:>8.2f} M/s {r['dropped_samples']:>12}")
PY
    else
      printf '%-18s %-9s %s\n' "$name" "$backend" "not run: $(tail -n 1 "$out/log")"
    fi
  done
done
