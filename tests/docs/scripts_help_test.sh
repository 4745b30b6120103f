#!/usr/bin/env bash
# Every scripts/*.sh answers --help (and -h) with a usage text and does nothing else: installers, cmake, ctest and
# the programs are replaced by stubs that leave a mark, and no mark may appear.
set -u
root=${1:?usage: scripts_help_test.sh REPOSITORY_ROOT}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir "$work/bin"
for tool in apt-get sudo dpkg-query cmake ctest make mpirun python3; do
  printf '#!/bin/sh\ntouch "%s/ran-%s"\nexit 1\n' "$work" "$tool" > "$work/bin/$tool"
  chmod +x "$work/bin/$tool"
done
fail=0
for script in "$root"/scripts/*.sh; do
  for flag in --help -h; do
    out=$(PATH="$work/bin:$PATH" timeout 10 bash "$script" "$flag" 2>&1)
    rc=$?
    name="$(basename "$script") $flag"
    if [ $rc -ne 0 ]; then echo "FAILED: $name: exit $rc"; fail=1; continue; fi
    if ! head -1 <<< "$out" | grep -q '^usage: '; then echo "FAILED: $name: no usage line: $(head -1 <<< "$out")"; fail=1; continue; fi
    if ls "$work"/ran-* > /dev/null 2>&1; then echo "FAILED: $name ran $(ls "$work" | grep ran-)"; fail=1; rm -f "$work"/ran-*; continue; fi
    echo "ok: $name ($(head -1 <<< "$out"))"
  done
done
# The plot scripts share one command line: one positional argument (the input) and the PNG after -o.
for script in "$root"/scripts/plot_*.py; do
  help=$(/usr/bin/python3 "$script" --help 2>&1)
  positional=$(awk '/^positional arguments:/{f=1; next} f && /^$/{exit} f && /^  [^ -]/{n++} END{print n+0}' <<< "$help")
  if [ "$positional" -eq 1 ] && grep -qE '^  -o [A-Z]+, --output' <<< "$help"; then
    echo "ok: $(basename "$script") takes INPUT -o PNG"
  else
    echo "FAILED: $(basename "$script"): $positional positional arguments, -o: $(grep -c -- '-o ' <<< "$help")"; fail=1
  fi
done
[ $fail -eq 0 ] && echo "scripts --help: all passed" || { echo "scripts --help: FAILED"; exit 1; }
