#!/usr/bin/env python3
"""The one source of the docs' figures: runs the benchmarks into docs/figures.json and writes
docs/performance.md and the README's figures from it.

    perf/figures.py measure [--only GROUP,...] [--old OLD_CLI] [--shared DIR]
    perf/figures.py write [--check]

`measure` runs each group (all by default) on this machine and keeps its figures with the commit,
date and machine that gave them; a group not run keeps its last figures. `write` fills
perf/figures/*.md.in ({{group.key}} or {{group.key:FORMAT}}) into the pages; `--check` fails
when a page differs from what the figures give (scripts/check_docs.py runs it).
"""
import argparse
import datetime
import json
import os
import platform
import re
import shutil
import statistics
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
FIGURES = os.path.join(ROOT, "docs", "figures.json")
TEMPLATES = os.path.join(ROOT, "perf", "figures")
CLI = os.path.join(ROOT, "build", "cli", "meshquilt")
PERF = os.path.join(ROOT, "build", "perf")
# The pages written, and where: a whole page, or the text between markers of a page.
PAGES = [("performance.md.in", "docs/performance.md", None),
         ("readme_sentence.md.in", "README.md", "default-job"),
         ("readme_table.md.in", "README.md", "performance-table")]


def run(args, env=None, cwd=None):
    done = subprocess.run(args, capture_output=True, text=True, env=env, cwd=cwd)
    if done.returncode != 0:
        sys.exit("figures: %s failed (exit %d): %s" % (" ".join(args), done.returncode, done.stderr.strip()[-400:]))
    return done.stdout


def timed(args, env=None, cwd=None):
    """Wall seconds and peak resident MiB of one run (from /usr/bin/time)."""
    done = subprocess.run(["/usr/bin/time", "-f", "TIME %e %M"] + args, capture_output=True, text=True, env=env,
                          cwd=cwd)
    if done.returncode != 0:
        sys.exit("figures: %s failed (exit %d): %s" % (" ".join(args), done.returncode, done.stderr.strip()[-400:]))
    line = [l for l in done.stderr.splitlines() if l.startswith("TIME ")][-1]
    seconds, kib = line.split()[1:]
    return float(seconds), int(kib) / 1024.0


def stage_shares(stages, count):
    total = sum(stages.values())
    top = sorted(stages.items(), key=lambda kv: -kv[1])[:count]
    return ", ".join("%s %.0f%%" % (name, 100.0 * seconds / total) for name, seconds in top)


def synth_stats(args, folder, env=None):
    stats = os.path.join(folder, "stats.json")
    seconds, mib = timed([CLI, "synth", *args, "--backend", "cpu", "--progress", "none", "--stats", stats, "-o",
                          os.path.join(folder, "out.ply")], env=env)
    with open(stats) as f:
        return seconds, mib, json.load(f)


def rings(mesh, swatch):
    args = [CLI, "inspect", mesh, "--rings", "--json"] + (["--swatch", swatch] if swatch else [])
    report = json.loads(run(args))
    return report


def measure_default_job(folder, options):
    env = dict(os.environ, MESHQUILT_CACHE=os.path.join(folder, "cache"))
    job = ["--base", os.path.join(ROOT, "data", "sphere.off"), "--scale", "0.2"]
    _, _, built = synth_stats(job, folder, env)  # the first job builds the grid
    runs, old_runs = [], []
    for _ in range(options.runs):
        runs.append(synth_stats(job, folder, env))
        if options.old:  # in turn, so both see the same machine
            old_runs.append(timed([options.old, "synth", *job, "--backend", "cpu", "--progress", "none", "-o",
                                   os.path.join(folder, "old.ply")], env=env)[0])
    seconds = statistics.median(r[0] for r in runs)
    stats = runs[-1][2]
    report = rings(os.path.join(folder, "out.ply"), None)
    against_old = ""
    if old_runs:
        old = statistics.median(old_runs)
        against_old = ("Run in turn with the build at %s, which takes %.2f s, the job takes %.2fx its time."
                       % (options.old_name or "OLD", old, seconds / old))
    return {"faces": stats["faces"], "elements": stats["elements"], "seconds": seconds,
            "peak_mib": statistics.median(r[1] for r in runs), "against_old": against_old,
            "patches": stats["patches"], "filled": stats.get("filled_elements", 0),
            "stages": stage_shares(stats["stages"], 7), "lattice_copies": stats.get("lattice_copies", 0),
            "grid_built": built["stages"]["index"], "grid_read": stats["stages"]["index"],
            "closed": report["closed_elements"], "intersecting": report["intersecting_face_pairs"],
            "linked_3": 100.0 * report["rings"]["linked_to_3_share"],
            "largest_piece": 100.0 * report["rings"]["largest_piece_share"]}


def without_default_job(table):
    """The table less its default-job row: the default_job group is that job's one figure."""
    return "\n".join(l for l in table.splitlines() if not l.startswith("| default-job |"))


def measure_repeat(folder, options):
    table = run(["bash", os.path.join(ROOT, "perf", "repeat_speed.sh"), CLI, options.old, str(options.runs),
                 os.path.join(options.shared, "data", "meshes", "bunny.off")], cwd=folder)
    table = without_default_job(table)
    names = [l.split("|")[1].strip() for l in table.splitlines() if l.startswith("| ")][1:]
    rows = table_rows(table, [n.replace("-", "_").replace(".", "_") for n in names if not n.startswith("---")])
    small = rows["plane4x4_small_mail"]
    return {"table": table.strip(), "rows": rows, "small_faces": int(small["faces"]), "old_name": options.old_name,
            "small_seconds": float(small["new_s"]), "small_floor": float(small["floor_s"]),
            "small_over_floor": float(small["new_over_floor"])}


def column_key(header):
    """"ours (s, median of 3)" -> ours, "ours / paper" -> ours_over_paper, "peak MiB" -> peak_mib."""
    text = re.sub(r" \(.*\)$", "", header.strip()).lower().replace(" / ", " over ")
    return re.sub(r"[^a-z0-9]+", "_", text).strip("_")


def table_rows(table, keys):
    """The rows of a markdown table, in order, as {key: {column_key(header): cell}}."""
    lines = [l for l in table.splitlines() if l.startswith("| ")]
    header = [column_key(c) for c in lines[0].strip("|").split("|")]
    rows = [[c.strip() for c in l.strip("|").split("|")] for l in lines[1:] if not l.startswith("|---")]
    if len(rows) != len(keys):
        sys.exit("figures: expected %d rows, got %d:\n%s" % (len(keys), len(rows), table))
    return {key: dict(zip(header, row)) for key, row in zip(keys, rows)}


def labelled_rows(table):
    """table_rows keyed by each row's first cell up to its "(": "Plane + Wire (1.56x1.56)" -> plane_wire."""
    labels = [l.split("|")[1] for l in table.splitlines() if l.startswith("| ")][1:]
    return table_rows(table, [column_key(l.split(" (")[0]) for l in labels])


def measure_table1(folder, options):
    runner = [os.path.join(PERF, "table1_runner"), "--backends", "cpu", "--runs", str(options.runs)]
    planar = run(runner + ["--scenarios", "wire,apple,twill"], cwd=folder).strip()
    curved = run(runner + ["--scenarios", "bunny-link,bunny-weave", "--shared", options.shared], cwd=folder).strip()
    rows = labelled_rows(planar)
    rows.update(labelled_rows(curved))
    return {"planar": planar, "curved": curved, "rows": rows}


def measure_scaling(folder, options):
    lines = ["| plane | faces out | patches | median (s) | microseconds per face | peak MiB |",
             "|---|---|---|---|---|---|"]
    values = {}
    for n in options.planes:
        runs = [synth_stats(["--plane", "%dx%d" % (n, n)], folder) for _ in range(1 if n > 16 else options.runs)]
        seconds = statistics.median(r[0] for r in runs)
        stats = runs[-1][2]
        per_face = 1e6 * seconds / stats["faces"]
        lines.append("| %dx%d | %s | %s | %.2f | %.1f | %.0f |" % (n, n, "{:,}".format(stats["faces"]),
                                                                 "{:,}".format(stats["patches"]), seconds, per_face,
                                                                 max(r[1] for r in runs)))
        values["plane%d" % n] = {"faces": stats["faces"], "seconds": seconds, "per_face": per_face,
                                 "peak_mib": max(r[1] for r in runs), "stages": stage_shares(stats["stages"], 4)}
    small, large = values["plane%d" % options.planes[-2]], values["plane%d" % options.planes[-1]]
    values["table"] = "\n".join(lines)
    values["large_over_small"] = large["per_face"] / small["per_face"]
    return values


def bench_output(args, folder):
    # Paths as a reader of the page would type them, from the repository's root.
    return run(args, cwd=folder).strip().replace(ROOT + "/", "")


def measure_benchmarks(folder, options):
    bunny = os.path.join(options.shared, "data", "meshes", "bunny.off")
    sphere = os.path.join(ROOT, "data", "sphere.off")
    bricks = os.path.join(ROOT, "data", "bricks.ppm")
    return {
        "matching_cost": bench_output([os.path.join(PERF, "matching_cost_bench")], folder),
        "inspect": bench_output([os.path.join(PERF, "inspect_bench")], folder),
        "mesh_io": bench_output([os.path.join(PERF, "mesh_io_bench")], folder),
        "paint": bench_output([os.path.join(PERF, "paint_bench"), sphere, bricks, "--scale", "0.3"], folder),
        "embed": bench_output([os.path.join(PERF, "embed_bench"), bunny, "--runs", str(options.runs)], folder),
        "stretch": bench_output([os.path.join(PERF, "stretch_bench"), bunny, "--height", "0.0054", "--height",
                                 "0.0107"], folder),
    }


def measure_quality(folder, options):
    return {"table": run([os.path.join(PERF, "quality_suite"), "--seeds", "1,2,3"], cwd=folder).strip()}


def numpy_python():
    """A Python of this machine with numpy (Debian's, beside a pyenv one without it)."""
    for candidate in (sys.executable, "/usr/bin/python3"):
        if subprocess.run([candidate, "-c", "import numpy"], capture_output=True).returncode == 0:
            return candidate
    sys.exit("figures: the loom group needs a Python with numpy (Debian: apt-get install python3-numpy)")


def measure_loom(folder, options):
    """The loom over the three-region design of tests/loom/loom_design.py from three exemplars:
    the assignment of 2,048 x 2,048 crossings alone, and the fabric of 512 x 512."""
    sys.path.insert(0, os.path.join(ROOT, "tests", "loom"))
    from loom_design import three_regions, write_pbm  # noqa: E402
    w = lambda name: os.path.join(folder, name)
    run([numpy_python(), os.path.join(ROOT, "tests", "loom", "make_exemplar.py"), w("plain.obj"), "--tilt", "7"])
    run([CLI, "swatch", "weave", "--pattern", "twill:2/2", "--warps", "8", "--wefts", "8", "-o", w("twill.ply")])
    run([CLI, "swatch", "weave", "--pattern", "satin:4/1", "--warps", "10", "--wefts", "10", "--sides", "6", "-o",
         w("satin.ply")])
    values = {}
    for size, extra in ((2048, ["--assignment-only"]), (512, [])):
        write_pbm(w("design.pbm"), three_regions(size))
        out = w("out.txt" if extra else "out.ply")
        seconds, mib = timed([CLI, "loom", "--design", w("design.pbm"), "--exemplar", w("plain.obj"), "--exemplar",
                              w("twill.ply"), "--exemplar", w("satin.ply"), "-o", out, "--stats", w("loom.json"),
                              "--progress", "none", *extra])
        with open(w("loom.json")) as f:
            summary = json.load(f)
        loom = summary["loom"]
        values["design%d" % size] = {"seconds": seconds, "peak_mib": mib, "faces": summary.get("faces", 0),
                                     "consistent": loom["assignment"]["consistent"],
                                     "continuous": loom["assignment"]["continuous"],
                                     "megabytes": os.path.getsize(out) / 1e6}
    return values


GROUPS = {"default_job": measure_default_job, "repeat": measure_repeat, "table1": measure_table1,
          "scaling": measure_scaling, "benchmarks": measure_benchmarks, "quality": measure_quality,
          "loom": measure_loom}


def machine():
    model = platform.processor() or platform.machine()
    try:
        with open("/proc/cpuinfo") as f:
            model = next(l.split(":", 1)[1].strip() for l in f if l.startswith("model name"))
    except (OSError, StopIteration):
        pass
    gpu = "no GPU" if not any(os.path.exists(p) for p in ("/dev/nvidia0", "/dev/dri/renderD128")) else "a GPU"
    return "%d cores (%s), %s" % (os.cpu_count(), model, gpu)


def load():
    if not os.path.exists(FIGURES):
        return {}
    with open(FIGURES) as f:
        return json.load(f)


def measure(options):
    figures = load()
    commit = run(["git", "-C", ROOT, "rev-parse", "--short", "HEAD"]).strip()
    if run(["git", "-C", ROOT, "status", "--porcelain", "--untracked-files=no"]).strip():
        commit += "+changes"
    for name in options.only:
        print("figures: measuring %s" % name, flush=True)
        with tempfile.TemporaryDirectory() as folder:
            values = GROUPS[name](folder, options)
        figures[name] = {"commit": commit, "date": datetime.date.today().isoformat(), "machine": machine(),
                         "values": values}
        with open(FIGURES + ".tmp", "w") as f:
            json.dump(figures, f, indent=1, sort_keys=True)
            f.write("\n")
        os.replace(FIGURES + ".tmp", FIGURES)


PLACEHOLDER = re.compile(r"\{\{([a-z0-9_]+)\.([a-z0-9_.]+)(?::([^}]*))?\}\}")


def fill(template, figures, name):
    def value(match):
        group, key, spec = match.group(1), match.group(2), match.group(3) or ""
        if group not in figures:
            sys.exit("figures: %s names group %s, never measured (perf/figures.py measure --only %s)" %
                     (name, group, group))
        entry = figures[group]
        found = entry if key in ("commit", "date", "machine") else entry["values"]
        for part in key.split("."):
            if not isinstance(found, dict) or part not in found:
                sys.exit("figures: %s names %s.%s, which the figures lack" % (name, group, key))
            found = found[part]
        return format(found, spec)
    return PLACEHOLDER.sub(value, template)


def write(options):
    figures = load()
    pages = {}
    for template_name, page, marker in PAGES:
        with open(os.path.join(TEMPLATES, template_name)) as f:
            text = fill(f.read(), figures, template_name)
        if page not in pages:
            with open(os.path.join(ROOT, page)) as f:
                pages[page] = f.read()
        if marker is None:
            pages[page] = text
            continue
        begin, end = "<!-- figures:%s -->\n" % marker, "<!-- /figures:%s -->" % marker
        start, stop = pages[page].find(begin), pages[page].find(end)
        if start < 0 or stop < start:
            sys.exit("figures: %s lacks the markers %s ... %s" % (page, begin.strip(), end))
        pages[page] = pages[page][:start + len(begin)] + text + pages[page][stop:]
    stale = []
    for page, text in pages.items():
        path = os.path.join(ROOT, page)
        with open(path) as f:
            if f.read() == text:
                continue
        stale.append(page)
        if not options.check:
            with open(path + ".tmp", "w") as f:
                f.write(text)
            os.replace(path + ".tmp", path)
    if options.check and stale:
        sys.exit("figures: %s differ from docs/figures.json; run perf/figures.py write" % ", ".join(stale))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    sub = parser.add_subparsers(dest="command", required=True)
    m = sub.add_parser("measure")
    m.add_argument("--only", default=",".join(GROUPS), help="groups: " + ", ".join(GROUPS))
    m.add_argument("--old", default="", help="another build's CLI for the repeat group's before column")
    m.add_argument("--old-name", default="", help="what the old build is (a commit), for the text")
    m.add_argument("--shared", default=os.path.join(ROOT, "..", "shared"))
    m.add_argument("--runs", type=int, default=3)
    m.add_argument("--planes", default="2,4,8,16,46")
    w = sub.add_parser("write")
    w.add_argument("--check", action="store_true")
    options = parser.parse_args()
    if options.command == "measure":
        options.only = [g for g in options.only.split(",") if g]
        for g in options.only:
            if g not in GROUPS:
                sys.exit("figures: unknown group %s (%s)" % (g, ", ".join(GROUPS)))
        options.planes = [int(n) for n in options.planes.split(",")]
        if not shutil.which("/usr/bin/time"):
            sys.exit("figures: /usr/bin/time is needed (Debian package time)")
        measure(options)
    write(options if options.command == "write" else argparse.Namespace(check=False))


if __name__ == "__main__":
    main()
