#!/bin/sh
# shizukuParticles writes 0/ for the dam-break tutorial: 4000 fluid particles
# (80 x 50 at d0 = 1 cm) and 2418 wall particles (3 layers: 3 x 206 bottom + 2 x 3 x 300 sides),
# and nothing else; a case with a later time directory is refused unless -overwrite;
# a misspelt keyword exits 1 naming the file.
set -e
bin=$1; src=$2
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
cp -r "$src/tutorials/damBreak" "$tmp/case"
"$bin" -case "$tmp/case" > "$tmp/log"
grep -q "4000 fluid and 2418 wall particles" "$tmp/log" || { cat "$tmp/log"; exit 1; }
test -f "$tmp/case/0/particles.vtp" && test -f "$tmp/case/0/uniform/time"
test "$(ls "$tmp/case" | grep -c '^[0-9]')" -eq 1
# A finished case (a later time directory exists): refused, naming it, 0/ untouched;
# -overwrite replaces 0/ and leaves the later one.
cp -r "$tmp/case/0" "$tmp/case/0.5"
touch -d 2000-01-01 "$tmp/case/0/particles.vtp"
if "$bin" -case "$tmp/case" > "$tmp/log3" 2>&1; then echo "finished case: expected failure"; exit 1; fi
grep -q "time directories 0.5).*-overwrite" "$tmp/log3" || { cat "$tmp/log3"; exit 1; }
test "$(stat -c %Y "$tmp/case/0/particles.vtp")" = "$(date -d 2000-01-01 +%s)"
"$bin" -case "$tmp/case" -overwrite > "$tmp/log4" || { cat "$tmp/log4"; exit 1; }
test "$(stat -c %Y "$tmp/case/0/particles.vtp")" != "$(date -d 2000-01-01 +%s)" && test -f "$tmp/case/0.5/particles.vtp"
rm -rf "$tmp/case/0.5"
sed -i 's/^spacing/spacng/' "$tmp/case/system/particlesDict"
rm -rf "$tmp/case/0"
if "$bin" -case "$tmp/case" > "$tmp/log2" 2>&1; then echo "expected failure"; exit 1; fi
grep -q "particlesDict" "$tmp/log2" && grep -q "spacing" "$tmp/log2" || { cat "$tmp/log2"; exit 1; }
test ! -e "$tmp/case/0"
echo "shizukuParticles: 1 passed, 0 failed"
