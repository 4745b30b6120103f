"""Fuzz test of both programs (seeded, a few hundred cases, under a minute).

Inputs a user can get wrong, made at random from good ones: byte-corrupted and edited mode tables, mutated scene
files, random option values. Every case must end in time with exit 0 or a one-line error (exit 1 or 2), never a
signal; print only UTF-8; leave no file behind when it fails (no output, no temporary) and never change its
inputs; and what it writes on success holds no NaN.

    python3 tests/fuzz/fuzz_test.py CAVITY_MODES CHAIN_ROM [--seed 1] [--cases 240] [--keep DIR]
"""
import argparse
import hashlib
import math
import os
import random
import re
import shutil
import subprocess
import sys
import tempfile
import time

import h5py
import numpy as np

LIMIT_S = 20  # every single run must end within this
EXTRA = random.Random(2026)  # the cases added later draw from this, leaving the main generator's sequence alone

SCENE = """[system]
kind = "fixed"
gravity = 9.81

[[body]]
mass = 2.0
A = 0.05
C = 0.08
com = 0.05
next_joint = 0.15
spin = 200.0
[body.cavity]
table = "sphere.h5"
density = 1000.0
scale = 0.04
center = 0.05

[[body]]
mass = 1.0
A = 0.02
C = 0.035
com = 0.04
spin = 150.0
[body.cavity]
table = "cylinder.h5"
density = 800.0
scale = 0.03
center = 0.04
coverage = 0.5

[[joint]]
stiffness = 5.0
friction = 0.001

[initial]
tilt = [[0.01, 0.0], [0.0, -0.005]]
rate = [[0.0, 0.1], [0.2, 0.0]]

[run]
t_end = 0.05
output_step = 0.001
method = "exact"
"""

# The same chain with body 1's tank viscous (Ek = nu/(spin scale^2) = 3.2e-3/(200 * 0.04^2) = 1e-2, the table's).
VISCOUS_SCENE = SCENE.replace('table = "sphere.h5"', 'table = "viscous.h5"\nviscosity = 3.2e-3')

ODD_NUMBERS = ["0", "-1", "1e308", "-1e308", "1e-308", "nan", "inf", "-inf", "1e20", "3", "0.5", "-0.0",
               "2147483648", "\"text\"", "[]", "true"]


class Failure(Exception):
    pass


def digest(path):
    return hashlib.sha256(open(path, "rb").read()).hexdigest()


def run(cmd, cwd, inputs, outputs):
    """Runs one case; checks time, exit, UTF-8, one-line errors, leftovers, inputs unchanged, NaN-free outputs."""
    before = {p: digest(os.path.join(cwd, p)) for p in inputs}
    for o in outputs:
        if os.path.exists(os.path.join(cwd, o)):
            os.remove(os.path.join(cwd, o))
    listing = set(os.listdir(cwd))
    t0 = time.time()
    try:
        p = subprocess.run(cmd, cwd=cwd, capture_output=True, timeout=LIMIT_S)
    except subprocess.TimeoutExpired:
        raise Failure("ran past %d s" % LIMIT_S)
    took = time.time() - t0
    if p.returncode < 0 or p.returncode > 2:
        raise Failure("exit %d (signal or unexpected code); stderr: %r" % (p.returncode, p.stderr[-300:]))
    for name, data in (("stdout", p.stdout), ("stderr", p.stderr)):
        try:
            data.decode("utf-8")
        except UnicodeDecodeError as e:
            raise Failure("%s is not UTF-8: %s" % (name, e))
    err_lines = [l for l in p.stderr.decode().splitlines() if l.strip()]
    if p.returncode != 0:
        errors = [l for l in err_lines if ": error: " in l or l.startswith("error")]
        if len(errors) != 1:
            raise Failure("exit %d with %d error lines: %r" % (p.returncode, len(errors), err_lines[-5:]))
    new = set(os.listdir(cwd)) - listing
    for f in new:
        if ".tmp" in f:
            raise Failure("left a temporary file %s" % f)
        if p.returncode != 0:
            raise Failure("failed (exit %d) but left %s" % (p.returncode, f))
    for path, h in before.items():
        if digest(os.path.join(cwd, path)) != h:
            raise Failure("changed its input %s" % path)
    if p.returncode == 0:
        for o in outputs:
            full = os.path.join(cwd, o)
            if os.path.exists(full):
                check_no_nan(full)
    return p.returncode, took


def check_no_nan(path):
    if path.endswith(".h5"):
        with h5py.File(path, "r") as f:
            bad = []

            def visit(name, obj):
                if isinstance(obj, h5py.Dataset) and obj.dtype.kind == "f" and not np.all(np.isfinite(obj[()])):
                    bad.append(name)
            f.visititems(visit)
            for k, v in f.attrs.items():
                if isinstance(v, (float, np.floating)) and not math.isfinite(v):
                    bad.append("@" + k)
            if bad:
                raise Failure("wrote non-finite values in %s: %s" % (os.path.basename(path), bad[:5]))
    elif path.endswith(".csv"):
        text = open(path).read().lower()
        if re.search(r"(^|,)\s*-?(nan|inf)", text, re.M):
            raise Failure("wrote NaN or inf in %s" % os.path.basename(path))


# --- case makers -------------------------------------------------------------------------------------------------

def corrupt_bytes(rng, src, dst):
    data = bytearray(open(src, "rb").read())
    for _ in range(rng.randint(1, 12)):
        data[rng.randrange(len(data))] = rng.randrange(256)
    if rng.random() < 0.2:
        data = data[:rng.randrange(len(data))]
    open(dst, "wb").write(bytes(data))


def edit_table(rng, src, dst):
    shutil.copy(src, dst)
    with h5py.File(dst, "a") as f:
        kind = rng.random()
        datasets = []
        f.visititems(lambda n, o: datasets.append(n) if isinstance(o, h5py.Dataset) else None)
        if kind < 0.4 and datasets:
            name = rng.choice(datasets)
            d = f[name]
            if d.size > 0 and d.dtype.kind in "fi":
                i = rng.randrange(d.size)
                value = rng.choice([0.0, -1.0, 1e308, -1e-300, float("nan"), float("inf"), 2.5, 1e6])
                arr = d[()]
                arr.flat[i] = value if d.dtype.kind == "f" else int(min(max(value if math.isfinite(value) else 0, -2**31), 2**31 - 1))
                d[...] = arr
        elif kind < 0.6 and datasets:
            del f[rng.choice(datasets)]
        elif kind < 0.8:
            names = list(f.attrs.keys())
            if names:
                name = rng.choice(names)
                value = rng.choice([0.0, -1.0, float("nan"), 1e308, np.bytes_(b"\xff\xfe"), np.int64(-5), "text"])
                # ... or an array where one value belongs: read into one number, it once overwrote the stack. Drawn
                # from its own generator, so that the seeded cases of the main one stay what they were.
                if EXTRA.random() < 0.4:
                    value = EXTRA.choice([np.full(4000, 0.5), np.array([1.0, 2.0]), np.arange(3, dtype=np.int64),
                                          np.array([b"ab", b"cd"])])
                del f.attrs[name]
                f.attrs[name] = value
        else:
            names = list(f.attrs.keys())
            if names:
                del f.attrs[rng.choice(names)]


def mutate_scene(rng, text):
    lines = text.splitlines()
    kind = rng.random()
    if kind < 0.55:  # a number replaced by an odd value
        numbered = [i for i, l in enumerate(lines) if re.search(r"=\s*[-0-9.\[]", l)]
        i = rng.choice(numbered)
        values = re.findall(r"-?[0-9.]+(?:e-?[0-9]+)?", lines[i].split("=", 1)[1])
        if values:
            v = rng.choice(values)
            lines[i] = lines[i].replace(v, rng.choice(ODD_NUMBERS), 1)
    elif kind < 0.7:  # a line dropped
        del lines[rng.randrange(len(lines))]
    elif kind < 0.8:  # a line doubled
        i = rng.randrange(len(lines))
        lines.insert(i, lines[i])
    elif kind < 0.9:  # bytes in the text
        i = rng.randrange(len(lines))
        lines[i] = lines[i][:rng.randrange(len(lines[i]) + 1)] + rng.choice(["\x00", "\xff", "]]", "[", "\"", "= ="]) 
    else:  # truncated
        lines = lines[:rng.randrange(len(lines))]
    return "\n".join(lines) + "\n"


def random_option_case(rng):
    value = lambda: rng.choice(["0", "-1", "nan", "inf", "1e308", "abc", "", "0.5", "1", "2", "1e-300"])
    shape = rng.choice([["sphere", "--radius", value()], ["spheroid", "--a", "1", "--c", value()],
                        ["cylinder", "--radius", "1", "--height", value()], ["cone", "--radius", value(), "--height", "1"]])
    # Valid computations are kept small (a coarse mesh, few modes) unless the draw replaces these.
    opts = {"--order": "3", "--mesh-size": "0.5", "--modes": "2"}
    for option in rng.sample(["--order", "--mesh-size", "--modes", "--coverage", "--min-lambda", "--lanczos-steps",
                              "--survey-steps", "--tolerance", "--convergence-tolerance", "--ekman", "--wall-size",
                              "--radial-size", "--method", "--clusters"], rng.randint(1, 3)):
        opts[option] = value()
    if "--coverage" in opts:
        del opts["--modes"]
    return shape + [x for kv in opts.items() for x in kv]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("modes")
    ap.add_argument("rom")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--cases", type=int, default=240)
    ap.add_argument("--keep", help="copy each failing case's inputs into this folder")
    a = ap.parse_args()
    a.modes, a.rom = os.path.abspath(a.modes), os.path.abspath(a.rom)
    rng = random.Random(a.seed)
    work = tempfile.mkdtemp(prefix="rc_fuzz_")
    failures, counts, slowest, seconds = [], {}, (0.0, ""), {}
    start = time.time()
    try:
        subprocess.run([a.modes, "sphere", "--radius", "1", "--order", "3", "--mesh-size", "0.5", "-o", "sphere.h5"],
                       cwd=work, check=True, capture_output=True)
        subprocess.run([a.modes, "cylinder", "--radius", "1", "--height", "2", "--modes", "5", "-o", "cylinder.h5"],
                       cwd=work, check=True, capture_output=True)
        subprocess.run([a.modes, "sphere", "--radius", "1", "--ekman", "1e-2", "--order", "3", "--mesh-size", "0.5",
                        "--modes", "1", "-o", "viscous.h5"], cwd=work, check=True, capture_output=True)
        for name, text in (("scene.toml", SCENE), ("viscous_scene.toml", VISCOUS_SCENE)):
            open(os.path.join(work, name), "w").write(text)
            subprocess.run([a.rom, "spectrum", name], cwd=work, check=True, capture_output=True)
        makers = ["table bytes", "table edit", "scene", "options"]
        for case in range(a.cases):
            what = makers[case % len(makers)]
            counts[what] = counts.get(what, 0) + 1
            try:
                if what in ("table bytes", "table edit"):
                    src = rng.choice(["sphere.h5", "cylinder.h5", "viscous.h5"])
                    (corrupt_bytes if what == "table bytes" else edit_table)(rng, os.path.join(work, src),
                                                                             os.path.join(work, "bad.h5"))
                    scene = (VISCOUS_SCENE if src == "viscous.h5" else SCENE).replace('"%s"' % src, '"bad.h5"')
                    open(os.path.join(work, "bad_scene.toml"), "w").write(scene)
                    cmds = [([a.modes, "info", "bad.h5", "--json"], []),
                            ([a.rom, "spectrum", "bad_scene.toml", "--json"], [])]
                    if rng.random() < 0.3:
                        cmds.append(([a.modes, "compare", "bad.h5", src], []))
                    if EXTRA.random() < 0.3:  # a damaged table read by run as well as by spectrum
                        cmds.append(([a.rom, "run", "bad_scene.toml", "-o", "traj_bad.h5"], ["traj_bad.h5"]))
                    inputs = ["bad.h5", "bad_scene.toml", src]
                elif what == "scene":
                    base = VISCOUS_SCENE if rng.random() < 0.3 else SCENE
                    open(os.path.join(work, "bad_scene.toml"), "w").write(mutate_scene(rng, base))
                    cmds = [([a.rom, "spectrum", "bad_scene.toml"], []),
                            ([a.rom, "run", "bad_scene.toml", "-o", "traj.h5"], ["traj.h5"])]
                    inputs = ["bad_scene.toml", "sphere.h5", "cylinder.h5", "viscous.h5"]
                else:
                    cmds = [([a.modes] + random_option_case(rng) + ["-o", "opt.h5"], ["opt.h5"])]
                    inputs = ["sphere.h5"]
                for cmd, outs in cmds:
                    rc, took = run(cmd, work, inputs, outs)
                    seconds[what] = seconds.get(what, 0.0) + took
                    if took > slowest[0]:
                        slowest = (took, " ".join(os.path.basename(c) if i == 0 else c for i, c in enumerate(cmd)))
            except Failure as e:
                failures.append("case %d (%s): %s: %s" % (case, what, " ".join(cmd[1:]), e))
                print("FAILED:", failures[-1], flush=True)
                if a.keep:
                    keep = os.path.join(a.keep, "case_%d" % case)
                    os.makedirs(keep, exist_ok=True)
                    for name in inputs:
                        shutil.copy(os.path.join(work, name), keep)
    finally:
        shutil.rmtree(work, ignore_errors=True)
    print("fuzz: seed %d, %d cases (%s), %.1f s; slowest run %.2f s (%s); %d failures"
          % (a.seed, a.cases, ", ".join("%d %s in %.1f s" % (n, k, seconds.get(k, 0)) for k, n in counts.items()),
             time.time() - start,
             slowest[0], slowest[1], len(failures)))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
