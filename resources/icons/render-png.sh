#!/usr/bin/env bash
# Renders the PNG sizes of the application icon from its SVG (the only source). Run after
# editing org.stepdeck.StepDeck.svg and commit the result; the build itself needs no SVG
# renderer. Needs rsvg-convert (Debian package librsvg2-bin).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")"
command -v rsvg-convert >/dev/null || { echo "rsvg-convert missing: apt install librsvg2-bin" >&2; exit 1; }
for size in 16 24 32 48 64 128 256; do
    dir="hicolor/${size}x${size}/apps"
    mkdir -p "$dir"
    rsvg-convert -w "$size" -h "$size" org.stepdeck.StepDeck.svg -o "$dir/org.stepdeck.StepDeck.png"
done
