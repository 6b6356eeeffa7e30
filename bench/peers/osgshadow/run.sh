#!/usr/bin/env bash
# penumbra beside OpenSceneGraph's osgShadow (Debian's libopenscenegraph-dev) on one generated
# scene: the same triangles (grid_<N>.obj / .json), camera, sun direction, map size and frame size.
# penumbra renders headless (EGL, `penumbra bench --fixed-camera`); osgShadow draws in a window
# under Xvfb, so its frames also pay for a buffer swap. Prints penumbra / OSG frame-time ratios
# for SM, soft PCF, PSSM / cascaded and LiSPSM, and leaves both programs' pictures in OUT.
# The scene does not move, so penumbra's default keeps its shadow maps after the first frame
# (RenderOptions::reuseStillCasters); the last columns redraw every map every frame
# (`--redraw-shadow-maps`), as osgShadow does.
#
# This machine runs at two speed levels about 25 % apart and switches between them within a
# second (README, "Benchmarks"), so one measurement of each side can put a ratio off by a third.
# The script therefore measures ROUNDS rounds, alternating which side goes first, takes each
# round's ratio and prints their median with the interval between two order statistics that holds
# the true median with at least 95 % probability (the same rule as `bench --rounds`,
# bench::medianInterval in src/bench/Statistics.cpp; none below 6 rounds).
#   bench/peers/osgshadow/run.sh [OUT=bench-out/osg] [TRIANGLES=98000] [MAPRES=2048] [FRAMES=20] [ROUNDS=6]
set -euo pipefail
root="$(cd "$(dirname "$0")/../../.." && pwd)"
out="$(realpath -m "${1:-bench-out/osg}")"
triangles="${2:-98000}"
mapres="${3:-2048}"
frames="${4:-20}"
rounds="${5:-6}"
size=1280x720
techniques=(none sm ssm pssm lispsm)
declare -A pair=([none]=none [sm]=hard [ssm]=pcf-poisson16 [pssm]=cascaded [lispsm]=lispsm)

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

ourTechniques="$(for t in "${techniques[@]}"; do printf '%s,' "${pair[$t]}"; done)"
# penumbra's side of one round: kept maps into OUT/round_R, redrawn maps into OUT/round_R/redraw.
# Round 1 also writes the scene (OUT/round_1/scenes/grid_N.json and .obj) and the pictures.
runPenumbra() {
  local r="$1" images=(--no-images)
  [ "$r" -eq 1 ] && images=()
  "$penumbra" bench --grid-scene "$triangles" --techniques "${ourTechniques%,}" --shadow-res "$mapres" \
    --size "$size" --frames "$frames" --warmup-seconds 2 --fixed-camera "${images[@]}" --out "$out/round_$r" >/dev/null
  "$penumbra" bench --grid-scene "$triangles" --techniques "${ourTechniques%,}" --shadow-res "$mapres" \
    --size "$size" --frames "$frames" --warmup-seconds 2 --fixed-camera --no-images --redraw-shadow-maps \
    --out "$out/round_$r/redraw" >/dev/null
}
# OSG's side of one round: one process per technique, each line "round technique ms" into osg_ms.txt.
runOsg() {
  local r="$1" scene="$out/round_1/scenes/grid_$triangles.json" shot=()
  local eye target fov sun line
  eye="$(jq -r '.camera.position | join(",")' "$scene")"
  target="$(jq -r '.camera.target | join(",")' "$scene")"
  fov="$(jq -r '.camera.fov_deg' "$scene")"
  sun="$(jq -r '.lights[0].direction | join(",")' "$scene")"
  for osg in "${techniques[@]}"; do
    shot=(); [ "$r" -eq 1 ] && shot=(--screenshot "$out/osg_$osg.png")
    line="$(xvfb-run -a -s "-screen 0 ${size}x24" "$peer" "$out/round_1/scenes/grid_$triangles.obj" --technique "$osg" \
            --mapres "$mapres" --size "$size" --eye "$eye" --target "$target" --fov "$fov" --sun "$sun" \
            --frames "$frames" --warmup 5 "${shot[@]}" 2>/dev/null | grep '^osgshadow')" \
      || { echo "run.sh: osgshadow_peer printed no timing for $osg (round $r)" >&2; exit 1; }
    echo "$r $osg $(echo "$line" | awk '{print $4}')" >> "$out/osg_ms.txt"
  done
}

mkdir -p "$out"
rm -f "$out/osg_ms.txt"
for ((r = 1; r <= rounds; ++r)); do
  echo "round $r of $rounds"
  if (( r % 2 )); then runPenumbra "$r"; runOsg "$r"; else runOsg "$r"; runPenumbra "$r"; fi
done

# Every sample into osg_rounds.csv: round, technique pair, OSG ms, penumbra ms (kept / redrawn maps).
echo "round,osg,penumbra,osg_ms,penumbra_ms,penumbra_redrawn_ms" > "$out/osg_rounds.csv"
for ((r = 1; r <= rounds; ++r)); do
  for osg in "${techniques[@]}"; do
    ours="${pair[$osg]}"
    osgMs="$(awk -v r="$r" -v t="$osg" '$1 == r && $2 == t {print $3}' "$out/osg_ms.txt")"
    penMs="$(jq -r --arg t "$ours" '.cases[] | select(.technique == $t) | .frame_ms.mean' "$out/round_$r/bench.json")"
    redrawMs="$(jq -r --arg t "$ours" '.cases[] | select(.technique == $t) | .frame_ms.mean' "$out/round_$r/redraw/bench.json")"
    echo "$r,$osg,$ours,$osgMs,$penMs,$redrawMs" >> "$out/osg_rounds.csv"
  done
done

# Median and 95 % interval of the per-round values in column COLUMN ("ms" columns as they are,
# "ratio" columns as penumbra ÷ OSG) for one technique: order statistics x(k), x(n+1-k) with the
# largest k for which 1 - 2·P(Binomial(n, ½) ≤ k - 1) stays ≥ 0.95.
summary() {
  awk -F, -v t="$1" -v what="$2" '
    $2 == t {
      if (what == "osg") x = $4; else if (what == "pen") x = $5; else if (what == "redraw") x = $6
      else if (what == "ratio") x = $5 / $4; else x = $6 / $4
      v[++n] = x
    }
    END {
      for (i = 2; i <= n; ++i) for (j = i; j > 1 && v[j - 1] > v[j]; --j) { x = v[j]; v[j] = v[j - 1]; v[j - 1] = x }
      median = (n % 2) ? v[(n + 1) / 2] : (v[n / 2] + v[n / 2 + 1]) / 2
      below = 0; term = 0.5 ^ n; interval = ""
      for (k = 1; 2 * k <= n + 1; ++k) {
        below += term; term *= (n - (k - 1)) / k
        if (1 - 2 * below < 0.95) break
        interval = sprintf(" (%.2f-%.2f)", v[k], v[n + 1 - k])
      }
      if (what ~ /ratio/) printf "%.2f%s", median, interval; else printf "%.2f", median
    }' "$out/osg_rounds.csv"
}
{
  echo "medians of $rounds rounds; ratios with the interval that holds their median at >= 95 % (none below 6 rounds)"
  printf '%-8s %-14s %9s %12s %-18s %11s %-18s\n' OSG penumbra "OSG ms" "penumbra ms" "ratio" "redrawn ms" "ratio"
  for osg in "${techniques[@]}"; do
    printf '%-8s %-14s %9s %12s %-18s %11s %-18s\n' "$osg" "${pair[$osg]}" "$(summary "$osg" osg)" "$(summary "$osg" pen)" \
      "$(summary "$osg" ratio)" "$(summary "$osg" redraw)" "$(summary "$osg" redraw_ratio)"
  done
} | tee "$out/osg_ratios.txt"
echo "pictures: $out/osg_*.png (OSG) and $out/round_1/images/ (penumbra); every round in $out/osg_rounds.csv"
