#!/usr/bin/env bash
# Checks the Debian packages of this machine's architecture (cmake --workflow --preset deb):
# lintian, the control data, then (as root) a real install on this machine: the service user, the
# installed mrd-controller checking the installed /etc/mrd/mrd.toml, the tools, an upgrade that
# keeps a local edit of the conffile, and a purge. Whatever it installed is purged on exit.
# usage: scripts/test-package.sh [DIR]   (DIR holds the .deb files; default build/release/packages)
set -euo pipefail
cd "$(dirname "$0")/.."
dir=${1:-build/release/packages}
arch=$(dpkg --print-architecture)
controller_deb=$(echo "$dir"/mrd-controller_*_"$arch".deb)
tools_deb=$(echo "$dir"/mrd-tools_*_"$arch".deb)
config=/etc/mrd/mrd.toml
passed=0
failed=0

check() {  # check NAME COMMAND...: runs the command, counts and reports its verdict
  local name=$1
  shift
  if "$@"; then
    passed=$((passed + 1))
    echo "ok:   $name"
  else
    failed=$((failed + 1))
    echo "FAIL: $name"
  fi
}
finish() {
  echo "package: $passed passed, $failed failed"
  ((failed == 0))
}

for deb in "$controller_deb" "$tools_deb"; do
  [[ -f $deb ]] || { echo "test-package: no $deb (build it: cmake --workflow --preset deb)" >&2; exit 1; }
done
work=$(mktemp -d)
installed=()
user_existed=$(getent passwd mrd >/dev/null && echo yes || echo no)
cleanup() {
  if ((${#installed[@]})); then dpkg --purge "${installed[@]}" >/dev/null || true; fi
  # The package keeps its service user on purge (postrm); the test removes the one it made.
  if [[ $user_existed == no ]] && getent passwd mrd >/dev/null; then deluser --system --quiet mrd 2>/dev/null || true; fi
  if [[ $user_existed == no ]] && getent group mrd >/dev/null; then delgroup --system --quiet mrd 2>/dev/null || true; fi
  rm -rf "$work"
}
trap cleanup EXIT

# Lint at every level (-I --pedantic): any tag fails, but for the accepted ones
# (packaging/deb/lintian-accepted) and those the packages override with their reason
# (packaging/deb/*.lintian-overrides); both are explained in docs/DEPLOY.md, "Lintian".
check "lintian -I --pedantic: no tag beyond packaging/deb/lintian-accepted and the packages' overrides" \
  lintian -I --pedantic --fail-on error,warning,info,pedantic --suppress-tags-from-file packaging/deb/lintian-accepted \
  "$controller_deb" "$tools_deb"
# Hardening (-D_FORTIFY_SOURCE=2, stack protector, PIE, -z relro -z now) by devscripts'
# hardening-check where it is installed; lintian's hardening-* tags above check the same.
if command -v hardening-check >/dev/null; then
  dpkg-deb -x "$controller_deb" "$work/files"
  dpkg-deb -x "$tools_deb" "$work/files"
  check "hardening-check: every program fortified, stack-protected, PIE, relro and bind-now" \
    hardening-check --quiet --nocfprotection "$work"/files/usr/bin/mrd-*
fi

dpkg-deb -e "$controller_deb" "$work/control"
check "conffiles lists $config" grep -qx "$config" "$work/control/conffiles"
check "Depends computed by dpkg-shlibdeps (libmodbus)" \
  bash -c "dpkg-deb -f '$controller_deb' Depends | grep -q 'libmodbus5'"
check "unit in /lib/systemd/system" bash -c "dpkg-deb -c '$controller_deb' | grep -q ' ./lib/systemd/system/mrd-controller.service$'"
check "udev rule for /dev/cpu_dma_latency" bash -c "dpkg-deb -c '$controller_deb' | grep -q ' ./lib/udev/rules.d/60-mrd-cpu-dma-latency.rules$'"
check "networkd file for can0" bash -c "dpkg-deb -c '$controller_deb' | grep -q ' ./lib/systemd/network/80-mrd-can0.network$'"
check "example configs" bash -c "dpkg-deb -c '$controller_deb' | grep -q ' ./usr/share/doc/mrd-controller/examples/can-box.toml$'"
check "the controller's docs in /usr/share/doc/mrd-controller, none in /usr/share/doc/mrd" bash -c \
  "dpkg-deb -c '$controller_deb' | grep -q ' ./usr/share/doc/mrd-controller/FIRMWARE.md$' && ! dpkg-deb -c '$controller_deb' | grep -q ' ./usr/share/doc/mrd/'"
check "unit's Documentation= names the man page" bash -c \
  "dpkg-deb --fsys-tarfile '$controller_deb' | tar -xO ./lib/systemd/system/mrd-controller.service | grep -qx 'Documentation=man:mrd-controller(1)'"
# Every program of a package has its man page beside it (help2man, at build time), with EXIT
# STATUS, FILES, EXAMPLES and SEE ALSO (tests/cli/check_man_page.sh; the options and exit codes
# against the installed programs below, as root).
for deb in "$controller_deb" "$tools_deb"; do
  dpkg-deb -x "$deb" "$work/pages"
  for program in $(dpkg-deb -c "$deb" | sed -n 's|.* \./usr/bin/\(mrd-[a-z0-9-]*\)$|\1|p'); do
    check "man page of $program" bash -c "dpkg-deb -c '$deb' | grep -q ' ./usr/share/man/man1/$program.1.gz$'"
    check "man page of $program: EXIT STATUS, FILES, EXAMPLES, SEE ALSO" \
      bash tests/cli/check_man_page.sh "$work/pages/usr/share/man/man1/$program.1.gz" "$program"
  done
done
for program in mrd-plant mrd-hil-report mrd-identify mrd-residual; do
  check "mrd-tools ships $program" bash -c "dpkg-deb -c '$tools_deb' | grep -q ' ./usr/bin/$program$'"
done
check "mrd-tools ships the docs" bash -c "dpkg-deb -c '$tools_deb' | grep -q ' ./usr/share/doc/mrd-tools/docs/DEPLOY.md$'"

if [[ $(id -u) -ne 0 ]]; then
  echo "test-package: the install checks need root; only the package files were checked"
  finish
  exit
fi
if dpkg-query -W -f='${Status}' mrd-controller mrd-tools 2>/dev/null | grep -q installed; then
  echo "test-package: mrd-controller or mrd-tools is installed here already; not touching it" >&2
  exit 1
fi

installed=(mrd-controller mrd-tools)
check "dpkg -i both packages" dpkg -i "$controller_deb" "$tools_deb"
check "service user mrd, no login" bash -c "getent passwd mrd | grep -q ':/nonexistent:/usr/sbin/nologin$'"
check "installed mrd-controller accepts the installed config" /usr/bin/mrd-controller --check-config "$config"
check "mrd-controller runs the simulated rig for 0.2 s" /usr/bin/mrd-controller --duration 0.2
check "mrd-replay starts" /usr/bin/mrd-replay --help
check "every installed program answers --version" bash -c \
  "for p in \$(dpkg -L mrd-controller mrd-tools | grep '^/usr/bin/mrd-'); do \$p --version | grep -q \"^\${p##*/} \" || exit 1; done"
check "man mrd-replay reads" bash -c "man -P cat mrd-replay 2>/dev/null | grep -q 'Exit status' || zcat /usr/share/man/man1/mrd-replay.1.gz | grep -q 'Exit status'"
check "every installed man page lists its program's options (mrd-identify: each subcommand's) and exit codes" bash -c \
  "for p in \$(dpkg -L mrd-controller mrd-tools | grep '^/usr/bin/mrd-'); do bash tests/cli/check_man_page.sh /usr/share/man/man1/\${p##*/}.1.gz \${p##*/} \$p >/dev/null || exit 1; done"
check "the installed example configs are accepted" bash -c \
  "for f in /usr/share/doc/mrd-controller/examples/*.toml; do /usr/bin/mrd-controller --check-config \$f || exit 1; done"
check "the installed hardware-in-the-loop examples are accepted (mrd-plant's man page runs them)" bash -c \
  "cd /usr/share/doc/mrd-tools/examples && /usr/bin/mrd-plant --check-config plant.toml && /usr/bin/mrd-plant --check-config plant-force.toml && /usr/bin/mrd-controller --check-config hil-modbus.toml && /usr/bin/mrd-controller --check-config hil-force-modbus.toml"
check "unit is Type=notify with a watchdog" bash -c \
  "grep -qx 'Type=notify' /lib/systemd/system/mrd-controller.service && grep -q '^WatchdogSec=' /lib/systemd/system/mrd-controller.service"
check "unit names the installed paths" \
  grep -qx "ExecStart=/usr/bin/mrd-controller --config $config" /lib/systemd/system/mrd-controller.service
# systemd-analyze verify also runs man for each Documentation=man: entry.
if command -v systemd-analyze >/dev/null; then
  check "systemd-analyze verify accepts the installed unit (man:mrd-controller(1) found)" \
    systemd-analyze verify /lib/systemd/system/mrd-controller.service
fi

# A local edit survives a reinstall and an upgrade whose default config did not change, silently.
echo "# local edit (test-package.sh)" >>"$config"
check "reinstall keeps the local edit" bash -c "dpkg -i '$controller_deb' >/dev/null && grep -q 'local edit' $config"
dpkg-deb -R "$controller_deb" "$work/next"
version=$(dpkg-deb -f "$controller_deb" Version)
sed -i "s/^Version: .*/Version: $version+next/" "$work/next/DEBIAN/control"
dpkg-deb -b "$work/next" "$work/next.deb" >/dev/null
check "upgrade keeps the local edit" bash -c "dpkg -i '$work/next.deb' >/dev/null && grep -q 'local edit' $config"
# An upgrade whose default config changed too: dpkg would ask; --force-confold keeps ours and
# leaves the package's version beside it.
echo "# changed upstream" >>"$work/next/etc/mrd/mrd.toml"
sed -i "s/^Version: .*/Version: $version+next2/" "$work/next/DEBIAN/control"
dpkg-deb -b "$work/next" "$work/next2.deb" >/dev/null
check "upgrade with a changed default keeps the edit (confold)" \
  bash -c "dpkg -i --force-confold '$work/next2.deb' </dev/null >/dev/null && grep -q 'local edit' $config && test -f $config.dpkg-dist"
check "still a valid config" /usr/bin/mrd-controller --check-config "$config"

check "purge" dpkg --purge mrd-controller mrd-tools
installed=()
check "purge removed the binary and /etc/mrd" bash -c "! test -e /usr/bin/mrd-controller && ! test -e /etc/mrd"
check "purge kept the service user" getent passwd mrd
finish
