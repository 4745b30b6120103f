#!/usr/bin/python3
"""Cone convergence study for cavity-modes (docs/cones.md: "which cone clusters converge").

Cones of apex half-angle alpha = 15, 30, 45, 60, 75 degrees, all of the same volume pi/3 (R^2 H = 1, so
R = tan(alpha)^(1/3), H = tan(alpha)^(-2/3); alpha = 45 is R = H = 1), each at a ladder of element orders and
mesh sizes (h halved at each rung, the same absolute h for every angle: the meridian triangles have areas
0.32..0.78, so the dof counts are comparable). Measured:

  * integrated quantities: J_zh, A_f (against its closed form), A_f - J_zh, the /bands weights and their
    E-weighted mean lambda (the survey's Gauss rule), with observed orders; the Gauss rule's own error
    (--survey-steps 100..1600 on one mesh);
  * clusters: lambda and E of the largest clusters across >= 3 refinements (nearest-lambda matching), the
    table's own converged flags, and whether any flagged cluster is unconverged against the finest table.

Every run's `cavity-modes info --json` (trimmed) is kept in bench/results/cone_study_raw.json, keyed by its
settings, so an interrupted study resumes and `--analyse-only` redoes the analysis without running anything.
Outputs (bench/results/): cone_study_<date>.md (the summary recorded in docs/cones.md), cone_study_runs.csv,
cone_study_clusters.csv, cone_study_bands.csv, cone_study.png.

    /usr/bin/python3 bench/cone_study.py [BINARY] [--quick] [--analyse-only] [--angles 15,30,...]
"""
import argparse
import csv
import datetime
import json
import math
import os
import resource
import subprocess
import sys
import tempfile
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(HERE)
RESULTS = os.path.join(HERE, "results")
RAW = os.path.join(RESULTS, "cone_study_raw.json")

ANGLES = [15, 30, 45, 60, 75]
SURVEY_ONLY = ["--modes", "1", "--no-convergence-check"]  # J_zh, A_f, bands (+ 6 cheap slices)
CLUSTERS = ["--modes", "20"]  # the 20 largest clusters, with the table's own convergence check

# set name -> (extra arguments, {order: [mesh sizes]}, [survey steps])
PLAN = {
    "survey": (SURVEY_ONLY, {2: [0.2, 0.1, 0.05, 0.025], 4: [0.4, 0.2, 0.1, 0.05], 6: [0.4, 0.2, 0.1, 0.05]}, [200]),
    "gauss": (SURVEY_ONLY, {6: [0.1]}, [100, 400, 800]),
    "clusters": (CLUSTERS, {4: [0.4, 0.2, 0.1], 6: [0.4, 0.2, 0.1]}, [200]),
}
# A fourth rung where it stays affordable (a --modes 20 table of a dense cone spectrum at ~4000 dofs takes
# minutes: most slices are widened, see docs/cones.md).
EXTRA_CLUSTER_RUNGS = {45: {4: [0.05]}}
QUICK_PLAN = {
    "survey": (SURVEY_ONLY, {4: [0.4, 0.2, 0.1]}, [200]),
    "gauss": (SURVEY_ONLY, {4: [0.2]}, [100, 400]),
    "clusters": (CLUSTERS, {4: [0.4, 0.2, 0.1]}, [200]),
}
EXTRA_GAUSS = {45: [1600]}  # one long rule, to judge the 800-step one
# Exact discrete band weights (spectral-window: every eigenpair in the band, no Gauss rule), order 6 ladder.
WINDOW_LADDER = {6: [0.4, 0.2, 0.1, 0.05]}
QUICK_WINDOW_LADDER = {6: [0.4, 0.2]}

HEAVY_BAND = 0.01  # bands carrying >= 1 % of A_f - J_zh are the ones reported
TOP_CLUSTERS = 10  # clusters of the finest table followed down the ladder


def cone_dims(alpha):
    t = math.tan(math.radians(alpha))
    return t ** (1 / 3), t ** (-2 / 3)


def critical_lambda(alpha):
    """An inertial wave of frequency lambda (omega0 = 1) has its wave vector at angle theta to the axis with
    lambda = 2 cos(theta); its energy travels perpendicular to it, along rays at theta to the horizontal. A ray is
    parallel to the cone's wall (at alpha to the axis, 90 - alpha to the horizontal) when lambda = 2 sin(alpha)."""
    return 2 * math.sin(math.radians(alpha))


def key(alpha, order, h, extra, steps):
    return "a%d_P%d_h%g_%s_K%d" % (alpha, order, h, "survey" if extra == SURVEY_ONLY else "clusters", steps)


def trim(info):
    keep = ["fe_order", "mesh_h", "ndof", "volume", "centroid_z", "A_f", "J_zh", "sum_rule", "coverage",
            "wall_seconds", "convergence_reference", "convergence_tolerance", "bands", "radius", "height"]
    t = {k: info[k] for k in keep if k in info}
    m = info["modes"]
    t["modes"] = {k: m[k] for k in ("lambda", "E", "spread", "members", "dlambda", "dE", "converged") if k in m}
    return t


def run(binary, alpha, order, h, extra, steps, timeout=3600):
    R, H = cone_dims(alpha)
    with tempfile.TemporaryDirectory(prefix="conestudy-") as tmp:
        out = os.path.join(tmp, "t.h5")
        cmd = [binary, "cone", "--radius", repr(R), "--height", repr(H), "--order", str(order), "--mesh-size",
               repr(h), "--survey-steps", str(steps)] + extra + ["-o", out]
        cpu0 = resource.getrusage(resource.RUSAGE_CHILDREN)
        t0 = time.perf_counter()
        p = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout)
        wall = time.perf_counter() - t0
        cpu1 = resource.getrusage(resource.RUSAGE_CHILDREN)
        if p.returncode != 0:
            return dict(status="exit %d: %s" % (p.returncode, p.stderr.strip()[-200:]), process_s=wall)
        info = json.loads(subprocess.run([binary, "info", out, "--json"], capture_output=True, text=True,
                                         check=True).stdout)
    r = trim(info)
    r.update(status="ok", alpha=alpha, order=order, h=h, steps=steps, set_extra=extra, process_s=round(wall, 2),
             user_s=round(cpu1.ru_utime - cpu0.ru_utime, 2), load1=round(os.getloadavg()[0], 2),
             date=datetime.date.today().isoformat())
    return r


def window_bands(raw, alpha):
    """The bands weighed exactly: the heaviest negative and the two heaviest positive bands of the finest order-6
    survey table (the Gauss rule only picks them)."""
    p6 = ladder(raw, alpha, 6, "survey") or ladder(raw, alpha, 4, "survey")
    if not p6:
        return []
    E, _, lo, hi = bands_of(p6[-1])
    neg = [i for i in np.argsort(-E) if hi[i] <= 0][:1]
    pos = [i for i in np.argsort(-E) if lo[i] >= 0][:2]
    # spectral-window needs -2 < lo < hi < 2 (|lambda| = 2 is outside the spectrum; no eigenpair is lost).
    return [(max(round(float(lo[i]), 2), -1.999999), min(round(float(hi[i]), 2), 1.999999)) for i in sorted(neg + pos)]


def run_windows(binary, alpha, order, h, bands):
    R, H = cone_dims(alpha)
    exe = os.path.join(os.path.dirname(binary), "spectral-window")
    cmd = [exe, "cone", "--radius", repr(R), "--height", repr(H), "--order", str(order), "--mesh-size", repr(h)]
    for lo, hi in bands:
        cmd.append("--window=%r,%r" % (lo, hi))
    cpu0 = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.perf_counter()
    p = subprocess.run(cmd, capture_output=True, text=True, timeout=3600)
    wall = time.perf_counter() - t0
    cpu1 = resource.getrusage(resource.RUSAGE_CHILDREN)
    if p.returncode != 0:
        return dict(status="exit %d: %s" % (p.returncode, p.stderr.strip()[-200:]), process_s=wall)
    w = [json.loads(line) for line in p.stdout.splitlines() if line.startswith("{")]
    return dict(status="ok", kind="window", alpha=alpha, order=order, h=h, windows=w, ndof=w[0]["ndof"],
                sum_rule=w[0]["sum_rule"], process_s=round(wall, 2), user_s=round(cpu1.ru_utime - cpu0.ru_utime, 2),
                load1=round(os.getloadavg()[0], 2), date=datetime.date.today().isoformat(), steps=0, set_extra=[])


def load_raw():
    if os.path.exists(RAW):
        with open(RAW) as f:
            return json.load(f)
    return {}


def save_raw(raw):
    tmp = RAW + ".tmp"
    with open(tmp, "w") as f:
        json.dump(raw, f, separators=(",", ":"))
    os.replace(tmp, RAW)


def plan_runs(plan, angles):
    runs = []
    for name in ("survey", "gauss", "clusters"):
        extra, ladder, steps_list = plan[name]
        for alpha in angles:
            for order, sizes in ladder.items():
                for h in sizes:
                    for steps in steps_list + (EXTRA_GAUSS.get(alpha, []) if name == "gauss" and plan is PLAN else []):
                        runs.append((alpha, order, h, extra, steps))
            if name == "clusters" and plan is PLAN:
                for order, sizes in EXTRA_CLUSTER_RUNGS.get(alpha, {}).items():
                    runs += [(alpha, order, h, extra, 200) for h in sizes]
    return runs


# ---------------------------------------------------------------------------------------------------------
# Analysis
# ---------------------------------------------------------------------------------------------------------


def exact_A_f(alpha):
    """Transverse moment of inertia of a solid cone about its centroid: m (3 R^2 / 20 + 3 H^2 / 80)."""
    R, H = cone_dims(alpha)
    m = math.pi * R * R * H / 3
    return m * (3 * R * R / 20 + 3 * H * H / 80)


def ladder(raw, alpha, order, kind, steps=200):
    rows = [r for r in raw.values() if r.get("status") == "ok" and r["alpha"] == alpha and r["order"] == order
            and r["steps"] == steps and (r["set_extra"] == SURVEY_ONLY) == (kind == "survey")]
    return sorted(rows, key=lambda r: -r["h"])  # coarse to fine


def observed_order(values, hs):
    """Order from the last three of a sequence with h halved at each step: log2(|d1| / |d2|)."""
    if len(values) < 3:
        return float("nan")
    d1, d2 = values[-2] - values[-3], values[-1] - values[-2]
    if abs(d2) < 1e-11 * abs(values[-1]) or d1 == 0:  # round-off level: no order to observe
        return float("nan")
    return math.log(abs(d1 / d2)) / math.log(hs[-3] / hs[-2])


def richardson(values, p, ratio=2.0):
    return values[-1] + (values[-1] - values[-2]) / (ratio ** p - 1)


def analyse_integrated(raw, angles, lines, csv_rows):
    lines.append("## Integrated quantities (survey-only runs, `--survey-steps 200`)\n")
    lines.append("J_zh reference: Richardson extrapolation of the three finest P6 meshes with their observed order "
                 "(its error estimated by the extrapolation step |J_ref - J_finest|). A_f has a closed form "
                 "(solid cone, m (3R^2/20 + 3H^2/80)). 'dJ/J' is the relative change from the next coarser mesh.\n")
    lines.append("| alpha | R | H | lambda_c = 2 sin alpha | order | h | ndof | A_f err | J_zh | dJ/J | J_zh err vs ref "
                 "| process s | user s |")
    lines.append("|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    refs = {}
    for alpha in angles:
        R, H = cone_dims(alpha)
        fine = ladder(raw, alpha, 6, "survey")
        if len(fine) >= 3:
            J = [r["J_zh"] for r in fine]
            p = observed_order(J, [r["h"] for r in fine])
            if math.isfinite(p) and p > 0.5:
                ref = richardson(J, p)
                refs[alpha] = (ref, abs(ref - J[-1]), p)
            else:  # changes at round-off or not shrinking: the finest value, the last change as its error
                refs[alpha] = (J[-1], abs(J[-1] - J[-2]), p)
        elif fine:
            refs[alpha] = (fine[-1]["J_zh"], float("nan"), float("nan"))
        for order in (2, 4, 6):
            rows = ladder(raw, alpha, order, "survey")
            for i, r in enumerate(rows):
                dJ = abs(r["J_zh"] - rows[i - 1]["J_zh"]) / r["J_zh"] if i else float("nan")
                ref = refs.get(alpha, (float("nan"),))[0]
                err = abs(r["J_zh"] - ref) / ref
                aerr = abs(r["A_f"] - exact_A_f(alpha)) / exact_A_f(alpha)
                lines.append("| %d | %.4f | %.4f | %.4f | %d | %g | %d | %.1e | %.10f | %.1e | %.1e | %.1f | %.1f |" % (
                    alpha, R, H, critical_lambda(alpha), order, r["h"], r["ndof"], aerr, r["J_zh"], dJ, err,
                    r["process_s"], r["user_s"]))
                csv_rows.append(dict(alpha=alpha, R=R, H=H, order=order, h=r["h"], steps=r["steps"], ndof=r["ndof"],
                                     kind="survey", A_f=r["A_f"], A_f_err=aerr, J_zh=r["J_zh"], J_zh_err=err,
                                     sum_rule=r["sum_rule"], coverage=r["coverage"], process_s=r["process_s"],
                                     user_s=r["user_s"], load1=r["load1"]))
    lines.append("")
    lines.append("| alpha | J_zh reference | its error estimate (relative) | observed order of J_zh (P2 / P4 / P6, last three meshes) | A_f - J_zh (ref) |")
    lines.append("|---|---|---|---|---|")
    for alpha in angles:
        if alpha not in refs:
            continue
        ref, err, p6 = refs[alpha]
        ps = []
        for order in (2, 4, 6):
            rows = ladder(raw, alpha, order, "survey")
            ps.append("%.2f" % observed_order([r["J_zh"] for r in rows], [r["h"] for r in rows]) if len(rows) >= 3 else "-")
        lines.append("| %d | %.12f | %.1e | %s | %.10f |" % (alpha, ref, err / ref, " / ".join(ps),
                                                            exact_A_f(alpha) - ref))
    lines.append("")
    return refs


def nanmax(a, b):
    """max that ignores a NaN (nothing measured) unless both are NaN."""
    return b if math.isnan(a) else a if math.isnan(b) else max(a, b)


def bands_of(r):
    b = r["bands"]
    return np.array(b["E"]), np.array(b["lambda_mean"]), np.array(b["lo"]), np.array(b["hi"])


def analyse_bands(raw, angles, lines, band_rows):
    lines.append("## Band weights (/bands: Sigma E and E-weighted mean lambda per 0.1-wide lambda-band)\n")
    lines.append("Heavy bands: weight >= %g of A_f - J_zh on the finest P6 mesh. 'mesh' columns: relative change of the "
                 "band weight (and absolute change of its mean lambda) between the two finest meshes of the same order "
                 "and survey steps 200; 'Gauss rule' columns: the same mesh (P6 h = 0.1) with 200 against 800 survey "
                 "steps. The bands' total is A_f - J_zh exactly at every setting.\n" % HEAVY_BAND)
    lines.append("| alpha | band | weight (P6 finest) | share of A_f - J_zh | mean lambda | mesh: dE/E P4 | mesh: dE/E P6 "
                 "| mesh: d(mean lambda) P6 | Gauss rule: dE/E 200 vs 800 | d(mean lambda) 200 vs 800 |")
    lines.append("|---|---|---|---|---|---|---|---|---|---|")
    summary = {}
    for alpha in angles:
        p6 = ladder(raw, alpha, 6, "survey")
        p4 = ladder(raw, alpha, 4, "survey")
        g = {r["steps"]: r for r in raw.values() if r.get("status") == "ok" and r["alpha"] == alpha
             and r["order"] == 6 and r["h"] == 0.1 and r["set_extra"] == SURVEY_ONLY}
        if len(p6) < 2:
            continue
        E6, L6, lo, hi = bands_of(p6[-1])
        E6c, L6c, _, _ = bands_of(p6[-2])
        E4, _, _, _ = bands_of(p4[-1]) if len(p4) >= 2 else (None,) * 4
        E4c, _, _, _ = bands_of(p4[-2]) if len(p4) >= 2 else (None,) * 4
        total = p6[-1]["sum_rule"]
        heavy = np.nonzero(E6 >= HEAVY_BAND * total)[0]
        worst = dict(mesh6=float("nan"), mesh4=float("nan"), gauss=float("nan"), lam6=float("nan"), lamg=float("nan"))
        for i in heavy:
            d6 = abs(E6[i] - E6c[i]) / E6[i]
            d4 = abs(E4[i] - E4c[i]) / E4[i] if E4 is not None else float("nan")
            dl6 = abs(L6[i] - L6c[i])
            if 200 in g and 800 in g:
                Eg2, Lg2, _, _ = bands_of(g[200])
                Eg8, Lg8, _, _ = bands_of(g[800])
                dg, dlg = abs(Eg2[i] - Eg8[i]) / Eg8[i], abs(Lg2[i] - Lg8[i])
            else:
                dg = dlg = float("nan")
            worst = dict(mesh6=nanmax(worst["mesh6"], d6), mesh4=nanmax(worst["mesh4"], d4),
                         gauss=nanmax(worst["gauss"], dg), lam6=nanmax(worst["lam6"], dl6), lamg=nanmax(worst["lamg"], dlg))
            lines.append("| %d | [%.1f, %.1f) | %.4e | %.3f | %.4f | %.1e | %.1e | %.1e | %.1e | %.1e |" % (
                alpha, lo[i], hi[i], E6[i], E6[i] / total, L6[i], d4, d6, dl6, dg, dlg))
        summary[alpha] = dict(worst, heavy=len(heavy), heavy_share=float(E6[heavy].sum() / total))
        for r in p4 + p6 + list(g.values()):
            E, L, lo_, hi_ = bands_of(r)
            for i in range(len(E)):
                band_rows.append(dict(alpha=alpha, order=r["order"], h=r["h"], steps=r["steps"], lo=round(lo_[i], 2),
                                      hi=round(hi_[i], 2), E=E[i], lambda_mean=L[i], share=E[i] / r["sum_rule"]))
    lines.append("")
    lines.append("| alpha | heavy bands | their share | worst dE/E mesh P4 | worst dE/E mesh P6 | worst dE/E Gauss 200 vs 800 "
                 "| worst d(mean lambda) mesh P6 | worst d(mean lambda) Gauss |")
    lines.append("|---|---|---|---|---|---|---|---|")
    for alpha, s in summary.items():
        lines.append("| %d | %d | %.3f | %.1e | %.1e | %.1e | %.1e | %.1e |" % (
            alpha, s["heavy"], s["heavy_share"], s["mesh4"], s["mesh6"], s["gauss"], s["lam6"], s["lamg"]))
    lines.append("")
    # The Gauss rule's convergence in its number of steps, on one mesh: L1 distance of the band weights.
    lines.append("Gauss rule against survey steps K (P6 h = 0.1): sum over bands of |E_K - E_ref| / (A_f - J_zh), "
                 "ref = the longest rule run; and the worst heavy band.\n")
    lines.append("| alpha | K | L1 distance | worst heavy band dE/E |")
    lines.append("|---|---|---|---|")
    for alpha in angles:
        g = {r["steps"]: r for r in raw.values() if r.get("status") == "ok" and r["alpha"] == alpha
             and r["order"] == 6 and r["h"] == 0.1 and r["set_extra"] == SURVEY_ONLY}
        if len(g) < 2:
            continue
        kref = max(g)
        Eref, _, _, _ = bands_of(g[kref])
        total = g[kref]["sum_rule"]
        heavy = np.nonzero(Eref >= HEAVY_BAND * total)[0]
        for K in sorted(g):
            if K == kref:
                continue
            E, _, _, _ = bands_of(g[K])
            lines.append("| %d | %d (ref %d) | %.1e | %.1e |" % (alpha, K, kref, np.abs(E - Eref).sum() / total,
                                                                max(np.abs(E[heavy] - Eref[heavy]) / Eref[heavy])))
    lines.append("")
    return summary


def analyse_windows(raw, angles, lines, win_rows):
    """Exact discrete band weights (spectral-window) against h, and the Gauss rule's error on the same mesh."""
    lines.append("## Exact band weights (spectral-window: Sigma E over every eigenpair of the band; no Gauss rule)\n")
    lines.append("Order 6. 'change' = relative change from the mesh twice as coarse; 'order' from the last three meshes; "
                 "'Gauss K' = relative error of the table's /bands value (survey with K steps) against the exact value "
                 "on the same mesh.\n")
    lines.append("| alpha | band | h | ndof | pairs | exact weight | share | mean lambda | change | Gauss K=200 error "
                 "| Gauss K=800 error | s (user) |")
    lines.append("|---|---|---|---|---|---|---|---|---|---|---|---|")
    summary = []
    for alpha in angles:
        rows = sorted((r for r in raw.values() if r.get("kind") == "window" and r.get("status") == "ok"
                       and r["alpha"] == alpha and r["order"] == 6), key=lambda r: -r["h"])
        if not rows:
            continue
        nb = len(rows[0]["windows"])
        for b in range(nb):
            vals, hs = [], []
            for k, r in enumerate(rows):
                w = r["windows"][b]
                vals.append(w["E"])
                hs.append(r["h"])
                change = abs(w["E"] - vals[-2]) / w["E"] if k else float("nan")
                gerr = {}
                for K in (200, 800):
                    g = [x for x in raw.values() if x.get("status") == "ok" and x.get("set_extra") == SURVEY_ONLY
                         and x["alpha"] == alpha and x["order"] == 6 and x["h"] == r["h"] and x["steps"] == K]
                    if g:
                        E, _, lo, hi = bands_of(g[0])
                        i = int(np.argmin(np.abs(lo - w["lo"]) + np.abs(hi - w["hi"])))
                        gerr[K] = abs(E[i] - w["E"]) / w["E"]
                lines.append("| %d | [%.1f, %.1f) | %g | %d | %d | %.6e | %.3f | %.5f | %.1e | %s | %s | %.0f |" % (
                    alpha, w["lo"], w["hi"], r["h"], r["ndof"], w["pairs"], w["E"], w["E"] / r["sum_rule"],
                    w["lambda_mean"], change, "%.1e" % gerr[200] if 200 in gerr else "-",
                    "%.1e" % gerr[800] if 800 in gerr else "-", r["user_s"]))
                win_rows.append(dict(alpha=alpha, lo=w["lo"], hi=w["hi"], order=6, h=r["h"], ndof=r["ndof"],
                                     pairs=w["pairs"], E=w["E"], share=w["E"] / r["sum_rule"],
                                     lambda_mean=w["lambda_mean"], E_max=w["E_max"],
                                     gauss200_err=gerr.get(200, float("nan")), gauss800_err=gerr.get(800, float("nan")),
                                     process_s=r["process_s"], user_s=r["user_s"], load1=r["load1"]))
            p = observed_order(vals, hs)
            last = abs(vals[-1] - vals[-2]) / vals[-1] if len(vals) > 1 else float("nan")
            summary.append((alpha, rows[0]["windows"][b]["lo"], rows[0]["windows"][b]["hi"], vals[-1], last, p))
    lines.append("")
    lines.append("| alpha | band | exact weight (finest) | last change | observed order |")
    lines.append("|---|---|---|---|---|")
    for a, lo, hi, v, last, p in summary:
        lines.append("| %d | [%.1f, %.1f) | %.6e | %.1e | %.2f |" % (a, lo, hi, v, last, p))
    lines.append("")


def match(lam, table):
    L = np.array(table["modes"]["lambda"])
    if len(L) == 0:
        return None
    j = int(np.argmin(np.abs(L - lam)))
    return j


def changes_down(rows, i_top):
    """For cluster i_top of the finest table (rows[-1]): its lambda and E in each coarser table (nearest lambda),
    and the relative changes between consecutive rungs, coarse to fine."""
    lam = rows[-1]["modes"]["lambda"][i_top]
    seq = []
    for r in rows:
        j = match(lam, r)
        seq.append((r["modes"]["lambda"][j], r["modes"]["E"][j], j) if j is not None else (float("nan"),) * 3)
    dl = [abs(seq[k][0] - seq[k - 1][0]) / abs(seq[k][0]) for k in range(1, len(seq))]
    dE = [abs(seq[k][1] - seq[k - 1][1]) / seq[k][1] for k in range(1, len(seq))]
    return seq, dl, dE


def analyse_clusters(raw, angles, lines, cl_rows):
    lines.append("## Clusters across refinements (`--modes 20`, each table with its own convergence check)\n")
    lines.append("The %d largest clusters of the finest table of each ladder, matched by nearest lambda in each coarser "
                 "table. 'level' = the largest relative change of lambda and of E over the last two refinements "
                 "(three meshes): a cluster 'converges to level' this. Table flag: the finest table's own `converged` "
                 "(against the same order on the mesh twice as coarse, tolerance 1e-6).\n" % TOP_CLUSTERS)
    lines.append("| alpha | order | meshes | # | lambda (finest) | E (finest) | E share | dlambda per refinement | dE per refinement "
                 "| level | table's dlambda, dE | flag |")
    lines.append("|---|---|---|---|---|---|---|---|---|---|---|---|")
    levels = {}
    for alpha in angles:
        for order in (4, 6):
            rows = ladder(raw, alpha, order, "clusters")
            if len(rows) < 3:
                continue
            fin = rows[-1]
            n = min(TOP_CLUSTERS, len(fin["modes"]["E"]))
            for i in range(n):
                seq, dl, dE = changes_down(rows, i)
                level = max(dl[-2:] + dE[-2:])
                levels.setdefault((alpha, order), []).append((fin["modes"]["lambda"][i], fin["modes"]["E"][i], level))
                m = fin["modes"]
                lines.append("| %d | P%d | %s | %d | %.6f | %.3e | %.3f | %s | %s | %.1e | %.1e, %.1e | %s |" % (
                    alpha, order, ",".join("%g" % r["h"] for r in rows), i + 1, m["lambda"][i], m["E"][i],
                    m["E"][i] / fin["sum_rule"], " ".join("%.0e" % d for d in dl), " ".join("%.0e" % d for d in dE),
                    level, m["dlambda"][i], m["dE"][i], "yes" if m["converged"][i] else "no"))
                cl_rows.append(dict(alpha=alpha, order=order, h=fin["h"], rank=i + 1, **{
                    "lambda": m["lambda"][i], "E": m["E"][i], "share": m["E"][i] / fin["sum_rule"], "level": level,
                    "table_dlambda": m["dlambda"][i], "table_dE": m["dE"][i], "flag": m["converged"][i],
                    "dlambda_ladder": " ".join("%.3e" % d for d in dl), "dE_ladder": " ".join("%.3e" % d for d in dE)}))
    lines.append("")
    lines.append("Count of the followed clusters by level (last two refinements):\n")
    lines.append("| alpha | order | <= 1e-6 | <= 1e-4 | <= 1e-2 | > 1e-2 | best level (its lambda) |")
    lines.append("|---|---|---|---|---|---|---|")
    for (alpha, order), lv in levels.items():
        c = [sum(1 for _, _, l in lv if l <= 1e-6), sum(1 for _, _, l in lv if 1e-6 < l <= 1e-4),
             sum(1 for _, _, l in lv if 1e-4 < l <= 1e-2), sum(1 for _, _, l in lv if l > 1e-2)]
        best = min(lv, key=lambda x: x[2])
        lines.append("| %d | P%d | %d | %d | %d | %d | %.1e (%.4f) |" % (alpha, order, *c, best[2], best[0]))
    lines.append("")
    return levels


def analyse_flags(raw, angles, lines):
    """The hard rule of docs/cones.md: a cone table must never present an unconverged cluster as converged. For every table
    with flags, each flagged cluster is compared with the finest table of the same cone (nearest lambda); also the
    flags a looser --convergence-tolerance tau would give (max(dlambda, dE) <= tau) against the same reference."""
    lines.append("## Are flags honest? (every table of the study with a convergence check)\n")
    taus = [1e-6, 1e-4, 1e-3, 1e-2, 1e-1]
    lines.append("For each table and cluster, 'flagged at tau' = max(table's dlambda, dE) <= tau (tau = 1e-6 is the "
                 "default flag). 'Honest' = within tau of the nearest-lambda cluster of the finest clusters table of that "
                 "cone (P6 or P4, whichever is finer in h at the highest order); the finest table itself is not judged.\n")
    lines.append("| alpha | tables | clusters | " + " | ".join("flagged / dishonest at %g" % t for t in taus) + " |")
    lines.append("|---|---|---|" + "---|" * len(taus))
    bad = []
    for alpha in angles:
        tables = [r for r in raw.values() if r.get("status") == "ok" and r["alpha"] == alpha
                  and "converged" in r.get("modes", {})]
        if not tables:
            continue
        ref = sorted(tables, key=lambda r: (r["order"] < 6, r["h"]))[0]  # finest P6 if any
        stats = {t: [0, 0] for t in taus}
        nclusters = 0
        for r in tables:
            if r is ref:
                continue
            m = r["modes"]
            for i in range(len(m["E"])):
                nclusters += 1
                j = match(m["lambda"][i], ref)
                dev = max(abs(ref["modes"]["lambda"][j] - m["lambda"][i]) / abs(ref["modes"]["lambda"][j]),
                          abs(ref["modes"]["E"][j] - m["E"][i]) / ref["modes"]["E"][j])
                ind = max(m["dlambda"][i], m["dE"][i])
                for t in taus:
                    if ind <= t:
                        stats[t][0] += 1
                        if dev > t:
                            stats[t][1] += 1
                            bad.append((alpha, r["order"], r["h"], i + 1, m["lambda"][i], t, ind, dev))
                if m["converged"][i] and ind > r["convergence_tolerance"]:
                    bad.append((alpha, r["order"], r["h"], i + 1, m["lambda"][i], "flag inconsistent", ind, float("nan")))
        lines.append("| %d | %d | %d | %s |" % (alpha, len(tables) - 1, nclusters,
                                               " | ".join("%d / %d" % tuple(stats[t]) for t in taus)))
    lines.append("")
    if bad:
        lines.append("Dishonest flags found (alpha, order, h, cluster #, lambda, tau, indicator, deviation from the finest):\n")
        for b in bad[:40]:
            lines.append("- " + ", ".join(str(x) if not isinstance(x, float) else "%.3g" % x for x in b))
        lines.append("")
    return bad


def plot(raw, angles, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(len(angles), 2, figsize=(13, 2.9 * len(angles)), squeeze=False,
                             gridspec_kw=dict(width_ratios=[2.2, 1]))
    for row, alpha in zip(axes, angles):
        ax, ax2 = row
        p6 = ladder(raw, alpha, 6, "survey")
        if not p6:
            continue
        total = p6[-1]["sum_rule"]
        E, L, lo, hi = bands_of(p6[-1])
        ax.bar(lo, E / total, width=0.1, align="edge", color="tab:blue", alpha=0.35,
               label="band weight P6 h=%g, 200 steps" % p6[-1]["h"])
        g = [r for r in raw.values() if r.get("status") == "ok" and r["alpha"] == alpha and r["order"] == 6
             and r["h"] == 0.1 and r["set_extra"] == SURVEY_ONLY]
        if g:
            gmax = max(g, key=lambda r: r["steps"])
            Eg, _, lo_g, _ = bands_of(gmax)
            ax.step(np.append(lo_g, 2.0), np.append(Eg, Eg[-1]) / gmax["sum_rule"], where="post", color="k", lw=0.8,
                    label="P6 h=0.1, %d steps" % gmax["steps"])
        cl = ladder(raw, alpha, 6, "clusters") or ladder(raw, alpha, 4, "clusters")
        if cl:
            fin = cl[-1]
            m = fin["modes"]
            conv = np.array(m["converged"], dtype=bool)
            lam, Ec = np.array(m["lambda"]), np.array(m["E"]) / fin["sum_rule"]
            ax.vlines(lam[~conv], 0, Ec[~conv], color="tab:red", lw=1.2, label="clusters P%d h=%g: not converged" % (
                fin["order"], fin["h"]))
            if conv.any():
                ax.vlines(lam[conv], 0, Ec[conv], color="tab:green", lw=1.6, label="converged (flag)")
        lc = critical_lambda(alpha)
        for s in (-1, 1):
            ax.axvline(s * lc, color="grey", ls=":", lw=1)
        ax.set_yscale("log")
        ax.set_ylim(1e-6, 1)
        ax.set_xlim(-2, 2)
        ax.set_title("alpha = %d deg (R = %.3f, H = %.3f): share of A_f - J_zh; dotted: +-2 sin(alpha)" % (
            alpha, *cone_dims(alpha)), fontsize=9)
        ax.tick_params(labelsize=8)
        ax.legend(fontsize=6.5, loc="upper left")
        # Right: changes against h.
        for order, style in ((4, "--"), (6, "-")):
            rows = ladder(raw, alpha, order, "survey")
            if len(rows) < 2:
                continue
            hs = [r["h"] for r in rows[1:]]
            dJ = [abs(rows[k]["J_zh"] - rows[k - 1]["J_zh"]) / rows[k]["J_zh"] for k in range(1, len(rows))]
            ax2.loglog(hs, np.maximum(dJ, 1e-16), "o" + style, color="tab:blue", ms=3, label="J_zh P%d" % order)
            Efin, _, _, _ = bands_of(rows[-1])
            heavy = Efin >= HEAVY_BAND * rows[-1]["sum_rule"]
            dB = []
            for k in range(1, len(rows)):
                a, _, _, _ = bands_of(rows[k])
                b, _, _, _ = bands_of(rows[k - 1])
                dB.append(max(np.abs(a[heavy] - b[heavy]) / a[heavy]))
            ax2.loglog(hs, dB, "s" + style, color="tab:orange", ms=3, label="heavy bands (max) P%d" % order)
            neg = int(np.argmax(np.where(np.array(rows[-1]["bands"]["hi"]) <= 0, Efin, -1)))  # the retrograde peak
            dN = [abs(bands_of(rows[k])[0][neg] - bands_of(rows[k - 1])[0][neg]) / bands_of(rows[k])[0][neg]
                  for k in range(1, len(rows))]
            ax2.loglog(hs, np.maximum(dN, 1e-16), "D" + style, color="tab:green", ms=3,
                       label="band of the lambda<0 peak P%d" % order)
            cl = ladder(raw, alpha, order, "clusters")
            if len(cl) >= 2:
                dE = []
                for k in range(1, len(cl)):
                    j = match(cl[-1]["modes"]["lambda"][0], cl[k])
                    jc = match(cl[-1]["modes"]["lambda"][0], cl[k - 1])
                    dE.append(abs(cl[k]["modes"]["E"][j] - cl[k - 1]["modes"]["E"][jc]) / cl[k]["modes"]["E"][j])
                ax2.loglog([r["h"] for r in cl[1:]], dE, "^" + style, color="tab:red", ms=3,
                           label="largest cluster E P%d" % order)
        ax2.set_title("relative change from the mesh twice as coarse", fontsize=9)
        ax2.set_xlabel("h", fontsize=8)
        ax2.tick_params(labelsize=8)
        ax2.grid(True, lw=0.3)
        ax2.legend(fontsize=6)
    fig.tight_layout()
    fig.savefig(path, dpi=100)


def write_csv(path, rows):
    if not rows:
        return
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        for r in rows:
            w.writerow({k: ("%.6e" % v if isinstance(v, float) else v) for k, v in r.items()})


def machine():
    cpu = "?"
    with open("/proc/cpuinfo") as f:
        for line in f:
            if line.startswith("model name"):
                cpu = line.split(":", 1)[1].strip()
                break
    return "%d cpus, %s" % (os.cpu_count(), cpu)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("binary", nargs="?", default=os.path.join(REPO, "build/modes/cavity-modes"))
    ap.add_argument("--quick", action="store_true", help="a small plan (coarse meshes, order 4)")
    ap.add_argument("--angles", default=",".join(map(str, ANGLES)))
    ap.add_argument("--analyse-only", action="store_true", help="no runs: analyse what the raw file holds")
    args = ap.parse_args()
    angles = [int(a) for a in args.angles.split(",")]
    os.makedirs(RESULTS, exist_ok=True)
    raw = load_raw()
    binary = os.path.abspath(args.binary)
    if not args.analyse_only:
        if not os.access(binary, os.X_OK):
            sys.exit("cone_study: %s is not an executable" % binary)
        runs = plan_runs(QUICK_PLAN if args.quick else PLAN, angles)
        todo = [r for r in runs if key(r[0], r[1], r[2], r[3], r[4]) not in raw]
        print("%d runs planned, %d already in %s" % (len(runs), len(runs) - len(todo), os.path.relpath(RAW)), flush=True)
        t0 = time.perf_counter()
        for n, (alpha, order, h, extra, steps) in enumerate(todo, 1):
            r = run(binary, alpha, order, h, extra, steps)
            k = key(alpha, order, h, extra, steps)
            raw[k] = r
            save_raw(raw)
            print("[%3d/%d %5.0f s] %-32s %s %6s dofs %7.1f s (user %.1f, load %.1f)" % (
                n, len(todo), time.perf_counter() - t0, k, r["status"], r.get("ndof", "-"), r["process_s"],
                r.get("user_s", 0), r.get("load1", 0)), flush=True)
        for alpha in angles:
            bands = None
            for order, sizes in (QUICK_WINDOW_LADDER if args.quick else WINDOW_LADDER).items():
                for h in sizes:
                    k = "a%d_P%d_h%g_window" % (alpha, order, h)
                    if k in raw:
                        continue
                    bands = bands or window_bands(raw, alpha)
                    raw[k] = run_windows(binary, alpha, order, h, bands)
                    save_raw(raw)
                    print("[window %5.0f s] %-32s %s %s dofs %7.1f s (user %.1f, load %.1f)" % (
                        time.perf_counter() - t0, k, raw[k]["status"], raw[k].get("ndof", "-"), raw[k]["process_s"],
                        raw[k].get("user_s", 0), raw[k].get("load1", 0)), flush=True)
    stamp = datetime.date.today().isoformat()
    commit = subprocess.run(["git", "-C", REPO, "log", "-1", "--format=%h"], capture_output=True, text=True).stdout.strip()
    total = sum(r.get("process_s", 0) for r in raw.values())
    user = sum(r.get("user_s", 0) for r in raw.values())
    loads = [r["load1"] for r in raw.values() if "load1" in r]
    lines = ["# Cone convergence study (%s)\n" % stamp,
             "Generated by `bench/cone_study.py` from `bench/results/cone_study_raw.json` (%d runs; %.0f s of process wall "
             "time, %.0f s user CPU; 1-minute load %.1f..%.1f during the runs; machine: %s; repository HEAD %s at "
             "analysis). Cones of volume pi/3: R = tan(alpha)^(1/3), H = tan(alpha)^(-2/3).\n" % (
                 len(raw), total, user, min(loads, default=0), max(loads, default=0), machine(), commit)]
    run_rows, band_rows, cl_rows, win_rows = [], [], [], []
    analyse_integrated(raw, angles, lines, run_rows)
    analyse_bands(raw, angles, lines, band_rows)
    analyse_windows(raw, angles, lines, win_rows)
    analyse_clusters(raw, angles, lines, cl_rows)
    analyse_flags(raw, angles, lines)
    md = os.path.join(RESULTS, "cone_study_%s.md" % stamp)
    with open(md, "w") as f:
        f.write("\n".join(lines) + "\n")
    write_csv(os.path.join(RESULTS, "cone_study_runs.csv"), run_rows)
    write_csv(os.path.join(RESULTS, "cone_study_bands.csv"), band_rows)
    write_csv(os.path.join(RESULTS, "cone_study_clusters.csv"), cl_rows)
    write_csv(os.path.join(RESULTS, "cone_study_windows.csv"), win_rows)
    png = os.path.join(RESULTS, "cone_study.png")
    plot(raw, angles, png)
    print("\n".join(lines))
    print("wrote %s, %s and the CSVs" % (md, png))


if __name__ == "__main__":
    main()
