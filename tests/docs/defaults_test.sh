#!/usr/bin/env bash
# The defaults docs/modes.md ("Options and defaults") states are those `cavity-modes ... --help` states: every
# "(default X)" of every command's help appears in the docs row of that option, and every option of the docs
# table exists in some command's help. docs/geometry.md states the command's order default, not the library's.
set -u
bin=${1:?usage: defaults_test.sh CAVITY_MODES REPOSITORY_ROOT}
root=${2:?usage: defaults_test.sh CAVITY_MODES REPOSITORY_ROOT}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for cmd in sphere spheroid cylinder cone section "response sphere" "response cylinder" "response section" compare; do
  # shellcheck disable=SC2086
  "$bin" $cmd --help > "$work/$(tr ' ' _ <<< "$cmd").txt" 2>&1 || { echo "FAILED: cavity-modes $cmd --help"; exit 1; }
done
python3 - "$work" "$root/docs/modes.md" "$root/docs/geometry.md" <<'PY'
import glob, os, re, sys
work, modes_md, geometry_md = sys.argv[1:4]
helps = {}  # option -> list of (command, default phrase)
for path in sorted(glob.glob(os.path.join(work, "*.txt"))):
    command = os.path.basename(path)[:-4].replace("_", " ")
    text = open(path).read()
    # An option's entry: its line and the indented lines after it (CLI11 puts long descriptions there).
    for entry in re.split(r"\n(?=  -)", text):
        m = re.match(r"\s*(?:-[a-z],)?(--[a-z-]+)", entry)
        if not m:
            continue
        option = m.group(1)
        helps.setdefault(option, [])
        for phrase in re.findall(r"\(default ([^()]*(?:\([^()]*\)[^()]*)*)\)", entry):
            helps[option].append((command, phrase.strip()))
section = open(modes_md).read().split("## Options and defaults", 1)
if len(section) < 2:
    sys.exit("FAILED: docs/modes.md has no section 'Options and defaults'")
rows = {}
for line in section[1].splitlines():
    cells = [c.strip() for c in line.strip().strip("|").split("|")]
    if len(cells) == 3 and cells[0].startswith("`"):
        for option in re.findall(r"`(--[a-z-]+)`", cells[0]):
            rows.setdefault(option, []).append(cells[2])
failed = 0
for option, defaults in sorted(helps.items()):
    for command, phrase in defaults:
        if not any(phrase in cell for cell in rows.get(option, [])):
            print("FAILED: %s %s --help says (default %s); docs/modes.md's row: %s" % (command, option, phrase, rows.get(option)))
            failed += 1
for option in sorted(rows):
    if option not in helps:
        print("FAILED: docs/modes.md lists %s, which no cavity-modes command takes" % option)
        failed += 1
geometry = open(geometry_md).read()
if re.search(r"`order` \(default \*\*3\*\*", geometry):
    print("FAILED: docs/geometry.md gives order default 3 as the command's (cavity-modes uses 6)")
    failed += 1
checked = sum(len(d) for d in helps.values())
print("%d default phrases of %d options checked against docs/modes.md; %d failures" % (checked, len(helps), failed))
sys.exit(1 if failed else 0)
PY
