#!/usr/bin/python3
"""Error against run time of the separable cylinder method (the speed targets in docs/benchmarks.md).

Runs `cavity-modes cylinder --method separable` for radius 1 and heights 1, 2, 4 (2h/a = 1, 2, 4) over a sweep
of --order and --radial-size (axial size --mesh-size = 3 x radial, the ratio of the defaults 3d/8 : d/8 for a <= 2h), then
the default settings (no --order / --mesh-size / --radial-size) re-run --repeat times with --modes 20 and with
--modes 1, then the fastest sweep settings that reach each target's accuracy, re-run --repeat times with the
target's arguments. Each table is compared with Stewartson's exact modes and the J_zh series, computed by
bench/cavity_modes_bench.py's own functions (imported, not copied). Writes

  bench/results/separable_cylinder_<date>.csv             one row per run (every set)
  bench/results/separable_cylinder_error_vs_time.png      top-20 and dominant-E error vs process wall time
  bench/results/separable_cylinder_<date>_targets.md      machine, commit, targets, defaults, fastest settings

    /usr/bin/python3 bench/separable_cylinder_bench.py [BINARY] [--repeat N] [--quick] [--no-check-set]
    /usr/bin/python3 bench/separable_cylinder_bench.py --replot bench/results/separable_cylinder_<date>.csv

Needs Debian's python3-numpy and python3-matplotlib (scripts/install-deps.sh) and python3-scipy (apt-get install python3-scipy).
"""
import argparse
import csv
import datetime
import hashlib
import importlib.util
import json
import math
import os
import re
import resource
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(HERE)

# The exact values (Stewartson's modes, the J_zh series), rel(), fnum() and machine() come from the older bench
# script. It has no module-level work (main() is guarded), but it is loaded by file path so that this script
# does not depend on sys.path or the working directory.
_spec = importlib.util.spec_from_file_location("cavity_modes_bench", os.path.join(HERE, "cavity_modes_bench.py"))
cmb = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(cmb)
rel, fnum = cmb.rel, cmb.fnum

RADIUS = 1.0
HEIGHTS = [2.0, 1.0, 4.0]  # 2h/a = height / radius; 2 is "the cylinder" of the targets
ORDERS = [4, 6, 8, 10]
RADIAL = [1 / 4, 1 / 6, 1 / 8, 1 / 10, 1 / 12, 1 / 16]  # absolute (radius 1); 1/12 with axial 1/4 = the default
AXIAL_FACTOR = 3.0
QUICK_ORDERS = [6, 8]
QUICK_RADIAL = [1 / 6, 1 / 12]
TOP = 20  # rows of a table compared with the TOP largest exact modes
KAPPA_MATCH = 1e-6  # an exact mode is "present" when some row has kappa within this (relative)

# Targets (docs/benchmarks.md), judged on the whole process's wall clock. The dominant-E target is timed with --modes 1.
TARGETS = [
    dict(key="dominant", name="dominant E to 1e-8", tol=1e-8, tmax=1.0, modes=1),
    dict(key="table20", name="20-cluster table: 20 largest exact modes present, each kappa and E to 1e-6",
         tol=1e-6, tmax=3.0, modes=20),
]

ERRORS = ["dom_E", "dom_kappa", "top20_idx_E", "top20_idx_kappa", "exact20_E", "exact20_kappa", "nearest20_E",
          "J_zh"]
COLUMNS = (["set", "height", "order", "radial_size", "axial_size", "h_radial", "h_axial", "modes_arg", "check", "repeat", "ndof", "rows",
            "converged", "wall_s", "process_s", "user_s", "cpu_s", "other_cpu_s", "load1", "status"] + ERRORS +
           ["idx_rows_off", "exact20_missing", "flag_false", "flag_missed", "meets_dominant", "meets_table20",
            "grid", "reference_grid", "flag_false_rows", "worst"])


# ---------------------------------------------------------------------------------------------------------
# Runs
# ---------------------------------------------------------------------------------------------------------

CLK_TCK = os.sysconf("SC_CLK_TCK")


def busy_seconds():
    """Non-idle CPU seconds of the whole machine so far (all CPUs), from /proc/stat."""
    with open("/proc/stat") as f:
        v = [int(x) for x in f.readline().split()[1:]]
    # user nice system idle iowait irq softirq steal (guest time is already in user)
    return (sum(v[:8]) - v[3] - v[4]) / CLK_TCK


def run_table(binary, height, order=None, radial=None, modes=20, check=True, timeout=300):
    """One table; (info json or None, timings, status). order/radial None: the defaults."""
    with tempfile.TemporaryDirectory(prefix="sepbench-") as tmp:
        out = os.path.join(tmp, "t.h5")
        cmd = [binary, "cylinder", "--radius", repr(RADIUS), "--height", repr(height), "--method", "separable",
               "--modes", str(modes)]
        if order is not None:
            cmd += ["--order", str(order)]
        if radial is not None:
            cmd += ["--radial-size", repr(radial), "--mesh-size", repr(AXIAL_FACTOR * radial)]
        if not check:
            cmd.append("--no-convergence-check")
        cmd += ["-o", out]
        ru0 = resource.getrusage(resource.RUSAGE_CHILDREN)
        busy0 = busy_seconds()
        t0 = time.perf_counter()
        try:
            p = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout)
        except subprocess.TimeoutExpired:
            return None, dict(process_s=time.perf_counter() - t0), "timeout"
        wall = time.perf_counter() - t0
        busy1 = busy_seconds()
        ru1 = resource.getrusage(resource.RUSAGE_CHILDREN)
        user, sys_ = ru1.ru_utime - ru0.ru_utime, ru1.ru_stime - ru0.ru_stime
        # CPU time the rest of the machine used while the table ran (from /proc/stat, 10 ms resolution; includes
        # this script's own few ms): > 0 means the run shared the 2 cores (the program uses both).
        tm = dict(process_s=wall, user_s=user, cpu_s=user + sys_, other_cpu_s=max(0.0, busy1 - busy0 - user - sys_))
        if p.returncode != 0:
            return None, tm, "exit %d: %s" % (p.returncode, (p.stderr.strip().splitlines() or [""])[-1])
        info = subprocess.run([binary, "info", out, "--json"], capture_output=True, text=True, check=True)
        return json.loads(info.stdout), tm, "ok"


def errors_of(t, ex):
    """Errors of a table against the exact modes `ex["modes"]` (sorted by E descending) and J_zh `ex["J_zh"]`."""
    M = t["modes"]
    K, E = M["kappa"], M["E"]
    exact = ex["modes"]
    n = len(K)
    e = dict(dom_E=rel(E[0], exact[0]["E"]), dom_kappa=rel(K[0], exact[0]["kappa"]), J_zh=rel(t["J_zh"], ex["J_zh"]))
    # Row i against the i-th largest exact mode (the table is sorted by E, so is the exact list).
    ik = [rel(K[i], exact[i]["kappa"]) for i in range(min(n, TOP))]
    iE = [rel(E[i], exact[i]["E"]) for i in range(min(n, TOP))]
    e["top20_idx_kappa"] = max(ik) if n >= TOP else float("nan")
    e["top20_idx_E"] = max(iE) if n >= TOP else float("nan")
    e["idx_rows_off"] = sum(1 for x in ik if x > KAPPA_MATCH)  # rows that are not the exact mode of their rank
    # Each of the TOP largest exact modes against the row of nearest kappa (the target's "present, to 1e-6").
    xk, xE = [], []
    for m in exact[:TOP]:
        i = min(range(n), key=lambda i: abs(K[i] - m["kappa"]))
        xk.append(rel(K[i], m["kappa"]))
        xE.append(rel(E[i], m["E"]))
    e["exact20_kappa"], e["exact20_E"] = max(xk), max(xE)
    # bench/cavity_modes_bench.py's own matching (each row to the exact mode of nearest kappa) and missing count.
    c = cmb.errors_of("cylinder", t, dict(cyl_modes=exact, cyl_J_zh=ex["J_zh"]))
    e["nearest20_E"] = c["cyl_top20_E"]
    e["exact20_missing"] = c["cyl_exact20_missing"]
    e["worst"] = c["cyl_top20_worst"]
    # Honesty of the table's `converged` flags (tolerance convergence_tolerance, relative): a flagged row whose
    # nearest exact mode is further than the tolerance in kappa or E, and unflagged rows that are within it.
    conv = M.get("converged")
    if conv is not None:
        tol = t.get("convergence_tolerance", 1e-6)
        ff, fm = [], 0
        for i, (k, en, f) in enumerate(zip(K, E, conv)):
            m = cmb.nearest(exact, k)
            ek, eE = rel(k, m["kappa"]), rel(en, m["E"])
            good = ek <= tol and eE <= tol
            if f and not good:
                ff.append("#%d kappa %.6g (exact n=%d j=%d): kappa err %.1e, E err %.1e, table's dlambda %.1e dE %.1e"
                          % (i + 1, k, m["n"], m["j"], ek, eE, M["dlambda"][i] if "dlambda" in M else float("nan"),
                             M["dE"][i] if "dE" in M else float("nan")))
            fm += (not f) and good
        e["converged"], e["flag_false"], e["flag_missed"] = sum(1 for f in conv if f), len(ff), fm
        e["flag_false_rows"] = "; ".join(ff)
    return e


def meets(row, target):
    if row["status"] != "ok":
        return False
    if target["key"] == "dominant":
        return fnum(row["dom_E"]) <= target["tol"]
    return (int(row["rows"]) >= TOP and int(row["exact20_missing"]) == 0 and
            fnum(row["exact20_kappa"]) <= target["tol"] and fnum(row["exact20_E"]) <= target["tol"])


def grid_of(text):
    """'12 radial x 8 axial' from the solver / convergence_reference description ('' if absent)."""
    m = re.search(r"(\d+ radial x \d+ axial)", text)
    return m.group(1) if m else ""


def do_run(binary, exact, set_name, height, order=None, radial=None, modes=20, check=True, repeat=0, log=print):
    t, tm, status = run_table(binary, height, order, radial, modes, check)
    wall = tm["process_s"]
    row = dict(set=set_name, height=height, order=order if order is not None else "", modes_arg=modes,
               check="yes" if check else "no", repeat=repeat, status=status,
               **{k: round(v, 4 if k == "process_s" else 3) for k, v in tm.items()}, radial_size="" if radial is None else round(radial, 6),
               axial_size="" if radial is None else round(AXIAL_FACTOR * radial, 6))
    if t is not None:
        # radial_size / axial_size: as requested ("" for the defaults); h_radial / h_axial: the element sizes
        # used (the program rounds to a whole number of elements).
        row.update(ndof=t["ndof"], rows=len(t["modes"]["E"]), wall_s=round(t["wall_seconds"], 4),
                   order=t.get("fe_order", order), h_radial=round(t.get("mesh_h_radial", float("nan")), 6),
                   h_axial=round(t.get("mesh_h", float("nan")), 6))
        row.update(grid=grid_of(t.get("solver", "")), reference_grid=grid_of(t.get("convergence_reference", "")))
        row.update(errors_of(t, exact[height]))
        for tg in TARGETS:
            row["meets_" + tg["key"]] = int(meets(row, tg))
    row["load1"] = round(os.getloadavg()[0], 2)
    log("%-8s H=%g P%-2s hr=%-8s %6s dofs %2s rows (%2s conv) --modes %-2d%s  %6.3f s (program %s)  domE %s  "
        "top20 %s/%s missing %s  J_zh %s  load %.2f other-cpu %.2f s%s" % (
            set_name, height, row["order"], row["radial_size"], row.get("ndof", "-"), row.get("rows", "-"),
            row.get("converged", "-"), modes, "" if check else " no-check", wall, row.get("wall_s", "-"),
            "%.1e" % row["dom_E"] if "dom_E" in row else "-",
            "%.1e" % row["exact20_kappa"] if "exact20_kappa" in row else "-",
            "%.1e" % row["exact20_E"] if "exact20_E" in row else "-", row.get("exact20_missing", "-"),
            "%.1e" % row["J_zh"] if "J_zh" in row else "-", row["load1"], row.get("other_cpu_s", float("nan")),
            "" if status == "ok" else "  " + status))
    return row


# ---------------------------------------------------------------------------------------------------------
# Reports
# ---------------------------------------------------------------------------------------------------------

def stats(xs):
    xs = [x for x in xs if not math.isnan(x)]
    return (statistics.median(xs), min(xs), max(xs)) if xs else (float("nan"),) * 3


def fmt_stats(s, digits=2):
    return "%.*f (%.*f–%.*f)" % (digits, s[0], digits, s[1], digits, s[2])


def inum(v):
    x = fnum(v)
    return 0 if math.isnan(x) else int(x)


def maxerr(rows, col):
    v = [fnum(r.get(col)) for r in rows]
    v = [x for x in v if not math.isnan(x)]
    return max(v) if v else float("nan")


def repeat_table(rows, set_name, tmax_of_modes):
    """Median (min–max) of process and program time per (height, --modes), for a set of repeated runs."""
    lines = ["| 2h/a | --modes | settings (order, radial h, axial h) | ndof | process wall [s] median (min–max) "
             "| program wall_seconds [s] median (min–max) | other processes' CPU s during a run (max) "
             "| rows flagged converged | errors (worst over the runs) | target met (median)? |",
             "|---|---|---|---|---|---|---|---|---|---|"]
    for h in HEIGHTS:
        for modes in (20, 1):
            rs = [r for r in rows if r["set"] == set_name and fnum(r["height"]) == h and int(r["modes_arg"]) == modes]
            if not rs:
                continue
            ok = [r for r in rs if r["status"] == "ok"]
            p = stats([fnum(r["process_s"]) for r in rs])
            w = stats([fnum(r["wall_s"]) for r in ok])
            r0 = ok[0] if ok else rs[0]
            if modes == 1:
                errs = "dominant E %.1e, κ %.1e" % (maxerr(ok, "dom_E"), maxerr(ok, "dom_kappa"))
                tg = TARGETS[0]
            else:
                errs = "top-20 (exact→row) κ %.1e, E %.1e; missing %d; dominant E %.1e; J_zh %.1e" % (
                    maxerr(ok, "exact20_kappa"), maxerr(ok, "exact20_E"),
                    max(int(r["exact20_missing"]) for r in ok) if ok else -1, maxerr(ok, "dom_E"), maxerr(ok, "J_zh"))
                tg = TARGETS[1]
            acc = len(ok) == len(rs) and all(meets(r, tg) for r in ok)
            met = ("yes" if p[0] < tg["tmax"] else ("program time only" if w[0] < tg["tmax"] else "**no** (time)")) \
                if acc else "**no** (accuracy)"
            conv = "/".join(sorted({"%s of %s" % (r["converged"], r["rows"]) if r.get("converged", "") != ""
                                    else "no flags" for r in ok}))
            other = max((fnum(r.get("other_cpu_s")) for r in rs), default=float("nan"))
            lines.append("| %g | %d | P%s, %.4g, %.4g | %s | %s | %s | %.2f | %s | %s | %s (< %g s) |" % (
                h, modes, r0["order"], fnum(r0["h_radial"]), fnum(r0["h_axial"]), r0.get("ndof", "-"),
                fmt_stats(p), fmt_stats(w, 3), other, conv, errs, met, tg["tmax"]))
    return "\n".join(lines) + "\n"


def fastest_markdown(best):
    lines = ["| 2h/a | target | fastest sweep setting (re-run --modes given) | ndof | process wall [s] median (min–max) "
             "| program wall_seconds [s] median | worst error over the re-runs | met? |",
             "|---|---|---|---|---|---|---|---|"]
    for (h, key), b in best.items():
        tg = next(t for t in TARGETS if t["key"] == key)
        if b is None:
            lines.append("| %g | %s | none in the sweep reaches the accuracy | | | | | **no** |" % (h, tg["name"]))
            continue
        met = "yes" if b["process"][0] < tg["tmax"] else (
            "program time only" if b["wall"][0] < tg["tmax"] else "**no**")
        lines.append("| %g | %s (< %g s) | `--order %d --radial-size %.4g --mesh-size %.4g --modes %d` | %d | %s | "
                     "%.3f | %s | %s |" % (h, tg["name"], tg["tmax"], b["order"], b["radial"], AXIAL_FACTOR * b["radial"],
                                            tg["modes"], b["ndof"], fmt_stats(b["process"]), b["wall"][0], b["errs"],
                                            met))
    return "\n".join(lines) + "\n"


def sweep_markdown(rows):
    """Per height and order: the coarsest radial size meeting each target's accuracy in the sweep."""
    lines = ["| 2h/a | order | radial h swept | coarsest h with dominant E ≤ 1e-8 (process s) | coarsest h with the "
             "20-mode table to 1e-6 (process s) | smallest top-20 error (row i vs i-th exact mode, κ and E) "
             "| exact top-20 modes missing, per h |",
             "|---|---|---|---|---|---|---|"]
    for h in HEIGHTS:
        for o in ORDERS:
            rs = sorted((r for r in rows if r["set"] == "sweep" and fnum(r["height"]) == h and str(r["order"]) == str(o)),
                        key=lambda r: -fnum(r["radial_size"]))
            if not rs:
                continue
            cells = []
            for tg in TARGETS:
                m = [r for r in rs if meets(r, tg)]
                cells.append("%.4g (%.2f s)" % (fnum(m[0]["radial_size"]), fnum(m[0]["process_s"])) if m else "none")
            best = min((max(fnum(r["top20_idx_kappa"]), fnum(r["top20_idx_E"])) for r in rs if r["status"] == "ok"),
                       default=float("nan"))
            lines.append("| %g | %d | %s | %s | %s | %.1e | %s |" % (
                h, o, ", ".join("%.4g" % fnum(r["radial_size"]) for r in rs), cells[0], cells[1], best,
                ", ".join(r["exact20_missing"] for r in rs)))
    return "\n".join(lines) + "\n"


def anomalies(rows):
    """Things worth a look: rows that are not their rank's exact mode, missing modes at settings that reach the
    accuracy elsewhere, false convergence flags, failed runs, and repeated runs far from their median."""
    out = []
    for r in rows:
        where = "%s H=%s P%s hr=%s --modes %s%s" % (r["set"], r["height"], r["order"], r["radial_size"],
                                                   r["modes_arg"], "" if r["check"] == "yes" else " no-check")
        if r["status"] != "ok":
            out.append("- %s: %s" % (where, r["status"]))
            continue
        if int(r["modes_arg"]) >= TOP and inum(r.get("idx_rows_off")) > 0 and int(r["exact20_missing"]) == 0:
            out.append("- %s: all 20 exact modes present but %s rows are out of rank order (row i is not the i-th "
                       "largest exact mode; top-20 error by rank %.1e against %.1e by nearest κ)" % (
                           where, r["idx_rows_off"], max(fnum(r["top20_idx_kappa"]), fnum(r["top20_idx_E"])),
                           max(fnum(r["exact20_kappa"]), fnum(r["exact20_E"]))))
        if inum(r.get("flag_false")) > 0:
            out.append("- %s (grid %s elements, convergence reference %s): %s row(s) flagged converged but "
                       "further than the convergence tolerance from the exact mode of nearest κ (%s of the 20 largest "
                       "exact modes missing): %s" % (where, r["grid"], r["reference_grid"], r["flag_false"],
                                                     r["exact20_missing"], r["flag_false_rows"]))
    groups = {}
    for r in rows:
        if r["set"] != "sweep" and r["status"] == "ok":
            groups.setdefault((r["set"], r["height"], r["order"], r["radial_size"], r["modes_arg"], r["check"]), []).append(r)
    for k, rs in groups.items():
        med = statistics.median(fnum(r["process_s"]) for r in rs)
        for r in rs:
            if fnum(r["process_s"]) > 1.5 * med:  # (other_cpu_s says whether the machine was busy meanwhile)
                out.append("- timing outlier: %s H=%s P%s hr=%s --modes %s repeat %s: %.2f s against a median of "
                           "%.2f s (load %s, other processes' CPU during the run %s s)" % (
                                                 k[0], k[1], k[2], k[3], k[4], r["repeat"], fnum(r["process_s"]), med,
                                                 r["load1"], r.get("other_cpu_s", "?")))
    return out


def plot(rows, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    FLOOR, CEIL = 1e-16, 10.0
    colours = {4: "tab:blue", 6: "tab:green", 8: "tab:red", 10: "tab:purple"}
    heights = [h for h in sorted(HEIGHTS) if any(fnum(r["height"]) == h for r in rows)]
    fig, axes = plt.subplots(2, len(heights), figsize=(5.0 * len(heights), 8.8), squeeze=False)
    panels = [("top 20: max rel. error in κ and E,\nrow i against the i-th largest exact mode",
               lambda r: max(fnum(r["top20_idx_kappa"]), fnum(r["top20_idx_E"])), TARGETS[1]),
              ("dominant mode: rel. error in E", lambda r: fnum(r["dom_E"]), TARGETS[0])]
    for col, h in enumerate(heights):
        for row_i, (title, err, tg) in enumerate(panels):
            ax = axes[row_i][col]
            for o in ORDERS:
                pts = sorted(((fnum(r["process_s"]), min(max(err(r), FLOOR), CEIL), fnum(r["radial_size"]),
                               int(r["exact20_missing"])) for r in rows
                              if r["set"] == "sweep" and r["status"] == "ok" and fnum(r["height"]) == h
                              and str(r["order"]) == str(o)), key=lambda p: -p[2])
                if not pts:
                    continue
                ax.loglog([p[0] for p in pts], [p[1] for p in pts], "o-", ms=4, lw=1.2, color=colours[o],
                          label="P%d" % o)
                if row_i == 0:  # open circles: some of the 20 largest exact modes missing from the table
                    miss = [p for p in pts if p[3] > 0]
                    ax.loglog([p[0] for p in miss], [p[1] for p in miss], "o", ms=9, mfc="none", color="k", lw=0.8,
                              label="some of the 20 largest\nexact modes missing" if o == ORDERS[-1] or miss else None)
            # Default settings: median of the repeats, with --modes 20 (top-20 panel) or --modes 1 (dominant panel).
            d = [r for r in rows if r["set"] == "default" and r["status"] == "ok" and fnum(r["height"]) == h
                 and int(r["modes_arg"]) == tg["modes"]]
            if d:
                ax.loglog([statistics.median(fnum(r["process_s"]) for r in d)],
                          [min(max(statistics.median(err(r) for r in d), FLOOR), CEIL)], "*", ms=14, color="gold",
                          mec="k", label="default, --modes %d (median)" % tg["modes"])
            ax.axhline(tg["tol"], color="grey", ls="--", lw=0.9)
            ax.axvline(tg["tmax"], color="grey", ls=":", lw=0.9)
            ax.fill_between([1e-2, tg["tmax"]], [FLOOR / 2] * 2, [tg["tol"]] * 2, color="green", alpha=0.08)
            ax.text(tg["tmax"] * 0.9, tg["tol"] * 2.5, "target: %.0e in < %g s" % (tg["tol"], tg["tmax"]),
                    fontsize=7, color="dimgrey", ha="right")
            ax.set_xlim(0.06, 12)
            ax.set_ylim(FLOOR / 2, CEIL * 3)
            ax.grid(True, which="major", lw=0.4, alpha=0.6)
            ax.tick_params(labelsize=8)
            if row_i == 0:
                ax.set_title("2h/a = %g (radius 1, height %g)" % (h, h), fontsize=10)
            ax.set_xlabel("process wall time [s] (sweep runs: --modes 20)", fontsize=8)
            ax.set_ylabel(title, fontsize=8)
            if col == 0:
                hs, ls = ax.get_legend_handles_labels()
                seen = {}
                for hh, ll in zip(hs, ls):
                    seen.setdefault(ll, hh)
                keys = sorted(seen, key=lambda ll: (not ll.startswith("P"), ll.startswith("some"),
                                                    int(ll[1:]) if ll.startswith("P") else 0, ll))
                ax.legend([seen[k] for k in keys], keys, fontsize=7, loc="upper right",
                          title="element order", title_fontsize=7)
    fig.suptitle("cavity-modes --method separable, cylinder radius 1: relative error against process wall time\n"
                 "points: radial h = 1/4 … 1/16 (coarse to fine), axial 3h, with the convergence check; star: default "
                 "settings; shaded: target; 1e-16: exact to rounding; 10: ≥ 10", fontsize=10)
    fig.tight_layout(rect=(0, 0, 1, 0.95))
    fig.savefig(path, dpi=100)


def read_csv(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def write_csv(rows, path):
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=COLUMNS, extrasaction="ignore")
        w.writeheader()
        for r in rows:
            w.writerow({k: ("%.3e" % v if k in ERRORS and isinstance(v, float) else v) for k, v in r.items()})


def dirty_note(porcelain, bin_mtime_s):
    """Uncommitted source files (modes/, geometry/, common/), and how many are newer than the binary."""
    if not porcelain:
        return ""
    files = [line[3:].strip() for line in porcelain.splitlines()]
    newer = [f for f in files if os.path.exists(os.path.join(REPO, f)) and
             os.path.getmtime(os.path.join(REPO, f)) > bin_mtime_s]
    return ("; uncommitted edits in %d source files (%s), %d of them modified after the binary was built: the "
            "binary is not necessarily HEAD's" % (len(files), ", ".join(files), len(newer)))


def sha256(path):
    with open(path, "rb") as f:
        return hashlib.sha256(f.read()).hexdigest()


# ---------------------------------------------------------------------------------------------------------

def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("binary", nargs="?", default=os.path.join(REPO, "build/modes/cavity-modes"))
    ap.add_argument("--repeat", type=int, default=5, help="re-runs of the defaults and of each target's candidates")
    ap.add_argument("--candidates", type=int, default=3, help="fastest sweep settings re-run per target and height")
    ap.add_argument("--quick", action="store_true", help="small sweep, 2 repeats; files get a _quick suffix")
    ap.add_argument("--no-check-set", action="store_true",
                    help="also time the defaults with --no-convergence-check (a separate set, not the targets)")
    ap.add_argument("--out-dir", default=os.path.join(HERE, "results"))
    ap.add_argument("--replot", metavar="CSV", help="only redraw the PNG (next to CSV) from a results CSV")
    args = ap.parse_args()
    if args.replot:
        png = os.path.join(os.path.dirname(os.path.abspath(args.replot)), "separable_cylinder_error_vs_time%s.png" % (
            "_quick" if args.replot.endswith("_quick.csv") else ""))
        plot(read_csv(args.replot), png)
        print("wrote", png)
        return
    binary = os.path.abspath(args.binary)
    if not os.access(binary, os.X_OK):
        sys.exit("separable_cylinder_bench: %s is not an executable" % binary)
    # The build tree may be rebuilt while this runs (modes/ being edited): every run uses a private copy of the
    # binary taken now, so all rows measure the same build. Its hash and time stamp go into the report.
    snap_dir = tempfile.mkdtemp(prefix="sepbench-bin-")
    source_binary = binary
    binary = os.path.join(snap_dir, "cavity-modes")
    shutil.copy2(source_binary, binary)
    os.makedirs(args.out_dir, exist_ok=True)
    log = lambda s: print(s, flush=True)
    repeat = 2 if args.quick and args.repeat == 5 else args.repeat
    orders, radial = (QUICK_ORDERS, QUICK_RADIAL) if args.quick else (ORDERS, RADIAL)
    suffix = "_quick" if args.quick else ""
    stamp = datetime.date.today().isoformat()
    head = subprocess.run(["git", "-C", REPO, "rev-parse", "HEAD"], capture_output=True, text=True).stdout.strip()
    dirty = subprocess.run(["git", "-C", REPO, "status", "--porcelain", "--", "modes", "geometry", "common"],
                           capture_output=True, text=True).stdout.rstrip("\n")
    head_date = subprocess.run(["git", "-C", REPO, "log", "-1", "--format=%cd", "--date=iso"], capture_output=True,
                               text=True).stdout.strip()
    bin_mtime_s = os.path.getmtime(binary)
    bin_hash0, bin_mtime = sha256(binary), time.strftime("%Y-%m-%d %H:%M:%S UTC", time.gmtime(os.path.getmtime(binary)))
    m = cmb.machine()
    load0 = os.getloadavg()
    log("binary %s, copied to %s (sha256 %s…, built %s), repository HEAD %s%s\nmachine: %d cpus, %s, %s RAM, Linux %s; load %s" % (
        source_binary, binary, bin_hash0[:12], bin_mtime, head, ", modes/ has uncommitted edits" if dirty else "", m["nproc"],
        m["cpu"], m["ram"], m["kernel"], " ".join("%.2f" % x for x in load0)))

    t0 = time.perf_counter()
    exact = {}
    for h in HEIGHTS:
        modes = cmb.cylinder_modes(RADIUS, h)
        exact[h] = dict(modes=modes, J_zh=cmb.cylinder_zhukovsky(RADIUS, h))
        log("exact 2h/a = %g: dominant κ %.12f E %.12e (n=%d j=%d); 20th largest E %.3e; J_zh %.12f" % (
            h, modes[0]["kappa"], modes[0]["E"], modes[0]["n"], modes[0]["j"], modes[TOP - 1]["E"], exact[h]["J_zh"]))
    log("exact values: %.1f s" % (time.perf_counter() - t0))

    rows = []
    # 1. Sweep: --modes 20, with the convergence check (the default).
    t1 = time.perf_counter()
    for h in HEIGHTS:
        for o in orders:
            for hr in radial:
                rows.append(do_run(binary, exact, "sweep", h, o, hr, 20, log=log))
    sweep_s = time.perf_counter() - t1
    log("sweep: %d runs, %.0f s" % (len(rows), sweep_s))

    # 2. Default settings, --modes 20 and --modes 1, `repeat` times each (interleaved so a load spike is shared).
    for h in HEIGHTS:
        for i in range(repeat):
            for modes in (20, 1):
                rows.append(do_run(binary, exact, "default", h, None, None, modes, repeat=i + 1, log=log))

    # 3. The fastest sweep settings meeting each target's accuracy, re-run with the target's --modes.
    best = {}
    for tg in TARGETS:
        for h in HEIGHTS:
            cand = sorted((r for r in rows if r["set"] == "sweep" and r["height"] == h and meets(r, tg)),
                          key=lambda r: fnum(r["process_s"]))[:args.candidates]
            best[(h, tg["key"])] = None
            for c in cand:
                rs = [do_run(binary, exact, "target-" + tg["key"], h, int(c["order"]), float(c["radial_size"]),
                             tg["modes"], repeat=i + 1, log=log) for i in range(repeat)]
                rows.extend(rs)
                if not all(meets(r, tg) for r in rs):
                    log("  candidate P%s hr=%s fails the accuracy on a re-run" % (c["order"], c["radial_size"]))
                    continue
                cols = ["dom_E"] if tg["key"] == "dominant" else ["exact20_kappa", "exact20_E"]
                b = dict(order=int(c["order"]), radial=float(c["radial_size"]), ndof=int(rs[0]["ndof"]),
                         process=stats([fnum(r["process_s"]) for r in rs]), wall=stats([fnum(r["wall_s"]) for r in rs]),
                         errs=", ".join("%s %.1e" % (q, maxerr(rs, q)) for q in cols))
                if best[(h, tg["key"])] is None or b["process"][0] < best[(h, tg["key"])]["process"][0]:
                    best[(h, tg["key"])] = b

    # 4. Optional, separate: the defaults without the convergence check (what the check costs).
    if args.no_check_set:
        for h in HEIGHTS:
            for i in range(repeat):
                for modes in (20, 1):
                    rows.append(do_run(binary, exact, "default-no-check", h, None, None, modes, check=False,
                                       repeat=i + 1, log=log))
    total_s = time.perf_counter() - t0
    bin_hash1 = sha256(source_binary) if os.path.exists(source_binary) else "(gone)"
    shutil.rmtree(snap_dir, ignore_errors=True)

    csv_path = os.path.join(args.out_dir, "separable_cylinder_%s%s.csv" % (stamp, suffix))
    write_csv(rows, csv_path)
    png_path = os.path.join(args.out_dir, "separable_cylinder_error_vs_time%s.png" % suffix)
    plot(read_csv(csv_path), png_path)

    crow = read_csv(csv_path)
    loads = [fnum(r["load1"]) for r in crow]
    others = [fnum(r["other_cpu_s"]) for r in crow if not math.isnan(fnum(r["other_cpu_s"]))]
    notes = anomalies(crow)
    md = ["# separable cylinder benchmark %s%s\n" % (stamp, suffix),
          "`bench/separable_cylinder_bench.py`: `cavity-modes cylinder --radius 1 --height H --method separable`, "
          "compared with Stewartson's exact modes and the J_zh series of `bench/cavity_modes_bench.py`.\n",
          "- date: %s (UTC %s)" % (stamp, datetime.datetime.now(datetime.timezone.utc).strftime("%H:%M")),
          "- repository HEAD: `%s` (%s)%s" % (head, head_date, dirty_note(dirty, bin_mtime_s)),
          "- binary: `%s` (a copy taken at the start ran every row), sha256 `%s`, modified %s%s" % (
              os.path.relpath(source_binary, REPO), bin_hash0[:16], bin_mtime,
              "" if bin_hash1 == bin_hash0 else "; the build tree's binary was rebuilt during the run (now %s)"
              % bin_hash1[:16]),
          "- machine: %d CPUs (nproc), %s, %s RAM, Linux %s" % (m["nproc"], m["cpu"], m["ram"], m["kernel"]),
          "- load average before: %s; 1-minute load after each run: %.2f–%.2f (median %.2f)" % (
              " ".join("%.2f" % x for x in load0), min(loads), max(loads), statistics.median(loads)),
          "- CPU used by other processes while a table ran (from /proc/stat; the program runs 2 threads on the 2 "
          "CPUs, so any of it slows the run): median %.2f s, max %.2f s; %d of %d runs had > 0.1 s" % (
              statistics.median(others), max(others), sum(1 for x in others if x > 0.1), len(others)),
          "- runs: %d (sweep %d in %.0f s); total %.0f s; all sequential; times are the whole process's wall clock "
          "(`process`) unless marked as the program's own `wall_seconds`" % (
              len(rows), sum(1 for r in rows if r["set"] == "sweep"), sweep_s, total_s),
          "- CSV: `%s`; plot: `%s`\n" % (os.path.relpath(csv_path, REPO), os.path.relpath(png_path, REPO)),
          "## Targets, default settings\n",
          "Targets: (a) the dominant E to 1e-8 (relative) in < 1 s, timed with `--modes 1`; (b) a 20-cluster table "
          "in < 3 s: every one of the 20 largest exact modes has a row within 1e-6 in κ (\"present\") whose κ and E "
          "are within 1e-6 (relative), timed with `--modes 20`. Both judged on the process wall clock; the "
          "convergence check is on (the default). Default settings: no `--order`/`--mesh-size`/`--radial-size` "
          "(order 10, axial 3d/8, radial max(d, R/2)/8, d = min(R, H) = 1). %d runs each; the error column is the worst over "
          "the runs.\n" % repeat,
          repeat_table(crow, "default", None),
          "## Fastest sweep settings meeting each target\n",
          "Among the sweep's settings that reach the accuracy (sweep runs use `--modes 20`), the %d fastest by "
          "process time were re-run %d times with the target's `--modes`; the fastest median is shown.\n" % (
              args.candidates, repeat),
          fastest_markdown(best),
          "## Sweep (orders %s × radial h %s, axial h = %g × radial, `--modes 20`)\n" % (
              ", ".join(map(str, orders)), ", ".join("1/%d" % round(1 / x) for x in radial), AXIAL_FACTOR),
          sweep_markdown(crow)]
    if args.no_check_set:
        md += ["## Separate set: default settings with `--no-convergence-check` (not the targets)\n",
               "What the convergence check costs; these tables flag no row converged.\n",
               repeat_table(crow, "default-no-check", None)]
    full = [r for r in crow if r["status"] == "ok" and int(r["modes_arg"]) >= TOP and inum(r["exact20_missing"]) == 0]
    agree = sum(1 for r in full if math.isclose(max(fnum(r["top20_idx_kappa"]), fnum(r["top20_idx_E"])),
                                                 max(fnum(r["exact20_kappa"]), fnum(r["exact20_E"])), rel_tol=1e-6))
    partial = [r for r in crow if r["status"] == "ok" and int(r["modes_arg"]) >= TOP and inum(r["exact20_missing"]) > 0]
    md += ["## Matching\n",
           "Two matchings of a `--modes 20` table: row i against the i-th largest exact mode (`top20_idx_*`, the "
           "plot), and each of the 20 largest exact modes against the row of nearest κ (`exact20_*`, the target). "
           "In %d of the %d runs with all 20 exact modes present the two maxima are equal (every row is the exact "
           "mode of its rank); %d runs (sets: %s) miss some of the 20, and there rows drop out of rank (by-rank "
           "errors up to %.1e, drawn at 10 when ≥ 10).\n" % (
               agree, len(full), len(partial), ", ".join(sorted({r["set"] for r in partial})) or "-",
               maxerr(partial, "top20_idx_E") if partial else float("nan"))]
    md += ["## Anomalies found by the script\n",
           ("\n".join(notes) if notes else "None: every run's rows are the exact modes of their rank, no false "
                                            "convergence flags, no failed runs, no repeat > 1.5 × its median.") + "\n"]
    md_path = os.path.join(args.out_dir, "separable_cylinder_%s%s_targets.md" % (stamp, suffix))
    with open(md_path, "w") as f:
        f.write("\n".join(md))
    log("\n".join(md))
    log("wrote %s\nwrote %s\nwrote %s\ntotal %.0f s" % (csv_path, png_path, md_path, total_s))


if __name__ == "__main__":
    main()
