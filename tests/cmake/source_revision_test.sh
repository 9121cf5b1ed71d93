#!/usr/bin/env bash
# cmake/source_revision.cmake on scratch repositories: the short revision of a clean checkout,
# "-dirty" once a tracked file changes (an untracked one does not count), "unknown" outside
# git, and the generated source left untouched while the revision stays the same.
# usage: source_revision_test.sh CMAKE SCRIPT
set -euo pipefail
cmake_bin=$1
script=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
revision_in() { sed -n 's/.*return "\(.*\)";.*/\1/p' "$1"; }
generate() { "$cmake_bin" -DSOURCE_DIR="$1" -DOUTPUT="$2" -P "$script"; }

mkdir "$work/repo"
git -C "$work/repo" init -q
echo one > "$work/repo/tracked.txt"
git -C "$work/repo" add tracked.txt
git -C "$work/repo" -c user.name=t -c user.email=t@t commit -q -m one
expected=$(git -C "$work/repo" rev-parse --short HEAD)

generate "$work/repo" "$work/out.cc"
[ "$(revision_in "$work/out.cc")" = "$expected" ] || fail "clean: $(revision_in "$work/out.cc")"

touch -d '2000-01-01' "$work/out.cc"
echo untracked > "$work/repo/new.txt"
generate "$work/repo" "$work/out.cc"
[ "$(revision_in "$work/out.cc")" = "$expected" ] || fail "untracked: $(revision_in "$work/out.cc")"
[ "$(stat -c %Y "$work/out.cc")" = "$(date -d '2000-01-01' +%s)" ] ||
  fail "rewritten although the revision did not change"

echo two >> "$work/repo/tracked.txt"
generate "$work/repo" "$work/out.cc"
[ "$(revision_in "$work/out.cc")" = "$expected-dirty" ] || fail "dirty: $(revision_in "$work/out.cc")"

mkdir "$work/plain"
generate "$work/plain" "$work/plain.cc"
[ "$(revision_in "$work/plain.cc")" = "unknown" ] || fail "no git: $(revision_in "$work/plain.cc")"
echo "source revision: clean, untracked, dirty and no-git cases pass"
