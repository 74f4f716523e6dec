#!/usr/bin/env bash
# Builds the Blender add-on as one zip with the Python module inside it, for Preferences >
# Add-ons > Install: no module folder to set afterwards.
#   bash scripts/blender_addon.sh [OUT.zip]   (default: out/meshquilt_blender.zip; the build in
#   MESHQUILT_BUILD_DIR, default build/)
# The module is built for the Python that builds it (Debian's Blender runs Debian's Python 3.11).
set -euo pipefail
cd "$(dirname "$0")/.."
out=$(realpath -m "${1:-out/meshquilt_blender.zip}")
build=${MESHQUILT_BUILD_DIR:-build}
[ -f "$build/build.ninja" ] || bash scripts/build.sh --tests >/dev/null
cmake --build "$build" --target _meshquilt >/dev/null
stage=$(mktemp -d); trap 'rm -rf "$stage"' EXIT
cp -r blender/meshquilt_blender "$stage/"
find "$stage" -name __pycache__ -prune -exec rm -rf {} +
mkdir -p "$stage/meshquilt_blender/module"
cp -r "$build/python/meshquilt" "$stage/meshquilt_blender/module/"
find "$stage" -name __pycache__ -prune -exec rm -rf {} +
mkdir -p "$(dirname "$out")"
rm -f "$out"
(cd "$stage" && /usr/bin/python3 -m zipfile -c "$out" meshquilt_blender)
echo "wrote $out: install it in Blender (Preferences > Add-ons > Install), then enable meshquilt"
