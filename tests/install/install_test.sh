#!/usr/bin/env bash
# The installed sdfreel renders without the source tree: `cmake --install` into a fresh prefix, and
# the Debian package from `cpack -G DEB` unpacked with `dpkg -x`, each render a small timeline from
# a folder holding only that timeline, with no SDFREEL_* variables, on every backend; their
# frames.framemd5 must equal the build tree's. Then, with share/sdfreel taken away, the installed
# binary must fail: it found its data in its prefix, not in the source tree it was built from.
# Both also hold the man page, which `man sdfreel` shows, and the bash completion.
# Usage: install_test.sh BUILD_DIR CMAKE CPACK BACKEND...
set -euo pipefail
build=$1 cmake=$2 cpack=$3
shift 3
backends=("$@")
fail() { echo "FAIL: $*" >&2; exit 1; }

for v in $(env | sed -n 's/^\(SDFREEL_[A-Za-z0-9_]*\)=.*/\1/p'); do unset "$v"; done
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cat >"$tmp/t.toml" <<'TOML'
[video]
scene = "sdf_morph"
fps = 10
duration = 0.3
resolution = [64, 36]
samples = 1
quality = "draft"

[output]
dir = "out"
frames = ["exr", "png"]
video = "t.mkv"
codec = "ffv1"

[camera]
keys = [
  { t = 0.0, position = [0.0, 1.5, -4.0], target = [0.0, 0.6, 0.0], fov = 40.0 },
  { t = 0.3, position = [1.0, 1.6, -3.8], target = [0.0, 0.6, 0.0], fov = 42.0 },
]
TOML

# The reference: the build tree's binary.
mkdir "$tmp/ref"
cp "$tmp/t.toml" "$tmp/ref/"
for b in "${backends[@]}"; do
  (cd "$tmp/ref" && "$build/sdfreel" render t.toml --backend "$b" --out "$b" 2>/dev/null) ||
    fail "build tree render ($b)"
done

"$cmake" --install "$build" --prefix "$tmp/prefix" >/dev/null
(cd "$tmp" && "$cpack" -G DEB --config "$build/CPackConfig.cmake" -B "$tmp/pkg" >/dev/null)
deb=$(ls "$tmp"/pkg/sdfreel_*.deb)
depends=$(dpkg-deb -f "$deb" Depends)
echo "package: $(basename "$deb"), Depends: $depends"
for lib in libpng16 libopenexr libopencolorio libavcodec libtbb libopenimageio; do
  [[ $depends == *"$lib"* ]] || fail "the package does not depend on $lib"
done
if [[ " ${backends[*]} " == *" gl "* ]]; then
  for lib in libegl1 libegl-mesa0 libgl1-mesa-dri; do
    [[ $depends == *"$lib"* ]] || fail "the package does not depend on $lib (the GL backend's EGL)"
  done
fi
dpkg -x "$deb" "$tmp/deb"

renders_like_the_build_tree() {  # PREFIX LABEL
  local prefix=$1 label=$2 b run
  [ -x "$prefix/bin/sdfreel" ] || fail "$label: no bin/sdfreel"
  [ -f "$prefix/share/sdfreel/ocio/config.ocio" ] || fail "$label: no share/sdfreel/ocio/config.ocio"
  [ -d "$prefix/share/sdfreel/shaders/common" ] || fail "$label: no share/sdfreel/shaders"
  for b in "${backends[@]}"; do
    run="$tmp/run-$label-$b"
    mkdir "$run"
    cp "$tmp/t.toml" "$run/"
    (cd "$run" && "$prefix/bin/sdfreel" render t.toml --backend "$b" 2>"$run.log") ||
      fail "$label: render with $b: $(tail -n 3 "$run.log")"
    cmp "$run/out/frames.framemd5" "$tmp/ref/$b/frames.framemd5" ||
      fail "$label: $b frames differ from the build tree's"
    [ -s "$run/out/t.mkv" ] || fail "$label: no video"
    echo "$label: $b render matches the build tree ($(grep -vc '^#' "$run/out/frames.framemd5") frames)"
  done
}
renders_like_the_build_tree "$tmp/prefix" install
renders_like_the_build_tree "$tmp/deb/usr" deb

# The man page and the bash completion come with both installs, and `man sdfreel` shows the page.
command -v man >/dev/null || fail "man is not installed (scripts/install-deps.sh --test installs man-db)"
for prefix in "$tmp/prefix" "$tmp/deb/usr"; do
  [ -f "$prefix/share/man/man1/sdfreel.1.gz" ] || fail "$prefix: no share/man/man1/sdfreel.1.gz"
  [ -f "$prefix/share/bash-completion/completions/sdfreel" ] ||
    fail "$prefix: no share/bash-completion/completions/sdfreel"
  MANPATH="$prefix/share/man" MANPAGER=cat MANWIDTH=80 man sdfreel >"$tmp/man.txt" 2>"$tmp/man.log" ||
    fail "$prefix: man sdfreel: $(cat "$tmp/man.log")"
  grep -q "EXIT STATUS" "$tmp/man.txt" || fail "$prefix: man sdfreel shows no EXIT STATUS"
  bash -c "source '$prefix/share/bash-completion/completions/sdfreel'; complete -p sdfreel" >/dev/null ||
    fail "$prefix: the bash completion does not register for sdfreel"
done
echo "man sdfreel: $(head -n 1 "$tmp/man.txt" | tr -s ' ')"

# Without its data the installed binary must fail, whatever the source tree holds: the OCIO config
# (every backend needs it), then the shaders (gl).
fails_without() {  # RELATIVE BACKEND MESSAGE
  local data=$tmp/prefix/share/sdfreel run=$tmp/run-without-${1//\//_}
  mv "$data/$1" "$data/$1.away"
  mkdir "$run"
  cp "$tmp/t.toml" "$run/"
  if (cd "$run" && "$tmp/prefix/bin/sdfreel" render t.toml --backend "$2" 2>"$run.log"); then
    fail "without share/sdfreel/$1 the installed binary still rendered with $2"
  fi
  grep -q "$3" "$run.log" || fail "without $1: expected '$3', got: $(cat "$run.log")"
  mv "$data/$1.away" "$data/$1"
  echo "without share/sdfreel/$1: $2 fails ($(grep -m 1 "$3" "$run.log"))"
}
fails_without ocio/config.ocio cpu "cannot find the shipped OCIO config"
if [[ " ${backends[*]} " == *" gl "* ]]; then
  fails_without shaders gl "cannot find the GLSL shader folder"
fi

# A shader's image channel opens the installed image module (lib/sdfreel, OpenImageIO): `check`
# reads the image from both installs, and fails, naming the module, without it.
img=$tmp/image-channel
mkdir "$img"
cp "$tmp/ref/${backends[0]}/frames/00000.png" "$img/picture.png"
echo 'void mainImage(out vec4 c, in vec2 p) { c = texture(iChannel0, p / iResolution.xy); }' >"$img/s.glsl"
printf '[video]\nshader = "s.glsl"\n[channels.image]\niChannel0 = { texture = "picture.png" }\n' >"$img/t.toml"
for prefix in "$tmp/prefix" "$tmp/deb/usr"; do
  [ -f "$prefix/lib/sdfreel/sdfreel_image_oiio.so" ] || fail "$prefix: no lib/sdfreel/sdfreel_image_oiio.so"
  (cd "$img" && "$prefix/bin/sdfreel" check t.toml >"$img.log" 2>&1) ||
    fail "$prefix: check of an image channel: $(tail -n 3 "$img.log")"
done
mv "$tmp/prefix/lib/sdfreel" "$tmp/prefix/lib/sdfreel.away"
if (cd "$img" && "$tmp/prefix/bin/sdfreel" check t.toml 2>"$img.log"); then
  fail "without lib/sdfreel the installed binary still read an image"
fi
grep -q "image module" "$img.log" || fail "without lib/sdfreel: expected 'image module', got: $(cat "$img.log")"
echo "image channel: read through the installed module; without it: $(grep -m 1 "image module" "$img.log")"

# libav's encoders are the installed video module (lib/sdfreel): without it a render that writes
# no video still works, and one with a video fails naming the module, before any frame.
vid=$tmp/video-module
mkdir "$vid"
cp "$tmp/t.toml" "$vid/"
(cd "$vid" && "$tmp/prefix/bin/sdfreel" render t.toml --no-video --out nv 2>"$vid.log") ||
  fail "without lib/sdfreel a render with --no-video failed: $(tail -n 3 "$vid.log")"
if (cd "$vid" && "$tmp/prefix/bin/sdfreel" render t.toml --out v 2>"$vid.log"); then
  fail "without lib/sdfreel the installed binary still wrote a video"
fi
grep -q "video module" "$vid.log" || fail "without lib/sdfreel: expected 'video module', got: $(cat "$vid.log")"
[ ! -e "$vid/v/frames/00000.png" ] || fail "without lib/sdfreel: frames were written before the failure"
echo "video: without the module --no-video renders; a video fails: $(grep -m 1 "video module" "$vid.log")"
