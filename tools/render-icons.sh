#!/usr/bin/env bash
# Renders the application icon's PNG sizes from its SVG (packaging/icons/hicolor/scalable) with
# rsvg-convert (Debian's librsvg2-bin; ImageMagick's own SVG reader drops the gradients). The
# PNGs are committed, so building and packaging need no SVG renderer; run this after editing
# the SVG.
set -euo pipefail
cd "$(dirname "$0")/../packaging/icons/hicolor"
svg=scalable/apps/org.reliefeditor.Relief.svg
for size in 16 24 32 48 64 128 256 512; do
  mkdir -p "${size}x${size}/apps"
  rsvg-convert -w "$size" -h "$size" "$svg" -o "${size}x${size}/apps/org.reliefeditor.Relief.png"
done
echo "render-icons: PNGs written under packaging/icons/hicolor"
