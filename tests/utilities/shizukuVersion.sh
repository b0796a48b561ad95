#!/bin/sh
# shizuku -version and --version print one line, "Shizuku <x.y.z> (commit <sha>[-dirty])"
# ("commit unknown" only for a build outside a git work tree) and exit 0; built from
# this repository, <sha> is one of its commits; -help lists -version.
#   shizukuVersion.sh SHIZUKU SOURCE_DIR
set -e
bin=$1; src=$2
format='^Shizuku [0-9]+\.[0-9]+\.[0-9]+ \(commit ([0-9a-f]{7,40}(-dirty)?|unknown)\)$'
for flag in -version --version; do
    out=$("$bin" "$flag") || { echo "$flag: exit status $?"; exit 1; }
    [ "$(printf '%s\n' "$out" | wc -l)" -eq 1 ] || { echo "$flag: more than one line:"; echo "$out"; exit 1; }
    printf '%s\n' "$out" | grep -Eq "$format" || { echo "$flag: '$out' does not match $format"; exit 1; }
done
commit=$(printf '%s\n' "$out" | sed 's/.*(commit \([^)]*\)).*/\1/; s/-dirty$//')
top=$(git -C "$src" rev-parse --show-toplevel 2>/dev/null || true)
if [ -n "$top" ] && [ "$(cd "$top" && pwd -P)" = "$(cd "$src" && pwd -P)" ]; then
    [ "$commit" != unknown ] || { echo "built from a git work tree but the commit is unknown"; exit 1; }
    git -C "$src" cat-file -e "$commit^{commit}" 2>/dev/null ||
        { echo "commit $commit is not a commit of $src"; exit 1; }
fi
"$bin" -help | grep -q -- '--version' || { echo "-help does not list -version"; exit 1; }
echo "shizuku -version: $out"
