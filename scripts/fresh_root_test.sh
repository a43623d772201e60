#!/usr/bin/env bash
# Runs the README's test command (bash scripts/test.sh) in a fresh Debian 12
# root, as a newcomer's machine would be: minbase plus ca-certificates and
# git, nothing else. CI runs this (.ci/run); run it yourself to check that a
# change still installs and passes from nothing. Needs root (mmdebstrap,
# chroot, mounts) and Debian's archive; about 4-8 minutes on 2 cores.
#
#   bash scripts/fresh_root_test.sh [COMMAND...]   # default: bash scripts/test.sh
#
# It tests what is committed: the root gets a `git clone` of this checkout's
# HEAD, so uncommitted changes are not in it. Everything runs in its own mount
# and PID namespaces (unshare), so its mounts never reach the host and every
# process it started ends with it. The root is deleted at the end unless
# RBS_KEEP_ROOT=1. Exit status: the command's; the command's last line of
# output is repeated last (for scripts/test.sh, ctest's summary line).
set -euo pipefail
export PATH=/usr/sbin:/usr/bin:/sbin:/bin:$PATH
here=$(cd "$(dirname "$0")/.." && pwd)
[ "$(id -u)" -eq 0 ] || { echo "fresh_root_test: needs root (mmdebstrap, chroot, mounts)" >&2; exit 2; }
command=("$@")
[ ${#command[@]} -gt 0 ] || command=(bash scripts/test.sh)

say() { echo "fresh_root_test: $*" >&2; }

if ! command -v mmdebstrap >/dev/null; then
  say "installing mmdebstrap"
  DEBIAN_FRONTEND=noninteractive apt-get update -q >/dev/null
  DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends mmdebstrap >/dev/null
fi

root=$(mktemp -d /var/tmp/rbs_fresh_root.XXXXXX)
log=$root.log
cleanup() {
  rm -f "$log"
  # The mounts live in the unshared namespace and are gone with it; never
  # delete through a mount that is somehow still there.
  if grep -q " $root/" /proc/self/mounts; then
    say "mounts under $root are still present; not deleting it"
  elif [ "${RBS_KEEP_ROOT:-0}" = 1 ]; then
    say "kept $root"
  else
    rm -rf --one-file-system "$root"
  fi
}
trap cleanup EXIT

# The machine's own archive entry (Debian 12's deb822 sources), or the default mirror.
sources=/etc/apt/sources.list.d/debian.sources
[ -f "$sources" ] || sources="http://deb.debian.org/debian"
start=$SECONDS
say "making a minimal Debian 12 root in $root (mmdebstrap)"
mmdebstrap --quiet --variant=minbase --include=ca-certificates,git bookworm "$root" "$sources"
# mmdebstrap leaves no /etc/hosts; ROS resolves localhost through it.
printf '127.0.0.1\tlocalhost\n::1\tlocalhost ip6-localhost ip6-loopback\n' >"$root/etc/hosts"
touch "$root/etc/resolv.conf"
git clone --quiet "$here" "$root/work/rigid_body_sim"
say "root ready in $((SECONDS - start)) s; running '${command[*]}' in it at $(git -C "$here" rev-parse --short HEAD)"

# Inside new mount and PID namespaces: mount what a system has, chroot with a
# clean environment, run the command, unmount in reverse order.
inner='
set -u
root=$1
shift
mount -t proc proc "$root/proc"
mount --bind /sys "$root/sys"
mount --bind /dev "$root/dev"
mount --bind /dev/pts "$root/dev/pts"
mount --bind /dev/shm "$root/dev/shm"
mount --bind /etc/resolv.conf "$root/etc/resolv.conf"
status=0
env -i HOME=/root TERM="${TERM:-dumb}" LANG=C.UTF-8 PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin \
  chroot "$root" bash -c "cd /work/rigid_body_sim && exec \"\$@\"" fresh_root "$@" </dev/null || status=$?
for m in etc/resolv.conf dev/shm dev/pts dev sys proc; do umount "$root/$m"; done
exit "$status"
'
set +e
unshare --mount --propagation private --pid --fork --kill-child bash -c "$inner" inner "$root" "${command[@]}" 2>&1 |
  tee "$log"
status=${PIPESTATUS[0]}
set -e
say "finished in $((SECONDS - start)) s with status $status"
grep -v '^[[:space:]]*$' "$log" | tail -n 1
exit "$status"
