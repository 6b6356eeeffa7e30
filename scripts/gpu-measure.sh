#!/usr/bin/env bash
# The NVIDIA measurements of the README's "Measured on an NVIDIA H100", in one run (~7 min on an
# H100, plus ~2 min for the goal ratios and stop 68's choices in rounds that come first). On the GPU
# machine, from the project root, after building here, `scripts/fetch-assets.sh` and
# `../shared/tools/gpu-bundle.sh`:
#     source .gpu/env.sh; scripts/gpu-measure.sh [OUT_DIR]
# Writes gltests.log (the GL suite against the driver: its warnings fail tests) and bench.log (every
# table) to OUT_DIR (default: $OUT where the device tool sets it, else ./gpu-out). Each step has a
# time limit and logs its start, end and the SM clock, so a cut-off run still says how far it got.
# GPU_MEASURE_SHORT=1 keeps the kept-map tables, the fixed-camera view-dependent ones and `compare`
# (~4 min with the suite) for a session with little device time; the redrawn-map and scaling
# tables need the whole run.
set -u
short_run=${GPU_MEASURE_SHORT:-0}
out=${1:-${OUT:-gpu-out}}
mkdir -p "$out"
log=$out/bench.log
work=$(mktemp -d)
step() {
    local name=$1 limit=$2
    shift 2
    echo "=== $name ($(date +%T), SM clock $(nvidia-smi --query-gpu=clocks.sm --format=csv,noheader 2>/dev/null))" >>"$log"
    timeout "$limit" "$@" >>"$log" 2>&1
    echo "=== $name: exit $? ($(date +%T))" >>"$log"
}
# A step of the whole run only.
long_step() {
    if [ "$short_run" = 1 ]; then echo "=== $1: skipped (GPU_MEASURE_SHORT)" >>"$log"; else step "$@"; fi
}
# The GL suite in four shards at once: the machine has 16 cores and the tests are mostly CPU work
# (the ray-traced references, scene set-up); the timed steps come after it, alone.
shards=4
gl_limit=300
[ "$short_run" = 1 ] && gl_limit=180
for i in $(seq 0 $((shards - 1))); do
    mkdir -p "$work/gl$i"
    (cd "$work/gl$i" && GTEST_TOTAL_SHARDS=$shards GTEST_SHARD_INDEX=$i timeout "$gl_limit" penumbra_gl_tests --gtest_brief=1 >"$out/gltests.$i.log" 2>&1
     echo "exit $?" >>"$out/gltests.$i.log") &
done
wait
cat "$out"/gltests.*.log >"$out/gltests.log" && rm "$out"/gltests.*.log
short=(--no-images --seconds 1 --warmup-seconds 1)
hd=(--size 1920x1080 --shadow-res 2048)
# The GPU idles at 345 MHz: a warm-up run first, never timed.
step warm-up 40 penumbra bench --techniques cssm2 "${hd[@]}" --seconds 8 --warmup-seconds 5 --no-images --out "$work/warm"
# The open goals' ratios first, in rounds (each case's frame ÷ its scene's first case's in the same
# round, the median with its interval), at the llvmpipe tables' 1280x720: issue 15's hard ÷ none,
# cssm2 and cssm1 ÷ hard on the default scene, issue 11's cssm2 ÷ hard on the glass scene (the H200
# read 1.53 there by GPU ms, from one measurement of each).
rounds=(--rounds 8 --seconds 0.5 --warmup-seconds 0.5 --interleave 9 --no-images)
step "goal ratios, default scene" 90 penumbra bench --techniques none,hard,cssm2,cssm1,pcf-poisson16,pcss "${rounds[@]}" --out "$work/goals-default"
step "goal ratios, glass scene" 60 penumbra bench scenes/glass.json --techniques hard,cssm2,cssm1 --fixed-camera "${rounds[@]}" --out "$work/goals-glass"
# The same goals without the screen split (receivers cut into rectangles, each drawn with a
# program that leaves out what cannot reach it: a shadow lookup, a light, the tint): on llvmpipe it
# pays, each pixel being dear; on a GPU its extra draws and program switches (120 draws against 42
# for none, default scene, hard) may cost more than the lookups they save. Compare the ratios.
step "goal ratios without the split, default scene" 90 penumbra bench --techniques none,hard,cssm2 --shadow-everywhere --light-everywhere --tint-everywhere "${rounds[@]}" --out "$work/goals-default-whole"
step "goal ratios without the split, glass scene" 60 penumbra bench scenes/glass.json --techniques hard,cssm2 --fixed-camera --shadow-everywhere --light-everywhere --tint-everywhere "${rounds[@]}" --out "$work/goals-glass-whole"
# Where the GPU time of the open goals goes, part by part (stop 71's sub-pass clock: each debug
# group bounded by glFinish, printed as "sub-pass" lines and in bench.json's sub_pass_wall_ms):
# issue 11's cssm2 against hard on the glass scene, issue 15's hard against none.
step "sub-passes, glass and default scenes" 60 bash -c "penumbra bench scenes/glass.json --techniques hard,cssm2 --fixed-camera --calibrate --frames 60 --no-images --out $work/sub-glass; penumbra bench --techniques none,hard --calibrate --frames 60 --no-images --out $work/sub-default"
# Stop 68's two llvmpipe-made choices, in rounds with every map redrawn: the depth tile bounds,
# made only for kept maps (on llvmpipe their pass cost more than the taps they saved; on a GPU the
# pass is cheap), against `tile_bounds_every_frame=true`, which makes them as before; and the
# moment maps' blur kernels (the box, the default since stop 69, saved a quarter of the pass there),
# and stop 69's blur and first mip levels in one compute pass with shared memory (`compute_blur`;
# 7x the shadow pass on llvmpipe); stop 70's MSM moments quantized to 64 bits (the default) against
# RGBA32F (`quantized=false`; on llvmpipe the pass 1.79-2.12x hard's against 1.96-2.38x).
step "stop 68-70 choices, maps redrawn" 140 penumbra bench --techniques hard,pcf-poisson16,pcf-poisson16:tile_bounds_every_frame=true,pcss,pcss:tile_bounds_every_frame=true,vsm,vsm:blur_kernel=gaussian,vsm:compute_blur=true,msm,msm:quantized=false --redraw-shadow-maps "${rounds[@]}" --out "$work/stop68"
# Stop 70's flat casters left out where their shadow falls on nothing (the osgShadow grid's
# ground), against `--every-caster`, maps redrawn.
step "stop 70 casters that shadow nothing, grid" 60 penumbra bench --grid-scene 98000 --techniques floor-depth,hard,pcf-poisson16 --shadow-res 2048 --fixed-camera --redraw-shadow-maps "${rounds[@]}" --out "$work/stop70-cut"
step "stop 70 every caster, grid" 60 penumbra bench --grid-scene 98000 --techniques floor-depth,hard,pcf-poisson16 --shadow-res 2048 --fixed-camera --redraw-shadow-maps --every-caster "${rounds[@]}" --out "$work/stop70-every"
# Stop 72's ground drawn only around the casters standing on it (default scene), and stop 73's in
# moment maps only around the shadows on it, blurred and mip-mapped only there, against
# `--every-caster`, maps redrawn: on llvmpipe about 1 ms of hard's 9 ms shadow pass and 7.5 of
# evsm4's 18.5; a GPU fills a ground's texels far faster, so it may show less.
step "stop 72-73 ground near its casters, default scene" 60 penumbra bench --techniques hard,cssm2,vsm,evsm4 --redraw-shadow-maps "${rounds[@]}" --out "$work/stop72-near"
step "stop 72-73 every caster, default scene" 60 penumbra bench --techniques hard,cssm2,vsm,evsm4 --redraw-shadow-maps --every-caster "${rounds[@]}" --out "$work/stop72-every"
step "default scene, every technique" 150 penumbra bench --techniques all "${hd[@]}" "${short[@]}" --out "$work/default"
# The view-dependent maps against hard from the scene's own camera, as the llvmpipe tables take them.
step "default scene, fixed camera" 40 penumbra bench --techniques none,hard,cascaded,lispsm,psm "${hd[@]}" --fixed-camera "${short[@]}" --out "$work/fixed"
# SDSM's pre-pass and its two-word read-back (stop 79: reduced on the GPU, bounds on 5 % steps):
# the CPU ms column against the GPU ms says whether the fit's wait for the GPU costs the frame.
step "default scene, cascaded with sdsm" 30 penumbra bench --techniques cascaded,cascaded:sdsm=true "${hd[@]}" "${short[@]}" --out "$work/sdsm"
# The float target and its resolve pass against the default straight-into-sRGB frame (render/SrgbTarget.h).
long_step "default scene, float target" 40 penumbra bench --techniques none,hard,cssm2 "${hd[@]}" --float-target "${short[@]}" --out "$work/float-target"
long_step "default scene, maps redrawn" 150 penumbra bench --techniques all "${hd[@]}" --redraw-shadow-maps "${short[@]}" --out "$work/redrawn"
# What CSSM's farthest-layer bound (tint_behind_all, on by default) costs where maps are redrawn.
long_step "default scene, maps redrawn, cssm without tint_behind_all" 40 penumbra bench --techniques cssm1,cssm2 "${hd[@]}" --redraw-shadow-maps --param tint_behind_all=false "${short[@]}" --out "$work/redrawn-no-tba"
if [ -f bench/assets/dragon_vrip.ply ]; then
    dragon=none,hard,cssm2,cssm1,pcf-poisson16,pcss,cascaded,lispsm,psm,vsm,msm,floor-depth,floor-lambert,floor-unshadowed
    step "dragon" 120 penumbra bench bench/dragon.json --techniques $dragon "${hd[@]}" "${short[@]}" --out "$work/dragon"
    long_step "dragon, maps redrawn" 120 penumbra bench bench/dragon.json --techniques $dragon "${hd[@]}" --redraw-shadow-maps "${short[@]}" --out "$work/dragon-redrawn"
    # Culling solids' back faces (the default) against drawing both, where triangles dominate.
    long_step "dragon, maps redrawn, both faces" 90 penumbra bench bench/dragon.json --techniques none,hard,cascaded,lispsm "${hd[@]}" --redraw-shadow-maps --both-faces "${short[@]}" --out "$work/dragon-both"
else
    echo "=== dragon: skipped (bench/assets/dragon_vrip.ply missing: scripts/fetch-assets.sh)" >>"$log"
fi
# Shadow volumes on models as they come: kept across frames (VolumeCache) against made through the
# geometry shader every frame (--redraw-shadow-maps).
step "street, shadow volumes" 60 penumbra bench scenes/street.json --techniques hard,shadow-volumes --size 1920x1080 --fixed-camera "${short[@]}" --out "$work/street-volumes"
long_step "street, shadow volumes made every frame" 60 penumbra bench scenes/street.json --techniques hard,shadow-volumes --size 1920x1080 --fixed-camera --redraw-shadow-maps "${short[@]}" --out "$work/street-volumes-redrawn"
step "glass scene" 60 penumbra bench scenes/glass.json --techniques none,hard,cssm2,cssm1 "${short[@]}" --out "$work/glass"
step "floor" 60 penumbra bench --suite floor --calibrate "${short[@]}" --out "$work/floor"
long_step "texel scaling" 80 penumbra bench --techniques hard --shadow-res 1024,2048,4096,8192 --size 1920x1080 --redraw-shadow-maps "${short[@]}" --out "$work/texels"
long_step "triangle scaling" 120 penumbra bench --suite triangle-scaling "${short[@]}" --out "$work/scaling"
step "compare, default scene" 100 penumbra compare --out "$work/compare-default"
long_step "compare, glass scene" 100 penumbra compare scenes/glass.json --out "$work/compare-glass"
echo "driver warning lines: $(grep -c 'warning: GL' "$log") (each distinct message is logged 3 times a run; the tables flag each case that had any)" >>"$log"
rm -rf "$work"
