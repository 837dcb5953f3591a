#!/usr/bin/env bash
# The GL backend on a GPU, for a machine with an NVIDIA GPU and its driver but no X server:
# lists the devices, renders every golden timeline (tests/golden) on the GPU and holds each frame
# to the CPU backend's by Filament's rule (`verify --tolerance filament`: at most 0.1% of display
# values off by more than 5/255, mean under 0.5/255, a diff image on failure; a user's shader,
# which has no CPU twin, to llvmpipe's), then runs `sdfreel bench` for every scene on cpu,
# llvmpipe and the GPU, and for every example shader (examples/shaders/*.toml) on llvmpipe and the
# GPU. Everything goes to one folder.
#
#   scripts/gpu-check.sh [--device gpu|software|N] [--out DIR] [--resolution WxH] [--bin SDFREEL]
#   scripts/gpu-check.sh --bundle DIR    (here: install sdfreel and the libraries it needs into
#                                          DIR, to carry to a bare machine that reaches nothing)
#
# On a bare machine: unpack the EGL loader first (libegl1 libglvnd0 libopengl0 .debs, see
# docs/gl.md), then `scripts/gpu-check.sh --bin DIR/bin/sdfreel`. `--device software` runs the
# same checks on Mesa's llvmpipe (how the script itself is tested). Exit 1 when a frame fails.
set -uo pipefail
cd "$(dirname "$0")/.."
device=gpu out=output/gpu-check resolution=1280x720 bin=build/sdfreel bundle=
while [ $# -gt 0 ]; do
  case $1 in
    --device) device=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    --resolution) resolution=$2; shift 2 ;;
    --bin) bin=$2; shift 2 ;;
    --bundle) bundle=$2; shift 2 ;;
    *) echo "gpu-check.sh: unknown argument '$1' (see the comment at its top)" >&2; exit 2 ;;
  esac
done

if [ -n "$bundle" ]; then
  # The binary with its data, and every shared library it links that is not libc's: the bare
  # machine has the same Debian base, not its -dev packages' runtime libraries.
  set -e
  cmake --install build --prefix "$bundle" >/dev/null
  mkdir -p "$bundle/lib"
  ldd "$bundle/bin/sdfreel" | awk '/=> \//{print $3}' |
    grep -v -E '/(libc|libm|libdl|libpthread|librt|ld-linux[^/]*)\.so' |
    xargs -r cp -L -t "$bundle/lib"
  echo "bundle: $bundle ($(du -sh "$bundle" | cut -f1)); run: LD_LIBRARY_PATH=$bundle/lib" \
    "scripts/gpu-check.sh --bin $bundle/bin/sdfreel"
  exit 0
fi

bin=$(realpath "$bin")
[ -x "$bin" ] || { echo "gpu-check.sh: no sdfreel at $bin (scripts/build.sh first)" >&2; exit 2; }
# NVIDIA's driver registers its EGL vendor file here on the lent machines; glvnd finds it in
# /usr/share/glvnd/egl_vendor.d on a normal installation.
nv=/usr/local/nvidia/share/glvnd/egl_vendor.d/10_nvidia.json
if [ -z "${__EGL_VENDOR_LIBRARY_FILENAMES:-}" ] && [ -f $nv ] &&
  [ ! -f /usr/share/glvnd/egl_vendor.d/10_nvidia.json ]; then
  export __EGL_VENDOR_LIBRARY_FILENAMES=$nv:/usr/share/glvnd/egl_vendor.d/50_mesa.json
fi
mkdir -p "$out"
out=$(realpath "$out")
log() { echo "$*" | tee -a "$out/summary.txt"; }
: >"$out/summary.txt"

"$bin" devices >"$out/devices.txt" 2>&1
"$bin" devices --json >"$out/devices.json" 2>/dev/null
log "devices ($out/devices.txt):"
sed 's/^/  /' "$out/devices.txt" | tee -a "$out/summary.txt"

failed=0
for timeline in tests/golden/*/*.toml; do
  scene=$(basename "$(dirname "$timeline")") name=$(basename "$timeline" .toml)
  work=$out/golden/$scene-$name
  rm -rf "$work" && mkdir -p "$work"
  # The timeline where it is (a shader's is found relative to it); the reference: the CPU's, or
  # llvmpipe's for a user's shader.
  t=$PWD/$timeline
  ref=(--backend cpu)
  [[ $scene == shader_* ]] && ref=(--backend egl --gl-device software)
  if ! (cd "$work" && "$bin" render "$t" "${ref[@]}" --out cpu >cpu.log 2>&1); then
    log "golden $scene/$name: the reference render failed ($work/cpu.log)"
    failed=1
    continue
  fi
  (cd "$work" && "$bin" verify "$t" --manifest cpu/manifest.json --tolerance filament \
    --backend egl --gl-device "$device" --out diff >verify.log 2>&1)
  rc=$?
  [ $rc -eq 0 ] || failed=1
  log "golden $scene/$name on device $device: $(tail -n 1 "$work/verify.log")"
  grep -q "OUTSIDE" "$work/verify.log" && log "  diff images: $work/diff/"
done

# Bench: CPU and llvmpipe in one run, then the GPU; the reference is rendered once and shared.
for scene in $("$bin" scenes | awk '{print $1}'); do
  b=$out/bench/$scene
  mkdir -p "$b"
  args=(bench "$scene" --resolution "$resolution" --frames 0 --presets-only --repetitions 3
    --out "$out/bench/reference-$scene")
  SDFREEL_GL_DEVICE=software "$bin" "${args[@]}" --backends cpu,egl >"$b/software.txt" 2>&1 ||
    log "bench $scene on cpu and llvmpipe failed ($b/software.txt)"
  cp "$out/bench/reference-$scene/bench.csv" "$b/software.csv" 2>/dev/null
  if [ "$device" != software ]; then
    SDFREEL_GL_DEVICE=$device "$bin" "${args[@]}" --backends egl >"$b/gpu.txt" 2>&1 ||
      log "bench $scene on device $device failed ($b/gpu.txt)"
    cp "$out/bench/reference-$scene/bench.csv" "$b/gpu.csv" 2>/dev/null
  fi
  log "bench $scene at $resolution ($b):"
  grep -h -E "^(backend|  *final|  *draft|  *naive)|x |dB" "$b"/*.txt 2>/dev/null | head -n 20 |
    sed 's/^/  /' | tee -a "$out/summary.txt"
done
# A user's shader: its Image pass's samples against a 64-sample reference, llvmpipe then the GPU.
for t in examples/shaders/*.toml; do
  name=$(basename "$t" .toml)
  b=$out/bench/shader-$name
  mkdir -p "$b"
  args=(bench "$t" --resolution "$resolution" --frames 0 --repetitions 3 --out "$b/run")
  SDFREEL_GL_DEVICE=software "$bin" "${args[@]}" --backends egl >"$b/software.txt" 2>&1 ||
    log "bench $name on llvmpipe failed ($b/software.txt)"
  if [ "$device" != software ]; then
    SDFREEL_GL_DEVICE=$device "$bin" "${args[@]}" --backends egl >"$b/gpu.txt" 2>&1 ||
      log "bench $name on device $device failed ($b/gpu.txt)"
  fi
  log "bench shader $name at $resolution ($b):"
  grep -h "spp=" "$b"/*.txt 2>/dev/null | grep "^|" | sed 's/^/  /' | tee -a "$out/summary.txt"
done
log "gpu-check: $([ $failed -eq 0 ] && echo "every golden frame within tolerance" ||
  echo "FAILED (see above)"); everything is in $out"
exit $failed
