#!/usr/bin/env bash
# The README's default job on a fresh machine, timed: a minimal Debian 12 (debootstrap --variant=minbase, no
# compiler, no cmake, no Python) in a chroot, a clean copy of the committed tree (git archive HEAD), and then
# `bash scripts/run-default.sh` inside it — package installation (apt-get update + install), configure, build and
# the job — as a user's first run. The minimal system has less than a new machine of ours (which has g++ and cmake),
# so the time is an upper bound. Prints the run's step lines and the total; writes OUT/fresh_machine_<date>.txt.
# JOB test runs the README's test command (`bash scripts/test.sh`) instead: OUT/fresh_machine_test_<date>.txt.
#   sudo bash bench/fresh_machine.sh [OUT] [CHROOT] [default|test]   (root; 10-25 minutes; needs debootstrap)
set -euo pipefail
if [ "${1:-}" = "--help" ] || [ "${1:-}" = "-h" ]; then
  sed -n '2,8p' "$0" | sed 's/^# \{0,1\}//'
  exit 0
fi
ROOT=$(cd "$(dirname "$0")/.." && pwd)
OUT=${1:-$ROOT/bench/results}
CHROOT=${2:-/var/tmp/rc-fresh-machine}
JOB=${3:-default}
case "$JOB" in
  default) script=scripts/run-default.sh; name=fresh_machine ;;
  test) script=scripts/test.sh; name=fresh_machine_test ;;
  *) echo "fresh_machine.sh: JOB is default or test, not '$JOB'" >&2; exit 1 ;;
esac
[ "$(id -u)" -eq 0 ] || { echo "fresh_machine.sh: needs root (debootstrap, chroot, mounts)" >&2; exit 1; }
command -v debootstrap > /dev/null || { echo "fresh_machine.sh: apt-get install debootstrap first" >&2; exit 1; }
[ ! -e "$CHROOT" ] || { echo "fresh_machine.sh: $CHROOT exists; remove it first" >&2; exit 1; }
mkdir -p "$OUT"
log=$OUT/${name}_$(date +%F).txt
cleanup() {
  for m in dev/shm dev/pts dev sys proc; do umount -l "$CHROOT/$m" 2> /dev/null || true; done
}
trap cleanup EXIT

t0=$SECONDS
debootstrap --variant=minbase bookworm "$CHROOT" http://deb.debian.org/debian > "$CHROOT.debootstrap.log" 2>&1 ||
  { tail -5 "$CHROOT.debootstrap.log" >&2; exit 1; }
echo "minimal Debian 12 made in $((SECONDS - t0)) s (not part of the first run)"
mount -t proc proc "$CHROOT/proc"
mount -t sysfs sys "$CHROOT/sys"
mount --bind /dev "$CHROOT/dev"
mount --bind /dev/pts "$CHROOT/dev/pts"
mount -t tmpfs shm "$CHROOT/dev/shm"
cp /etc/resolv.conf "$CHROOT/etc/resolv.conf"
mkdir -p "$CHROOT/root/repo"
git -C "$ROOT" archive HEAD | tar -x -C "$CHROOT/root/repo"
commit=$(git -C "$ROOT" rev-parse --short HEAD)

{
  echo "# bench/fresh_machine.sh, $(date -u '+%F %H:%M UTC'), commit $commit, $(nproc) cores,"\
       "$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), $(free -g | awk '/Mem/ {print $2}') GiB"
  echo "# chroot: debootstrap --variant=minbase bookworm (no compiler, cmake or Python); command: bash $script"
} > "$log.tmp"
t1=$SECONDS
status=0
chroot "$CHROOT" /usr/bin/env -i HOME=/root PATH=/usr/sbin:/usr/bin:/sbin:/bin TERM=dumb \
  bash -c "cd /root/repo && bash $script" > "$CHROOT.run.log" 2>&1 || status=$?
total=$((SECONDS - t1))
grep -E '^\[run-default|^test\.sh:|tests passed|tests failed|Total Test time' "$CHROOT.run.log" >> "$log.tmp" || true
echo "exit status $status; first run (install + build + $JOB): $total s" >> "$log.tmp"
mv "$log.tmp" "$log"
cat "$log"
exit "$status"
