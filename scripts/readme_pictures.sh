#!/usr/bin/env bash
# Regenerates the README's pictures (docs/pictures/) from penumbra's own output, so they show
# what the current build draws:
#   techniques.jpg  every technique on the default scene (scene time 1 s), labelled
#   coloured.jpg    seed 000's coloured glass: deterministic tint (hard) | CSSM (cssm2), split
#   heat_maps.jpg   compare's |technique - ray-traced reference| on the default scene
#   street.jpg      seed 002's street, one technique per region, at three points of its walk
# Needs ImageMagick's montage (installed here when missing). About 5 minutes on llvmpipe.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh >/dev/null
if ! command -v montage >/dev/null; then
  SUDO=""; [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  $SUDO apt-get install -y -q imagemagick >/dev/null
fi
p=build/penumbra
work=build/pictures
rm -rf "$work"; mkdir -p "$work/techniques" "$work/heat" "$work/street" docs/pictures

for t in $($p techniques | awk '{print $1}'); do
  $p render --technique "$t" --size 256x144 --time 1 --frames 1 --out "$work/r-$t" >/dev/null
  cp "$work/r-$t/frame_0000.png" "$work/techniques/$t.png"
done
montage -label '%t' "$work"/techniques/*.png -tile 6x -geometry +3+3 -pointsize 13 -quality 85 docs/pictures/techniques.jpg

$p render scenes/glass.json --technique hard --split cssm2 --size 640x360 --frames 1 --out "$work/glass" >/dev/null
montage -label 'hard (deterministic tint)  |  cssm2 (Colored Stochastic Shadow Maps)' "$work/glass/frame_0000.png" \
  -geometry +0+0 -pointsize 14 -quality 88 docs/pictures/coloured.jpg

$p compare --techniques hard,pcf-poisson16,pcss,vsm,cascaded,cssm2 --size 320x180 --samples 16 --timed-frames 1 \
  --out "$work/compare" >/dev/null
for t in hard pcf-poisson16 pcss vsm cascaded cssm2; do cp "$work/compare/${t}_heat.png" "$work/heat/$t.png"; done
montage -label '%t' "$work"/heat/*.png -tile 3x -geometry +3+3 -pointsize 13 -quality 85 docs/pictures/heat_maps.jpg

# The walk along the street (2 m/s from x = -3): in region 1 (256 texels), 6 (soft PCF), 7 (LiSPSM).
for stop in "2 1 region 1, shadow map 256" "34 6 region 6, soft PCF" "36.5 7 region 7, LiSPSM"; do
  read -r time n text <<<"$stop"
  $p render scenes/street.json --size 427x240 --time "$time" --frames 1 --out "$work/s$n" >/dev/null
  cp "$work/s$n/frame_0000.png" "$work/street/$n.png"
  montage -label "$text" "$work/street/$n.png" -geometry +0+0 -pointsize 13 "$work/street/$n.png"
done
montage "$work"/street/1.png "$work"/street/6.png "$work"/street/7.png -tile 3x -geometry +3+3 -quality 85 docs/pictures/street.jpg
ls -la docs/pictures
