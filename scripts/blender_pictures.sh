#!/usr/bin/env bash
# Regenerates docs/blender.md's pictures: the add-on's panel during and after a modal Create in
# Blender's window under Xvfb, a quilted sphere and two spheres painted and raised from data/bricks.png,
# rendered with Cycles on the CPU. Needs a build with the
# Python module (scripts/build.sh --tests), Blender and xvfb-run.
set -euo pipefail
cd "$(dirname "$0")/.."
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
blender -b --factory-startup --python-expr "import bpy; bpy.ops.wm.save_as_mainfile(filepath='$work/start.blend')" >/dev/null
xvfb-run -a -s "-screen 0 1280x1280x24" blender --factory-startup "$work/start.blend" \
  --python blender/examples/panel_screenshot.py -- "$PWD/build/python" "$PWD" docs/images/blender_panel.png \
  docs/images/blender_progress.png >/dev/null
blender -b --factory-startup --python blender/examples/render_quilted_sphere.py -- \
  "$PWD/build/python" "$PWD" docs/images/blender_sphere.png >/dev/null
blender -b --factory-startup --python blender/examples/render_painted_spheres.py -- \
  "$PWD/build/python" "$PWD" docs/images/blender_painted_spheres.png >/dev/null
echo "wrote docs/images/blender_panel.png, blender_progress.png, blender_sphere.png and blender_painted_spheres.png"
