# Shared by the command-line tests (sourced): counters, ok/bad, and expect_error, which runs a command that
# must fail with exactly one error line on stderr containing the expected text and leave no out.h5 behind.
# Progress lines ("[   1.5 s] ...", printed by runs longer than a second) are not counted.
pass=0
fail=0
ok() { echo "ok: $1"; pass=$((pass + 1)); }
bad() { echo "FAILED: $1"; fail=$((fail + 1)); }

expect_error() {  # name, expected text in the message, command...
  local name=$1 text=$2
  shift 2
  rm -f out.h5 out.h5.samples
  "$@" > stdout.txt 2> stderr.txt
  local rc=$?
  local lines
  lines=$(grep -cv '^\[ *[0-9.]* s\] ' stderr.txt)
  if [ "$rc" -eq 0 ]; then bad "$name: exit 0"; return; fi
  if [ "$lines" -ne 1 ]; then bad "$name: $lines lines on stderr: $(cat stderr.txt)"; return; fi
  if ! grep -v '^\[ *[0-9.]* s\] ' stderr.txt | grep -q -- "$text"; then bad "$name: message lacks '$text': $(cat stderr.txt)"; return; fi
  # (a response fit's kept forced solves, out.h5.samples, are no half-written table: docs/viscous.md, "Response fit")
  if ls out.h5* 2> /dev/null | grep -qv '\.samples$'; then bad "$name: left a file behind"; return; fi
  ok "$name ($(grep -v '^\[ *[0-9.]* s\] ' stderr.txt))"
}

# Prints the closing line ctest users read and exits non-zero on any failure.
finish() {
  echo "$pass passed, $fail failed"
  [ "$fail" -eq 0 ]
}
