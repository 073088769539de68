#!/usr/bin/env bash
# Fuzzes every parser of untrusted input (tests/fuzz): builds the libFuzzer targets with clang, ASan and UBSan
# in build/fuzz and runs each for SECONDS (default 600). Crashes land in build/fuzz/tests/fuzz/artifacts/;
# minimise one with `<fuzzer> -minimize_crash=1 FILE` and commit it under tests/fuzz/regressions/<target>/.
#
#   tools/fuzz.sh [SECONDS]
set -euo pipefail
seconds=${1:-600}
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$root"
tools/setup.sh deps
missing=()
for package in clang-14 libclang-rt-14-dev; do
  dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q '^install ok installed$' || missing+=("$package")
done
if [[ ${#missing[@]} -gt 0 ]]; then
  echo "fuzz: installing ${missing[*]}"
  apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
cmake --preset fuzz -DRAYLAB_FUZZ_SECONDS="$seconds" >/dev/null
cmake --build --preset fuzz --target gltf_fuzzer environment_fuzzer image_exr_fuzzer brdf_csv_fuzzer fit_target_fuzzer \
  nbrdf_fuzzer view_script_fuzzer raylab
ctest --preset fuzz -R '_fuzz$'
