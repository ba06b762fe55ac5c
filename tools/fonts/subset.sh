#!/bin/sh
# `make fonts`: the app's monospace font, Hack (egui's default, MIT and Bitstream Vera
# licences: crates/marbling-app/fonts/Hack-LICENSE.txt), cut to the characters a
# marbling playground shows — Latin-1, Greek, punctuation, arrows, mathematical
# operators and geometric shapes — for the web module's
# size (docs/BENCHMARKS.md, "The first visit"). Ubuntu Light, the proportional font, is
# used whole (its licence asks a cut copy to be renamed). src/fonts.rs loads both; its
# test checks that every character of the app's text has a glyph.
set -eu
cd "$(dirname "$0")/../.."
python3 -c 'import fontTools' 2>/dev/null || python3 -m pip install --quiet 'fonttools==4.61.0'
src=$(cargo metadata --format-version 1 | python3 -c '
import json, os, sys
for p in json.load(sys.stdin)["packages"]:
    if p["name"] == "epaint_default_fonts":
        print(os.path.join(os.path.dirname(p["manifest_path"]), "fonts"))
        break')
out=crates/marbling-app/fonts
python3 -m fontTools.subset "$src/Hack-Regular.ttf" \
  --unicodes='U+0020-007E,U+00A0-00FF,U+0131,U+0152-0153,U+0160-0161,U+0178,U+017D-017E,U+0192,U+02C6-02DC,U+0370-03FF,U+2000-206F,U+2070-209F,U+20AC,U+2100-214F,U+2190-21FF,U+2200-22FF,U+25A0-25FF,U+FFFD' \
  --layout-features='*' --no-hinting --desubroutinize \
  --output-file="$out/Hack-Regular-subset.ttf"
cp "$src/Hack-Regular.txt" "$out/Hack-LICENSE.txt"
ls -l "$out/Hack-Regular-subset.ttf"
