#!/bin/bash
# skein's knitout of AutoKnit's test-A, test-B and test-C against AutoKnit's own knitout of the
# same stitch graphs, counted by one rule for both: a transfer pass is a run of `xfer`s at one
# rack, a knitting pass a run of stitches (knit, tuck, split, miss) one way with one carrier set;
# drops are not passes (AutoKnit's files end by dropping every loop); a rack change is a `rack`
# to another value. skein on generic, whole and with its bind-off chains left out.
#   bench/knitout_autoknit.sh [build/skein] [source dir] [AutoKnit's knitout dir]
set -eu
skein=${1:-build/skein}
source_dir=${2:-.}
autoknit_dir=${3:-$source_dir/../shared/data/autoknit-knitout}
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
count() {
  awk -v rack=0 '
    /^(knit|tuck|split|miss) / {
      carriers = ""
      for (i = ($1 == "split" ? 5 : 4); i <= NF; i++) carriers = carriers " " $i
      if ("s" $2 carriers != last) { knitting++; last = "s" $2 carriers }
    }
    /^xfer / { xfers++; if ("x" rack != last) { moving++; last = "x" rack } }
    /^rack / { if ($2 + 0 != rack + 0) { changes++; rack = $2 } }
    END { printf "%d (%d + %d), %d, %d", knitting + moving, knitting, moving, xfers, changes }'
}
echo "| graph | AutoKnit: passes (knit + xfer), transfers, rack changes | skein | skein, its bind-off chains left out |"
echo "|---|---|---|---|"
for graph in test-A test-B test-C; do
  "$skein" compile "$source_dir/samples/autoknit/$graph.st" -t knitout -m generic \
    -o "$scratch/$graph.k" --force >/dev/null
  without_chains=$(awk '/^;!source/ { skip = /bind-off/ } !skip' "$scratch/$graph.k" | count)
  echo "| $graph | $(count <"$autoknit_dir/$graph.k") | $(count <"$scratch/$graph.k") | $without_chains |"
done
