#!/usr/bin/env bash
# Repeating textures against their floor and against another build: the jobs of the lattice-copy
# work, run in turn with each binary (median of RUNS wall-clock seconds), with the plain tiling
# of perf/plain_tiling.py as the floor and the quality measures that must hold.
# Usage: perf/repeat_speed.sh NEW_CLI [OLD_CLI] [RUNS] [BASE]
#   BASE: the base of the large mail job (default ../shared/data/meshes/bunny.off; skipped if absent)
set -euo pipefail
new=$(realpath "$1"); old=${2:+$(realpath "$2")}; runs=${3:-3}
root=$(cd "$(dirname "$0")/.." && pwd)
base=${4:-$root/../shared/data/meshes/bunny.off}
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
cd "$work"
"$new" swatch chainmail --preset small --seed 3 -o small.off >/dev/null
"$new" swatch chainmail --rows 6 --columns 5 --ring-segments 16 --wire-segments 6 -o mail.ply >/dev/null
"$new" swatch chainmail --rows 4 --columns 4 --ring-segments 16 --wire-segments 6 -o builtin.ply >/dev/null
"$new" swatch weave --pattern twill:2/2 -o twill.off >/dev/null
"$new" swatch fruit -o fruit.off >/dev/null
cp "$root/data/sphere.off" sphere.off

jobs=("plane4x4-small-mail|--swatch small.off --plane 4x4|small.off"
      "default-job|--base sphere.off --scale 0.2|builtin.ply"
      "twill-4x4|--swatch twill.off --plane 4x4|"
      "fruit-3x3|--swatch fruit.off --plane 3x3|")
[ -f "$base" ] && jobs+=("mail-over-$(basename "$base" .off)-0.08|--swatch mail.ply --base $base --scale 0.08|mail.ply")

median() { sort -g | awk '{a[NR]=$1} END {print (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2}'; }
wall() { local start end; start=$(date +%s.%N); "$@" >/dev/null 2>&1; end=$(date +%s.%N); echo "$end - $start" | bc -l; }
rings() {  # linked to >= 3, largest piece, elements
  "$new" inspect "$1" --rings --swatch "$2" --json 2>/dev/null |
    /usr/bin/python3 -c 'import json,sys; d=json.load(sys.stdin); r=d["rings"]; print("%.3f %.3f %d" % (r["linked_to_3_share"], r["largest_piece_share"], d["elements"]))'
}

echo "| job | faces | new s | old s | new / old | floor s | new / floor | new rings >= 3, largest piece, elements | old |"
echo "|---|---|---|---|---|---|---|---|---|"
for job in "${jobs[@]}"; do
  IFS='|' read -r name args ring_swatch <<<"$job"
  : >new.t; : >old.t
  for ((r = 0; r < runs; ++r)); do
    # shellcheck disable=SC2086
    wall "$new" synth $args --backend cpu --progress none --stats new.json -o new.ply >>new.t
    # shellcheck disable=SC2086
    [ -n "$old" ] && wall "$old" synth $args --backend cpu --progress none --stats old.json -o old.ply >>old.t
  done
  faces=$(/usr/bin/python3 -c 'import json; print(json.load(open("new.json"))["faces"])')
  n=$(median <new.t); o=-; ratio=-; old_rings=-
  if [ -n "$old" ]; then o=$(median <old.t | xargs printf "%.2f"); ratio=$(echo "$n / $o" | bc -l | xargs printf "%.2f"); fi
  floor=-; over=-
  if [[ "$args" == *--plane* ]]; then  # the floor: the same swatch tiled to the same faces
    swatch=$(echo "$args" | awk '{print $2}')
    floor=$(/usr/bin/python3 "$root/perf/plain_tiling.py" "$swatch" "$faces" tile.ply --runs 5)
    over=$(echo "$n / $floor" | bc -l | xargs printf "%.0f")
  fi
  new_rings=-
  if [ -n "$ring_swatch" ]; then
    new_rings=$(rings new.ply "$ring_swatch")
    [ -n "$old" ] && old_rings=$(rings old.ply "$ring_swatch")
  fi
  printf "| %s | %s | %.2f | %s | %s | %s | %s | %s | %s |\n" "$name" "$faces" "$n" "$o" "$ratio" "$floor" "$over" "$new_rings" "$old_rings"
done
