#!/bin/sh
# Trunk post-build hook: writes the service worker's file list and build version into
# the staged sw.js (see web/sw.js). Runs in Trunk's staging directory.
set -eu
cd "${TRUNK_STAGING_DIR:?run by trunk build}"
files=$(find . -type f ! -name sw.js | sed 's#^\./##' | LC_ALL=C sort)
build=$(for f in $files; do printf '%s %s\n' "$f" "$(wc -c < "$f")"; done | sha256sum | cut -c1-16)
list="['./'"
for f in $files; do list="$list, '$f'"; done
list="$list]"
sed -e "s#__BUILD__#$build#" -e "s#__FILES__#$list#" sw.js > sw.js.tmp
mv sw.js.tmp sw.js
