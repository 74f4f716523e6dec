#!/usr/bin/env python3
"""Quilts a fixed sample of foreign swatches (make_swatches.py) and checks what must hold.

Usage:
  python3 foreign_corpus_test.py MESHQUILT WORK_DIR [--seeds FIRST-LAST] [FAMILY ...]

With --seeds, every family of SAMPLE is quilted with each seed in the range instead of SAMPLE's.

For each (family, seed) of SAMPLE: the swatch is made, `meshquilt swatch check` must accept it
(the border-cut family: refuse it; synth leaves its cut elements out), `synth --plane 2x2` grows it, and `meshquilt inspect` of the
output must show every element closed, no intersecting face pairs, and coverage of the plane
asked >= 0.98 (inspect's cells as large as the swatch's largest gap, so its own holes are not
missing cover); ring mails must keep their links (LINKED_SHARE) and chains stay apart; yarns,
grown over 3 x 3 swatches, must continue across seams (YARN_MIN swatch lengths); over the
repository's sphere, the swatch's periods must be found (on_lattice). Seconds per
output face against our own `swatch wire --radius 0.07` are printed, not
asserted. A check listed in KNOWN_FAILURES is reported as a known failure and does not fail the
run. Exit 0 when every other check holds, 1 otherwise, 77 (skipped) without numpy.
Python 3 standard library; the swatches need numpy in some interpreter on the machine.
"""

import json
import os
import subprocess
import sys
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent

# One or two seeds a family, picked to cover the variants: wire-mesh 9 overlaps by 0.36 pitch,
# turned 230 degrees, unevenly sampled, jittered, 16 sides; wire-mesh 1 is short of abutting with
# fine rings; plain-weave 2 overlaps by 0.41 with domed caps, 5 is turned 332 degrees; mail-6in1
# 4 is turned 198 degrees, so its bounding box's corners are bare; border-cut 4 keeps a sparse
# 3 x 3 rings whose last column falls just past the plane's edge.
SAMPLE = [
    ("issue-wire", 1),
    ("wire-mesh", 9),
    ("wire-mesh", 1),
    ("plain-weave", 2),
    ("plain-weave", 5),
    ("mail-4in1", 2),
    ("mail-6in1", 1),
    ("mail-6in1", 4),
    ("chains-2in2", 2),
    ("border-cut", 1),
    ("border-cut", 4),
]
PLANE = "2x2"
# Yarns are grown over 3 x 3 swatches, where a yarn that continues across seams is >= 2 swatch
# lengths long (YARN_MIN); a yarn cut at every seam is about one.
WOVEN_PLANE = "3x3"
YARN_MIN = 2.0
# 2-in-2 chains link only along a chain: the largest linked piece is one chain, a small share.
CHAIN_SHARE_MAX = 0.5
COVERAGE_MIN = 0.98
# Largest linked piece of the output's ring graph, as a share of its rings. Each swatch is one
# piece, and so is its tiling; the output may only lose links where patches meet and where
# rings hang past the plane's border. The bars are set below what the product gives today
# (4-in-1: 1.0; 6-in-1: 1.0 on the sample) with room for a ring or two cut off at the border.
LINKED_SHARE = {"mail-4in1": 0.9, "mail-6in1": 0.9}
WOVEN = {"issue-wire", "wire-mesh", "plain-weave"}
# Over a curved base (the repository's sphere at --scale 0.5) the layout's seams continue by the
# swatch's periods only where they are found: from centroids for rings, from the surface for
# yarns, refined where jitter and uneven sampling put the centroids off.
SPHERE = HERE.parent.parent / "data" / "sphere.off"

# (family, seed, check): why it fails today. Printed as KNOWN FAILURE, not counted.
KNOWN_FAILURES = {}


def find_numpy_python():
    for candidate in [sys.executable, "/usr/bin/python3", "python3"]:
        try:
            if subprocess.run([candidate, "-c", "import numpy"], capture_output=True).returncode == 0:
                return candidate
        except OSError:
            continue
    return None


class Run:
    def __init__(self, meshquilt, work, python):
        self.meshquilt, self.work, self.python = meshquilt, work, python
        self.failures, self.known, self.rows = [], [], []

    def cli(self, *args, expect=0):
        start = time.monotonic()
        done = subprocess.run([self.meshquilt, *map(str, args)], capture_output=True, text=True,
                              env=dict(os.environ, MESHQUILT_CACHE=str(self.work / "grids")))
        seconds = time.monotonic() - start
        if expect is not None and done.returncode != expect:
            raise RuntimeError("meshquilt %s: exit %d (expected %d)\n%s%s" % (
                " ".join(map(str, args)), done.returncode, expect, done.stdout, done.stderr))
        return done, seconds

    def check(self, family, seed, name, holds, detail):
        known = KNOWN_FAILURES.get((family, seed, name))
        if holds and known:
            print("  now holds, remove from KNOWN_FAILURES: %s: %s (%s)" % (name, detail, known))
        elif holds:
            print("  ok   %s: %s" % (name, detail))
        elif known:
            print("  KNOWN FAILURE %s seed %d: %s: %s [%s]" % (family, seed, name, detail, known))
            self.known.append((family, seed, name, detail))
        else:
            print("  FAIL %s seed %d: %s: %s" % (family, seed, name, detail))
            self.failures.append((family, seed, name, detail))

    def synth(self, swatch, out, plane=PLANE):
        stats = out.with_suffix(".json")
        done, seconds = self.cli("synth", "--swatch", swatch, "--plane", plane, "--seed", 1, "--progress", "none",
                                 "--backend", "cpu", "-o", out, "--stats", stats)
        return json.loads(stats.read_text()), seconds

    def inspect(self, out, stats, swatch, *extra):
        rect = ",".join("%.9g" % v for v in stats["plane_rect"])
        done, _ = self.cli("inspect", out, "--json", "--plane", "--region", rect, "--swatch", swatch, *extra)
        return json.loads(done.stdout)

    def ours(self):
        swatch = self.work / "ours_wire.ply"
        self.cli("swatch", "wire", "--radius", 0.07, "-o", swatch)
        out = self.work / "ours_wire_out.ply"
        stats, seconds = self.synth(swatch, out, WOVEN_PLANE)
        report = self.inspect(out, stats, swatch, "--yarns")
        per_face = stats["seconds"] / max(1, stats["faces"])
        print("ours: swatch wire --radius 0.07 over %s: %d faces, %.1f s, %.3g s/face, yarns %.2f swatch lengths"
              % (WOVEN_PLANE, stats["faces"], stats["seconds"], per_face, report["yarns"].get("in_swatch_lengths", float("nan"))))
        return per_face

    def curved(self, family, seed, swatch):
        out = self.work / ("%s_%d_sphere.ply" % (family, seed))
        stats_file = out.with_suffix(".json")
        self.cli("synth", "--swatch", swatch, "--base", SPHERE, "--scale", 0.5, "--seed", 1, "--progress", "none",
                 "--backend", "cpu", "-o", out, "--stats", stats_file)
        stats = json.loads(stats_file.read_text())
        self.check(family, seed, "periods found on the sphere", stats["on_lattice"],
                   "on_lattice %s, %d elements, %d rejected inputs" % (
                       stats["on_lattice"], stats["elements"], stats["rejected_inputs"]))

    def family(self, family, seed, ours_per_face, curved):
        print("%s seed %d" % (family, seed))
        swatch = self.work / ("%s_%d.ply" % (family, seed))
        made = subprocess.run([self.python, str(HERE / "make_swatches.py"), "--family", family, "--seed", str(seed),
                               "-o", str(swatch)], capture_output=True, text=True)
        if made.returncode != 0:
            self.check(family, seed, "swatch made", False, made.stderr.strip())
            return
        print("  " + made.stdout.strip())
        check, _ = self.cli("swatch", "check", swatch, expect=None)
        if family == "border-cut":
            self.check(family, seed, "swatch check refuses it", check.returncode == 16 and "cut open by the border" in check.stdout,
                       "exit %d: %s" % (check.returncode, check.stdout.strip()))
        else:
            self.check(family, seed, "swatch check accepts it", check.returncode == 0,
                       "exit %d: %s" % (check.returncode, (check.stdout + check.stderr).strip()))

        out = self.work / ("%s_%d_out.ply" % (family, seed))
        try:
            stats, _ = self.synth(swatch, out, WOVEN_PLANE if family in WOVEN else PLANE)
        except RuntimeError as error:
            self.check(family, seed, "synth runs", False, str(error).splitlines()[0])
            return
        extra = ["--yarns"] if family in WOVEN else ["--rings"]
        report = self.inspect(out, stats, swatch, *extra)
        row = dict(family=family, seed=seed, faces=stats["faces"], seconds=stats["seconds"],
                   coverage=report["coverage"], intersecting=report["intersecting_face_pairs"],
                   elements=report["elements"], closed=report["closed_elements"],
                   dropped_open=stats.get("dropped_open", 0), cut=stats.get("cut_swatch_elements", 0),
                   holes=stats.get("holes", 0))

        if family == "border-cut":
            # The swatch's cut elements are left out and counted: nothing is quilted open.
            self.check(family, seed, "cut elements left out",
                       report["closed_elements"] == report["elements"] and stats.get("cut_swatch_elements", 0) > 0,
                       "%d of %d output elements closed, cut_swatch_elements %d" % (
                           report["closed_elements"], report["elements"], stats.get("cut_swatch_elements", 0)))
        else:
            self.check(family, seed, "every element closed", report["closed_elements"] == report["elements"],
                       "%d of %d" % (report["closed_elements"], report["elements"]))
        self.check(family, seed, "no intersecting face pairs", report["intersecting_face_pairs"] == 0,
                   "%d pairs" % report["intersecting_face_pairs"])
        self.check(family, seed, "coverage >= %.2f" % COVERAGE_MIN, report["coverage"] >= COVERAGE_MIN,
                   "%.4f of the plane asked (holes %d)" % (report["coverage"], stats.get("holes", 0)))
        if family in LINKED_SHARE:
            rings = report["rings"]
            row.update(pieces=rings["pieces"], linked_share=rings["largest_piece_share"])
            self.check(family, seed, "largest linked piece >= %.2f" % LINKED_SHARE[family],
                       rings["largest_piece_share"] >= LINKED_SHARE[family],
                       "%.3f of %d rings (%d pieces)" % (rings["largest_piece_share"], rings["rings"], rings["pieces"]))
        elif family == "chains-2in2":
            rings = report["rings"]
            row.update(pieces=rings["pieces"], linked_share=rings["largest_piece_share"])
            self.check(family, seed, "chains stay apart: largest linked piece <= %.2f" % CHAIN_SHARE_MAX,
                       rings["pieces"] > 1 and rings["largest_piece_share"] <= CHAIN_SHARE_MAX,
                       "%.3f of %d rings (%d pieces)" % (rings["largest_piece_share"], rings["rings"], rings["pieces"]))
        elif "rings" in report:
            rings = report["rings"]
            row.update(pieces=rings["pieces"], linked_share=rings["largest_piece_share"])
            print("  rings: %d, %d pieces, largest %.3f (printed, not asserted)" % (
                rings["rings"], rings["pieces"], rings["largest_piece_share"]))
        if family in WOVEN:
            per_face = stats["seconds"] / max(1, stats["faces"])
            lengths = report["yarns"].get("in_swatch_lengths", float("nan"))
            row.update(yarn_lengths=lengths, per_face_vs_ours=per_face / ours_per_face)
            self.check(family, seed, "yarns continue: median >= %.1f swatch lengths" % YARN_MIN, lengths >= YARN_MIN,
                       "%.2f over %s" % (lengths, WOVEN_PLANE))
            print("  %.3g s/face, %.2f x ours; stitched_pairs %d (printed, not asserted)"
                  % (per_face, per_face / ours_per_face, stats.get("stitched_pairs", 0)))
        if curved and family != "border-cut":
            self.curved(family, seed, swatch)
        self.rows.append(row)


def main(argv):
    if len(argv) < 2:
        print(__doc__)
        return 2
    meshquilt, work = argv[0], Path(argv[1])
    rest = argv[2:]
    sample = SAMPLE
    # The curved check runs on the fixed sample; the seeds run stays planar.
    curved = True
    if rest[:1] == ["--seeds"] and len(rest) >= 2:
        curved = False
        first, last = (int(x) for x in rest[1].split("-"))
        families = list(dict.fromkeys(family for family, _ in SAMPLE))
        sample = [(family, seed) for family in families for seed in range(first, last + 1)]
        rest = rest[2:]
    only = set(rest)
    python = find_numpy_python()
    if python is None:
        print("skipped: no Python with numpy (Debian: apt-get install python3-numpy)")
        return 77
    work.mkdir(parents=True, exist_ok=True)
    run = Run(meshquilt, work, python)
    ours_per_face = run.ours()
    for family, seed in sample:
        if not only or family in only:
            try:
                run.family(family, seed, ours_per_face, curved)
            except RuntimeError as error:
                run.check(family, seed, "commands run", False, str(error))
    print("\nsummary (one JSON object per swatch):")
    for row in run.rows:
        print(json.dumps(row))
    for family, seed, name, detail in run.known:
        print("known failure: %s seed %d: %s: %s" % (family, seed, name, detail))
    if run.failures:
        print("%d checks failed" % len(run.failures))
        return 1
    print("foreign corpus: every check holds (%d known failures)" % len(run.known))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
