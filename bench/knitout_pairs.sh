#!/bin/bash
# The knitout target over every model/machine pair: each knittable sample and each `skein new`
# shape (default sizes) on generic, swg091n2 and kniterate. A pair is proven (exit 0: written
# and proven by the v-bed), refused by name (exit 3: UnsupportedError before writing) or failing
# (anything else). For a proven pair: carriage passes, transfers and rack changes.
#   bench/knitout_pairs.sh [build/skein] [source dir]
set -u
skein=${1:-build/skein}
source_dir=${2:-.}
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
models=()
for sample in auto-shift-path/tube.obj autoknit/test-A.st autoknit/test-B.st autoknit/test-C.st \
  beanie/beanie.yaml hat/hat.obj letter-h/letter-h.yaml letter-i/letter-i.yaml \
  letter-r/letter-r.yaml rib-swatch/rib-swatch.obj short-row-wedge/short-row-wedge.yaml \
  sock/sock.yaml swatch/swatch.yaml sweater/sweater.yaml teapot/teapot.yaml \
  three-bars/three-bars.yaml three-bars-own/three-bars-own.yaml two-bars/two-bars.yaml; do
  models+=("$source_dir/samples/$sample")
done
for shape in sheet tube hat sock sweater set-in-sweater mitten glove shorts trousers bag; do
  "$skein" new "$shape" -o "$scratch/new-$shape" >/dev/null
  models+=("$scratch/new-$shape.yaml")
done
proven=0 refused=0 failing=0
for model in "${models[@]}"; do
  for profile in generic swg091n2 kniterate; do
    out=$("$skein" compile "$model" -t knitout -m "$profile" -o "$scratch/out.k" --force 2>&1)
    status=$?
    name=$(basename "$model")
    case $status in
      0)
        proven=$((proven + 1))
        passes=$(grep -o 'carriage passes: [0-9]*' <<<"$out" | grep -o '[0-9]*$')
        counts=$(grep -o 'transfers: [0-9]*, rack changes: [0-9]*' <<<"$out")
        echo "proven  $name $profile: passes: $passes, $counts"
        ;;
      3)
        refused=$((refused + 1))
        echo "refused $name $profile: $(tail -1 <<<"$out")"
        ;;
      *)
        failing=$((failing + 1))
        echo "FAILING $name $profile (exit $status): $(tail -1 <<<"$out")"
        ;;
    esac
  done
done
echo "pairs: $proven proven, $refused refused by name, $failing failing (of $((proven + refused + failing)))"
