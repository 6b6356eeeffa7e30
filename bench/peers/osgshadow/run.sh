#!/usr/bin/env bash
# penumbra beside OpenSceneGraph's osgShadow (Debian's libopenscenegraph-dev) on one generated
# scene: the same triangles (grid_<N>.obj / .json), camera, sun direction, map size and frame size.
# penumbra renders headless (EGL, `penumbra bench --fixed-camera`); osgShadow draws in a window
# under Xvfb, so its frames also pay for a buffer swap. Prints penumbra / OSG frame-time ratios
# for SM, soft PCF, PSSM / cascaded and LiSPSM, and leaves both programs' pictures in OUT.
# The scene does not move, so penumbra's default keeps its (non view-dependent) shadow maps
# after the first frame (RenderOptions::reuseStillCasters); the last two columns redraw every
# map every frame (`--redraw-shadow-maps`), as osgShadow does.
#   bench/peers/osgshadow/run.sh [OUT=bench-out/osg] [TRIANGLES=98000] [MAPRES=2048] [FRAMES=20]
set -euo pipefail
root="$(cd "$(dirname "$0")/../../.." && pwd)"
out="$(realpath -m "${1:-bench-out/osg}")"
triangles="${2:-98000}"
mapres="${3:-2048}"
frames="${4:-20}"
size=1280x720

need=()
for p in libopenscenegraph-dev openscenegraph xvfb xauth jq; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || need+=("$p")
done
if [ ${#need[@]} -gt 0 ]; then
  SUDO=""; [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${need[@]}" >/dev/null
fi
penumbra="$root/build/penumbra"
[ -x "$penumbra" ] || "$root/scripts/setup.sh"
cmake -S "$root/bench/peers/osgshadow" -B "$root/build/osgshadow_peer" -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$root/build/osgshadow_peer" >/dev/null
peer="$root/build/osgshadow_peer/osgshadow_peer"

# penumbra first: it writes the scene (OUT/scenes/grid_N.json and the one-file grid_N.obj).
"$penumbra" bench --grid-scene "$triangles" --techniques none,hard,pcf-poisson16,cascaded,lispsm \
  --shadow-res "$mapres" --size "$size" --frames "$frames" --warmup-seconds 2 --fixed-camera --out "$out"
"$penumbra" bench --grid-scene "$triangles" --techniques none,hard,pcf-poisson16,cascaded,lispsm \
  --shadow-res "$mapres" --size "$size" --frames "$frames" --warmup-seconds 2 --fixed-camera --no-images \
  --redraw-shadow-maps --out "$out/redraw"
obj="$out/scenes/grid_$triangles.obj"
scene="$out/scenes/grid_$triangles.json"
eye="$(jq -r '.camera.position | join(",")' "$scene")"
target="$(jq -r '.camera.target | join(",")' "$scene")"
fov="$(jq -r '.camera.fov_deg' "$scene")"
sun="$(jq -r '.lights[0].direction | join(",")' "$scene")"

declare -A pair=([none]=none [sm]=hard [ssm]=pcf-poisson16 [pssm]=cascaded [lispsm]=lispsm)
printf '%-8s %-14s %12s %12s %9s %12s %9s\n' OSG penumbra "OSG ms" "penumbra ms" ratio "redrawn ms" ratio | tee "$out/osg_ratios.txt"
for osg in none sm ssm pssm lispsm; do
  line="$(xvfb-run -a -s "-screen 0 ${size}x24" "$peer" "$obj" --technique "$osg" --mapres "$mapres" --size "$size" \
          --eye "$eye" --target "$target" --fov "$fov" --sun "$sun" --frames "$frames" --warmup 5 \
          --screenshot "$out/osg_$osg.png" 2>/dev/null | grep '^osgshadow')"
  osgMs="$(echo "$line" | awk '{print $4}')"
  ours="${pair[$osg]}"
  penMs="$(jq -r --arg t "$ours" '.cases[] | select(.technique == $t) | .frame_ms.mean' "$out/bench.json")"
  redrawMs="$(jq -r --arg t "$ours" '.cases[] | select(.technique == $t) | .frame_ms.mean' "$out/redraw/bench.json")"
  ratio="$(awk -v a="$penMs" -v b="$osgMs" 'BEGIN { printf "%.2f", a / b }')"
  redrawRatio="$(awk -v a="$redrawMs" -v b="$osgMs" 'BEGIN { printf "%.2f", a / b }')"
  printf '%-8s %-14s %12.2f %12.2f %8sx %12.2f %8sx\n' "$osg" "$ours" "$osgMs" "$penMs" "$ratio" "$redrawMs" "$redrawRatio" \
    | tee -a "$out/osg_ratios.txt"
done
echo "pictures: $out/osg_*.png (OSG) and $out/images/ (penumbra); ratios in $out/osg_ratios.txt"
