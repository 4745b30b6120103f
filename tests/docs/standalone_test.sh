#!/usr/bin/env bash
# The repository stands alone for a user who clones it: no text cites a file outside it (the product contract or
# the source papers by path), an unnumbered internal document ("SPEC §2", "seed 000") or an issue number; every
# docs page a text names (docs/NAME.md) exists; every relative Markdown link in README.md and docs/ resolves.
# Papers are cited by author and equation ("Kononov (26)"), docs/physics.md §5 lists them.
set -u
root=${1:?usage: standalone_test.sh REPOSITORY_ROOT}
cd "$root"
fail=0
bad() { echo "FAILED: $*"; fail=1; }

# Tracked text files (a clean checkout's view), minus this test, which has to spell the patterns. A copy without
# git (an export, as bench/fresh_machine.sh makes) is taken whole, minus build trees and outputs.
list_files() {
  if git rev-parse --is-inside-work-tree > /dev/null 2>&1; then
    git ls-files
  else
    find . \( -name .git -o -name 'build*' -o -name out \) -prune -o -type f -print | sed 's#^\./##'
  fi
}
mapfile -t files < <(list_files | grep -vE '\.(h5|png|jpg|pdf)$|^tests/docs/standalone_test\.sh$')
[ ${#files[@]} -gt 50 ] || { echo "FAILED: no file list (${#files[@]} files)"; exit 1; }

check_pattern() {  # description, extended regex
  local hits
  hits=$(grep -nIE -- "$2" "${files[@]}" 2>/dev/null | head -5)
  if [ -n "$hits" ]; then bad "$1:"$'\n'"$hits"; else echo "ok: no $1"; fi
}
check_pattern "citation of the contract outside the repository" 'SPEC(\.md| §| section [0-9])'
check_pattern "citation of a paper by its file number" '[Ss]eed 00[0-9]|[Ss]eeds/'
check_pattern "path outside the repository" '\.\./shared|\.\./\.\./shared'
check_pattern "issue number" '[Ii]ssue #?[0-9]+'

# docs/NAME.md named anywhere must exist.
missing=$(grep -ohIE 'docs/[A-Za-z0-9_-]+\.md' "${files[@]}" | sort -u | while read -r p; do [ -f "$p" ] || echo "$p"; done)
if [ -n "$missing" ]; then bad "docs pages named but missing: $missing"; else echo "ok: every docs/*.md named exists"; fi

# Relative Markdown links [text](target) in README.md and docs/*.md resolve (anchors stripped).
for md in README.md docs/*.md; do
  dir=$(dirname "$md")
  while read -r target; do
    t=${target%%#*}
    [ -z "$t" ] && continue
    case "$t" in http://*|https://*|mailto:*) continue ;; esac
    [ -e "$dir/$t" ] || bad "$md links to $target, which does not exist"
  done < <(grep -oE '\]\([^)]+\)' "$md" | sed -E 's/^\]\(//; s/\)$//; s/ .*//')
done
[ $fail -eq 0 ] && echo "ok: relative Markdown links resolve"

# The physics page has the sections the citations name.
for s in 1 2 3 4 5; do grep -q "^## $s\. " docs/physics.md || bad "docs/physics.md has no section $s"; done
if [ $fail -ne 0 ]; then echo "standalone: FAILED"; exit 1; fi
echo "standalone: all checks passed"
