#!/usr/bin/env python3
"""Every case of the wild corpus (make_wild.py) gets its documented outcome from `meshquilt synth`.

Usage:
  python3 wild_corpus_test.py MESHQUILT WORK_DIR [--seeds FIRST-LAST] [--issue-wires]

For each seed, the clean swatch is quilted over --plane 2x2 and the clean base carries our small
chain mail at --scale 0.3; then each case, by its outcome:
  repaired  exit 0, the named repair counted in the stats JSON, and the job's measures as the
            clean file's: elements within 3% on a plane, 20% over a base (or 2), every element
            closed, on a plane coverage at most 0.01 below and the median yarn length at most 25%
            shorter,
            over a base the share left bare at most 0.01 above;
  accepted  the same, with no repair counted;
  quilted   exit 0 and every element closed;
  refused   the documented exit code, a one-line message naming the file (and the problem, where
            documented), and no output file left behind.
No command may crash or run past TIMEOUT seconds. With --issue-wires, the issue's two exported
wire swatches (tubes in, caps out) are quilted over --plane 3x3 --seed 2 beside their consistent
versions: median wire >= 2 swatch lengths, coverage >= 0.98; the per-face time ratio is printed.
Exit 0 when everything holds, 1 otherwise, 77 (skipped) without numpy.
"""

import json
import os
import subprocess
import sys
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent / "foreign"))
from foreign_corpus_test import find_numpy_python  # noqa: E402
TIMEOUT = 300
# Equally valid outputs differ: on a plane by the ties a repair reorders; over a base by where the
# layout's cones fall, which moves with the last bits of the coordinates and sets the rings' size
# (issue 65): the clean base of seed 1 with 1e-9 noise gives 273-285 elements, that of seed 5
# 284 and the same in millimetres 328. Bases are judged by what is bare, closed, and a margin.
ELEMENTS_SHARE = {"swatch": 0.03, "base": 0.2}
COVERAGE_DROP = 0.01
# Yarns may come out shorter by this share (longer is no fault): a soup's faces arrive in another
# order, so stitching takes other ties (seed 5: 2.27 swatch lengths against 2.69).
YARN_SHARE = 0.25


class Run:
    def __init__(self, meshquilt, work):
        self.meshquilt, self.work = meshquilt, work
        self.failures = 0

    def cli(self, *args):
        start = time.monotonic()
        try:
            done = subprocess.run([self.meshquilt, *map(str, args)], capture_output=True, text=True, timeout=TIMEOUT,
                                  env=dict(os.environ, MESHQUILT_CACHE=str(self.work / "grids")))
        except subprocess.TimeoutExpired:
            return None, TIMEOUT
        return done, time.monotonic() - start

    def check(self, name, holds, detail):
        print("  %s %s: %s" % ("ok  " if holds else "FAIL", name, detail))
        if not holds:
            self.failures += 1

    def job(self, role, path, out, plane="2x2", seed=1):
        """Runs the role's job on `path`; returns (process, stats, measures, seconds)."""
        stats_file = out.with_suffix(".json")
        for stale in (out, stats_file):
            if stale.exists():
                stale.unlink()
        if role == "swatch":
            args = ["--swatch", path, "--plane", plane]
        else:
            args = ["--swatch", self.work / "small_mail.ply", "--base", path, "--scale", 0.3]
        done, seconds = self.cli("synth", *args, "--seed", seed, "--backend", "cpu", "--progress", "none", "-o", out,
                                 "--stats", stats_file)
        if done is None or done.returncode != 0:
            return done, None, None, seconds
        stats = json.loads(stats_file.read_text())
        extra = ["--plane", "--region", ",".join("%.9g" % v for v in stats["plane_rect"]), "--swatch", path,
                 "--yarns"] if role == "swatch" else []
        report, _ = self.cli("inspect", out, "--json", *extra)
        measures = json.loads(report.stdout)
        if role == "base":  # the share of the base the texture leaves bare
            measures["hole_share"] = stats["hole_area"] / max(1e-300, stats["hole_area"] + stats["covered_area"])
        return done, stats, measures, seconds

    def same_job(self, measures, clean, role):
        """(holds, detail): measures within the stated tolerance of the clean file's."""
        problems = []
        elements, clean_elements = measures["elements"], clean["elements"]
        if abs(elements - clean_elements) > max(2, ELEMENTS_SHARE[role] * clean_elements):
            problems.append("elements %d vs %d" % (elements, clean_elements))
        if measures["closed_elements"] != elements:
            problems.append("%d of %d elements closed" % (measures["closed_elements"], elements))
        detail = "elements %d (clean %d)" % (elements, clean_elements)
        if role == "swatch":
            if measures["coverage"] < clean["coverage"] - COVERAGE_DROP:
                problems.append("coverage %.4f vs %.4f" % (measures["coverage"], clean["coverage"]))
            yarn, clean_yarn = (m["yarns"].get("in_swatch_lengths", 0.0) for m in (measures, clean))
            if yarn < (1.0 - YARN_SHARE) * clean_yarn:
                problems.append("yarns %.2f vs %.2f swatch lengths" % (yarn, clean_yarn))
            detail += ", coverage %.4f (%.4f), yarns %.2f (%.2f)" % (measures["coverage"], clean["coverage"], yarn,
                                                                     clean_yarn)
        else:
            holes, clean_holes = measures["hole_share"], clean["hole_share"]
            if holes > clean_holes + COVERAGE_DROP:
                problems.append("hole share %.4f vs %.4f" % (holes, clean_holes))
            detail += ", hole share %.4f (%.4f)" % (holes, clean_holes)
        return not problems, "; ".join(problems) or detail

    def case(self, entry, corpus, clean_measures):
        role, path = entry["role"], corpus / entry["file"]
        print("%s %s seed %d (%s, %s)" % (role, entry["case"], entry["seed"], entry["format"], entry["note"]))
        out = self.work / ("%s_%s_%d_out.ply" % (role, entry["case"], entry["seed"]))
        done, stats, measures, seconds = self.job(role, path, out)
        if done is None:
            self.check("finishes", False, "ran past %d s" % TIMEOUT)
            return
        self.check("no crash", done.returncode >= 0 and done.returncode != 1,
                   "exit %d%s" % (done.returncode, (": " + done.stderr.strip()) if done.returncode else ""))
        outcome = entry["outcome"]
        if outcome == "refused":
            lines = [line for line in done.stderr.splitlines() if line.startswith("meshquilt: ")]
            named = [line for line in lines if entry["file"] in line and entry["message"] in line]
            self.check("refused with exit %d" % entry["exit"], done.returncode == entry["exit"],
                       "exit %d" % done.returncode)
            self.check("one line naming the file and the problem", len(named) == 1,
                       lines[-1] if lines else "(nothing on stderr)")
            self.check("no output written", not out.exists(), str(out))
            return
        if done.returncode != 0:
            self.check("quilted", False, done.stderr.strip())
            return
        repairs = stats.get("repairs", {}).get(role, {})
        made = {k: v for k, v in repairs.items() if v}
        if outcome == "repaired":
            self.check("repair %s counted" % entry["repair"], repairs.get(entry["repair"], 0) > 0, str(made))
            said = [line for line in done.stderr.splitlines() if entry["file"] in line and "repaired:" in line]
            self.check("one line says what was repaired", len(said) == 1, said[0] if said else done.stderr.strip())
        elif outcome == "accepted":
            self.check("no repair needed", not made, str(made) or "none")
        if outcome in ("repaired", "accepted"):
            holds, detail = self.same_job(measures, clean_measures[(role, entry["seed"])], role)
            self.check("as the clean file quilts", holds, detail)
        else:
            self.check("every element closed", measures["closed_elements"] == measures["elements"],
                       "%d of %d" % (measures["closed_elements"], measures["elements"]))

    def issue_wires(self, python):
        corpus = self.work / "wires"
        corpus.mkdir(exist_ok=True)
        subprocess.run([python, str(HERE / "make_wild.py"), "--issue-wires", "-o", str(corpus)], check=True)
        for which in (1, 2):
            rows = {}
            for name in ("wire_%d.obj" % which, "wire_%d_consistent.off" % which):
                done, stats, measures, seconds = self.job("swatch", corpus / name,
                                                          self.work / (name.replace(".", "_") + "_out.ply"),
                                                          plane="3x3", seed=2)
                if stats is None:
                    self.check("wire %d: %s quilts" % (which, name), False, done.stderr.strip() if done else "timeout")
                    return
                rows[name] = (stats, measures)
                print("wire %d: %s: %d faces in %.1f s, %d patches, %d stitched pairs, coverage %.4f, yarns %.2f"
                      % (which, name, stats["faces"], stats["seconds"], stats["patches"], stats["stitched_pairs"],
                         measures["coverage"], measures["yarns"].get("in_swatch_lengths", 0.0)))
            (wild_stats, wild), (clean_stats, _) = rows["wire_%d.obj" % which], rows["wire_%d_consistent.off" % which]
            yarns = wild["yarns"].get("in_swatch_lengths", 0.0)
            self.check("wire %d as exported: median wire >= 2 swatch lengths" % which, yarns >= 2.0, "%.2f" % yarns)
            self.check("wire %d as exported: coverage >= 0.98" % which, wild["coverage"] >= 0.98,
                       "%.4f" % wild["coverage"])
            ratio = (wild_stats["seconds"] / wild_stats["faces"]) / (clean_stats["seconds"] / clean_stats["faces"])
            print("wire %d: per-face time as exported / consistent: %.2f (printed, not asserted)" % (which, ratio))


def main(argv):
    if len(argv) < 2:
        print(__doc__)
        return 2
    meshquilt, work = argv[0], Path(argv[1])
    first, last = 1, 1
    if "--seeds" in argv:
        first, last = (int(x) for x in argv[argv.index("--seeds") + 1].split("-"))
    python = find_numpy_python()
    if python is None:
        print("skipped: no Python with numpy (Debian: apt-get install python3-numpy)")
        return 77
    work.mkdir(parents=True, exist_ok=True)
    run = Run(meshquilt, work)
    if "--issue-wires" in argv:
        run.issue_wires(python)
    else:
        corpus = work / "corpus"
        subprocess.run([python, str(HERE / "make_wild.py"), "--seeds", "%d-%d" % (first, last), "-o", str(corpus)],
                       check=True)
        entries = json.loads((corpus / "manifest.json").read_text())
        run.cli("swatch", "chainmail", "--preset", "small", "-o", work / "small_mail.ply")
        clean_measures = {}
        for entry in entries:
            key = (entry["role"], entry["seed"])
            if key not in clean_measures:
                done, stats, measures, _ = run.job(entry["role"], corpus / entry["clean"],
                                                   work / ("clean_%s_%d_out.ply" % key))
                if measures is None:
                    run.check("clean %s seed %d quilts" % key, False, done.stderr.strip() if done else "timeout")
                    return 1
                clean_measures[key] = measures
        for entry in entries:
            run.case(entry, corpus, clean_measures)
    if run.failures:
        print("%d checks failed" % run.failures)
        return 1
    print("wild corpus: every check holds")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
