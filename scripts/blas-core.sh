#!/usr/bin/env bash
# Sourced by the scripts that run the programs (test.sh, run-default.sh, bench/): OpenBLAS chooses its kernels from
# the CPU's model number, and a hypervisor that reports a generic model ("Intel(R) Xeon(R) Processor" on our 2-core
# machines) gets the SSE3 "Prescott" kernels although the CPU has AVX-512. Choose from the CPU's flags instead —
# SkylakeX with AVX-512 (F, CD, BW, DQ, VL), Haswell with AVX2 and FMA — unless OPENBLAS_CORETYPE is set already.
# Measured (docs/benchmarks.md, "OpenBLAS kernels"): MUMPS's factorisation of the water cylinder's 39 002 unknowns
# 0.84 s with Prescott's kernels, 0.52 s with SkylakeX's.
# Run rather than sourced (e.g. with --help): this text, nothing else.
if [ "${BASH_SOURCE[0]}" = "$0" ]; then
  echo "usage: source scripts/blas-core.sh   (exports OPENBLAS_CORETYPE for the programs this shell then starts)"
  sed -n '2,/^# Run rather/p' "$0" | grep '^#' | grep -v '^# Run rather' | sed 's/^# \{0,1\}//'
  exit 0
fi
if [ -z "${OPENBLAS_CORETYPE:-}" ] && [ -r /proc/cpuinfo ]; then
  rc_flags=" $(grep -m1 '^flags' /proc/cpuinfo) "
  rc_has() { for f in "$@"; do case "$rc_flags" in *" $f "*) ;; *) return 1 ;; esac; done; }
  if rc_has avx512f avx512cd avx512bw avx512dq avx512vl; then
    export OPENBLAS_CORETYPE=SkylakeX
  elif rc_has avx2 fma; then
    export OPENBLAS_CORETYPE=Haswell
  fi
  unset -f rc_has
  unset rc_flags
fi
