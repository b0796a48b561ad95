#!/bin/sh
# The programs run from an install and from a source tree the way a user runs them:
#  1. `cmake --install BUILD --prefix P` into a temporary P puts the programs and the
#     python utilities in P/bin, the tutorials (no run outputs) and etc/bashrc,
#     etc/tutorialFunctions in P/share/shizuku, README.md and docs/ in P/share/doc/shizuku;
#  2. a copy of an installed tutorial, in a shell whose only Shizuku setting is
#     P/share/shizuku/etc/bashrc: shizuku -version, shizuku -case . -dryRun (also through
#     tutorialFunctions' runApplication) and ./Allclean exit 0 with P's programs;
#  3. an installed tutorial run in place, nothing sourced: tutorialFunctions finds P/bin;
#  4. a copy of a repository tutorial with the repository's etc/bashrc sourced: the
#     build's shizuku -case . -dryRun exits 0.
#   installedTree.sh BUILD SOURCE_DIR
set -e
build=$(cd "$1" && pwd); src=$(cd "$2" && pwd)
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
P=$tmp/prefix
fail() { echo "FAIL: $*"; exit 1; }

cmake --install "$build" --prefix "$P" > "$tmp/install.log" || { cat "$tmp/install.log"; fail "cmake --install"; }
for f in bin/shizuku bin/shizukuParticles bin/shizukuPostProcess bin/shizukuPlot bin/shizukuCompare bin/shizukuPvsm; do
    [ -x "$P/$f" ] || fail "$f not installed (or not executable)"
done
for f in share/shizuku/etc/bashrc share/shizuku/etc/tutorialFunctions share/doc/shizuku/README.md \
         share/doc/shizuku/docs/solver.md; do
    [ -f "$P/$f" ] || fail "$f not installed"
done
for t in "$src"/tutorials/*/; do
    name=$(basename "$t")
    [ -x "$P/share/shizuku/tutorials/$name/Allrun" ] || fail "tutorial $name not installed"
    [ -d "$P/share/shizuku/tutorials/$name/system" ] || fail "tutorial $name: no system/"
done
outputs=$(find "$P/share/shizuku/tutorials" \( -name 'log.*' -o -name postProcessing -o -name plots \
          -o -name particles.pvd -o -name '[0-9]*' \) | head -3)
[ -z "$outputs" ] || fail "run outputs installed: $outputs"

# 2. A user's copy of an installed tutorial, environment from the install only.
env -i HOME="$tmp" PATH=/usr/bin:/bin P="$P" tmp="$tmp" bash -c '
    set -e
    . "$P/share/shizuku/etc/bashrc"
    [ "$SHIZUKU_DIR" = "$P/share/shizuku" ] || { echo "SHIZUKU_DIR=$SHIZUKU_DIR"; exit 1; }
    cp -r "$SHIZUKU_DIR/tutorials/hydrostaticTank" "$tmp/myCase"
    cd "$tmp/myCase"
    [ "$(command -v shizuku)" = "$P/bin/shizuku" ] || { echo "shizuku is $(command -v shizuku)"; exit 1; }
    shizuku -version
    shizuku -case . -dryRun > log.dryRun 2>&1 || { cat log.dryRun; exit 1; }
    grep -q "Dry run: the case is valid" log.dryRun
    . "$SHIZUKU_DIR/etc/tutorialFunctions"
    runApplication shizuku -case . -dryRun
    ./Allclean
    [ ! -e log.shizuku ] && [ ! -e log.dryRun ] || { echo "Allclean left the logs"; exit 1; }
' > "$tmp/copy.log" 2>&1 || { cat "$tmp/copy.log"; fail "installed tutorial copy with P/share/shizuku/etc/bashrc"; }

# 3. An installed tutorial in place, nothing sourced.
env -i HOME="$tmp" PATH=/usr/bin:/bin P="$P" sh -c '
    set -e
    cd "$P/share/shizuku/tutorials/hydrostaticTank"
    . ../../etc/tutorialFunctions
    [ "$(command -v shizuku)" = "$P/bin/shizuku" ] || { echo "shizuku is $(command -v shizuku)"; exit 1; }
' > "$tmp/inplace.log" 2>&1 || { cat "$tmp/inplace.log"; fail "installed tutorial in place without the environment"; }

# 4. A copy of a repository tutorial with the repository's environment.
env -i HOME="$tmp" PATH=/usr/bin:/bin SHIZUKU_BUILD="$build" src="$src" tmp="$tmp" bash -c '
    set -e
    . "$src/etc/bashrc"
    [ "$SHIZUKU_DIR" = "$src" ] || { echo "SHIZUKU_DIR=$SHIZUKU_DIR"; exit 1; }
    cp -r "$src/tutorials/hydrostaticTank" "$tmp/repoCase"
    cd "$tmp/repoCase"
    [ "$(command -v shizuku)" = "$SHIZUKU_BUILD/solver/shizuku" ] || { echo "shizuku is $(command -v shizuku)"; exit 1; }
    command -v shizukuPlot > /dev/null
    shizuku -case . -dryRun > log.dryRun 2>&1 || { cat log.dryRun; exit 1; }
' > "$tmp/repo.log" 2>&1 || { cat "$tmp/repo.log"; fail "repository tutorial copy with etc/bashrc"; }
echo "install: 4 passed, 0 failed"
