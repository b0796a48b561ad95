#!/bin/sh
# `cpack -G DEB` in the build folder makes the package shizuku: /usr/bin/shizuku and
# the other programs, the tutorials under /usr/share/shizuku/tutorials, etc/bashrc;
# a maintainer, a description, and Depends naming only packages Debian knows
# (installed here, or available to apt); the packaged shizuku -version runs.
#   debPackage.sh BUILD
set -e
build=$(cd "$1" && pwd)
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
(cd "$build" && cpack -G DEB -B "$tmp" > "$tmp/cpack.log" 2>&1) || { cat "$tmp/cpack.log"; fail "cpack -G DEB"; }
deb=$(ls "$tmp"/shizuku_*.deb 2>/dev/null | head -1)
[ -n "$deb" ] || { cat "$tmp/cpack.log"; fail "no shizuku_*.deb written"; }
dpkg-deb -c "$deb" | awk '{print $NF}' > "$tmp/contents"
for f in ./usr/bin/shizuku ./usr/bin/shizukuParticles ./usr/bin/shizukuPostProcess ./usr/bin/shizukuPlot \
         ./usr/bin/shizukuCompare ./usr/bin/shizukuPvsm ./usr/share/shizuku/etc/bashrc ./usr/share/shizuku/etc/tutorialFunctions \
         ./usr/share/shizuku/tutorials/damBreak/Allrun ./usr/share/shizuku/tutorials/damBreak/system/controlDict \
         ./usr/share/doc/shizuku/README.md; do
    grep -qx "$f" "$tmp/contents" || fail "$f not in $(basename "$deb")"
done
dpkg-deb -x "$deb" "$tmp/root"
"$tmp/root/usr/bin/shizuku" -version > /dev/null || fail "the packaged shizuku -version"
[ "$(dpkg-deb -f "$deb" Package)" = shizuku ] || fail "package name"
[ -n "$(dpkg-deb -f "$deb" Maintainer)" ] || fail "no maintainer"
[ -n "$(dpkg-deb -f "$deb" Description)" ] || fail "no description"
depends=$(dpkg-deb -f "$deb" Depends)
for p in $(printf '%s\n' "$depends" | tr ',' '\n' | sed 's/(.*)//; s/|.*//' | tr -d ' '); do
    dpkg-query -W "$p" > /dev/null 2>&1 || apt-cache show "$p" > /dev/null 2>&1 ||
        fail "Depends names $p, which Debian does not know"
done
echo "$(basename "$deb"): $(wc -l < "$tmp/contents") entries; Depends: $depends"
