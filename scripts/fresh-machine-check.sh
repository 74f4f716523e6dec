#!/usr/bin/env bash
# Runs the README's two set-up commands as a new user would: in a minimal Debian 12 root made
# with debootstrap, with this working tree and ../shared copied in, as root. Prints each
# command's result and time. Not part of the test command: it installs and builds everything
# again. Run it (as root) before calling a change to set-up, CI or dependencies done.
#   bash scripts/fresh-machine-check.sh [ROOT_DIR]   (default /var/tmp/meshquilt-fresh; reused
#   for the debootstrap step when it already holds a root, rebuilt from the tree otherwise)
set -euo pipefail
cd "$(dirname "$0")/.."
repo=$PWD
root=${1:-/var/tmp/meshquilt-fresh}
[ "$(id -u)" = 0 ] || { echo "fresh-machine-check: run as root (debootstrap and mounts need it)" >&2; exit 2; }

# The two commands, read from the README so the check follows it.
mapfile -t commands < <(awk '/^```/ { if (inside) exit; inside = 1; next } inside && NF' README.md)
[ "${#commands[@]}" = 2 ] || { echo "fresh-machine-check: README.md: expected two commands in its first block" >&2; exit 2; }

command -v debootstrap >/dev/null || { apt-get update -qq && apt-get install -y -qq debootstrap >/dev/null; }

unmount_all() {
  for m in dev sys proc; do
    mountpoint -q "$root/$m" && umount -R "$root/$m" 2>/dev/null || umount -lR "$root/$m" 2>/dev/null || true
  done
}
trap unmount_all EXIT

if [ ! -x "$root/usr/bin/apt-get" ]; then
  start=$(date +%s)
  debootstrap --variant=minbase bookworm "$root" >/tmp/fresh-machine-debootstrap.log 2>&1 ||
    { echo "fresh-machine-check: debootstrap failed (see /tmp/fresh-machine-debootstrap.log)" >&2; exit 1; }
  echo "minimal Debian 12 root: $root ($(( $(date +%s) - start )) s)"
fi
cp /etc/resolv.conf "$root/etc/resolv.conf" 2>/dev/null || true
[ -f /etc/apt/sources.list ] && cp /etc/apt/sources.list "$root/etc/apt/sources.list"
for f in /etc/apt/sources.list.d/*.sources /etc/apt/sources.list.d/*.list; do
  [ -f "$f" ] && mkdir -p "$root/etc/apt/sources.list.d" && cp "$f" "$root/etc/apt/sources.list.d/"
done

# A fresh copy of the tree (tracked and untracked files, no build outputs) and of ../shared.
rm -rf "$root/work"
mkdir -p "$root/work/main"
git ls-files -co --exclude-standard -z | tar --null -T - -cf - | tar -xf - -C "$root/work/main"
[ -d ../shared ] && cp -r ../shared "$root/work/shared"

for m in proc sys dev; do mount --rbind "/$m" "$root/$m"; mount --make-rslave "$root/$m"; done

status=0
for c in "${commands[@]}"; do
  start=$(date +%s)
  if chroot "$root" /usr/bin/env -i HOME=/root PATH=/usr/sbin:/usr/bin:/sbin:/bin CI=true \
      bash -c "cd /work/main && $c" >"/tmp/fresh-machine-$(echo "$c" | tr -c 'a-z0-9' '_').log" 2>&1; then
    result=passed
  else
    result=failed; status=1
  fi
  printf '%-28s %s in %d s (log: /tmp/fresh-machine-%s.log)\n' "$c" "$result" $(( $(date +%s) - start )) \
    "$(echo "$c" | tr -c 'a-z0-9' '_')"
done
exit $status
