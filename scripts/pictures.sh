#!/usr/bin/env bash
# Regenerates the README's pictures in docs/images/ from the built CLI: small swatches quilted
# over a 4x4 plane, rendered from the top (the relief tiles oblique) with one colour per element.
# Run after a build; MESHQUILT=path/to/meshquilt picks another executable. Takes a few minutes on
# two cores, and 10-20 more with ../shared (the bunny with the default swatches).
set -euo pipefail
cd "$(dirname "$0")/.."
meshquilt=${MESHQUILT:-build/cli/meshquilt}
[ -x "$meshquilt" ] || { echo "pictures.sh: $meshquilt not found; run scripts/build.sh first" >&2; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p docs/images

# picture NAME VIEW SWATCH-ARGS...: swatch, quilt over 4x4, render to docs/images/NAME.png.
picture() {
  local name=$1 view=$2
  shift 2
  "$meshquilt" swatch "$@" --preset small -o "$work/$name-swatch.ply" >/dev/null
  "$meshquilt" synth --swatch "$work/$name-swatch.ply" --plane 4x4 --backend cpu --progress none -o "$work/$name.ply" >/dev/null
  "$meshquilt" render "$work/$name.ply" --view "$view" --mode elements --size 800x600 -o "docs/images/$name.png"
}

picture chainmail top chainmail
picture twill top weave --pattern twill:2/3
picture fruit top fruit --seed 7
picture wire top wire
picture heightfield oblique heightfield --tiles 4

# The default curved job: the built-in chain mail over the shipped sphere.
"$meshquilt" synth --base data/sphere.off --scale 0.2 --backend cpu --progress none -o "$work/sphere.ply" \
  --preview docs/images/sphere_chainmail.png >/dev/null

# Curved, from ../shared when it is there: the bunny in chain mail and in a weave along a field.
bunny=../shared/data/meshes/bunny.off
# Editing (the paper's Figure 9) and a swatch animation.
"$meshquilt" swatch weave --preset small -o "$work/weave_small.ply" >/dev/null
"$meshquilt" synth --swatch "$work/weave_small.ply" --plane 3x3 --backend cpu --progress none -o "$work/wicker.ply" >/dev/null
"$meshquilt" edit "$work/wicker.ply" -o "$work/wicker_colour.ply" --color-by source --palette b5651d,e8c07a,8b4513,d2a56d >/dev/null
"$meshquilt" edit "$work/wicker.ply" -o "$work/wicker_aged.ply" --age 0.1 --seed 3 --color-by source \
  --palette b5651d,e8c07a,8b4513,d2a56d >/dev/null
"$meshquilt" render "$work/wicker_colour.ply" --mode colors --size 640x480 -o docs/images/edit_before.png
"$meshquilt" render "$work/wicker_aged.ply" --mode colors --size 640x480 -o docs/images/edit_aged.png
"$meshquilt" swatch vine --frames 12 -o "$work/vine.ply" >/dev/null
"$meshquilt" synth --swatch "$work/vine.ply" --plane 3x3 --provenance --backend cpu --progress none -o "$work/vines.ply" >/dev/null
"$meshquilt" animate --quilt "$work/vines.ply" --swatch "$work/vine.ply" --swatch-frames "$work/vine_frames" \
  -o "$work/vine_out" >/dev/null
for k in 00 03 06 09; do
  "$meshquilt" render "$work/vine_out/frame_00$k.ply" --view front --size 320x240 -o "docs/images/vine_frame_$k.png"
done

if [ -f "$bunny" ]; then
  "$meshquilt" swatch chainmail --preset small -o "$work/chain.ply" >/dev/null
  "$meshquilt" swatch weave --preset small -o "$work/weave.ply" >/dev/null
  # The default swatches at the curved issue's scales (about 56 copies each): 5-15 minutes.
  "$meshquilt" swatch chainmail -o "$work/chain_default.ply" >/dev/null
  "$meshquilt" swatch weave -o "$work/weave_default.ply" >/dev/null
  "$meshquilt" synth --swatch "$work/chain_default.ply" --base "$bunny" --scale 0.14 --backend cpu --progress none \
    -o "$work/bunny_chain.ply" >/dev/null
  "$meshquilt" render "$work/bunny_chain.ply" --view side --size 800x640 -o docs/images/bunny_chainmail.png
  "$meshquilt" synth --swatch "$work/weave_default.ply" --base "$bunny" --scale 0.13 --field data/bunny_field.json \
    --backend cpu --progress none -o "$work/bunny_weave.ply" >/dev/null
  "$meshquilt" render "$work/bunny_weave.ply" --view side --mode elements --size 800x640 -o docs/images/bunny_weave_field.png
  # One texture in a thick layer (twice the rings' height), placed through the shell map and by
  # displacement along normals (the paper's Figure 8).
  "$meshquilt" synth --swatch "$work/chain.ply" --base "$bunny" --scale 0.16 --shell-height 0.0107 --no-cleanup \
    --backend cpu --progress none --write-texture "$work/thick.mqt" -o "$work/thick_shell.ply" >/dev/null
  "$meshquilt" embed --embed normal --texture "$work/thick.mqt" --base "$bunny" -o "$work/thick_normal.ply" >/dev/null
  "$meshquilt" render "$work/thick_shell.ply" --mode elements --size 800x600 -o docs/images/bunny_thick_shell.png
  "$meshquilt" render "$work/thick_normal.ply" --mode elements --size 800x600 -o docs/images/bunny_thick_normal.png
  # Ring size over the bunny (#65's job) and the mail round a cone of each sign.
  "$meshquilt" swatch chainmail --rows 6 --columns 5 --ring-segments 16 --wire-segments 6 -o "$work/mail65.ply" >/dev/null
  "$meshquilt" synth --swatch "$work/mail65.ply" --base "$bunny" --scale 0.08 --seed 1 --backend cpu --progress none \
    --stats "$work/mail65.json" -o "$work/bunny_mail65.ply" >/dev/null
  "$meshquilt" render "$work/bunny_mail65.ply" --up y --view front --size 800x640 -o docs/images/bunny_ring_size.png
  "$meshquilt" synth --swatch "$work/mail65.ply" --base "$bunny" --scale 0.08 --seed 1 --size-hold 10 --backend cpu \
    --progress none -o "$work/bunny_mail65_held.ply" >/dev/null
  "$meshquilt" render "$work/bunny_mail65_held.ply" --up y --view front --size 800x640 -o docs/images/bunny_ring_size_held.png
  read -r plus minus < <(python3 - "$work/mail65.json" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
at = lambda sign: ",".join(map(str, next(p for p, k in zip(s["cone_points"], s["cone_indices"]) if k * sign > 0)))
print(at(1), at(-1))
PY
)
  "$meshquilt" render "$work/bunny_mail65.ply" --up y --around "$plus" --radius 0.02 --size 640x512 \
    -o docs/images/bunny_cone_plus.png
  "$meshquilt" render "$work/bunny_mail65.ply" --up y --around "$minus" --radius 0.02 --size 640x512 \
    -o docs/images/bunny_cone_minus.png
fi
