#!/usr/bin/env bash
# The project's one set-up script. Installs the Debian packages probeproxy needs (only those
# missing: `apt-get update` once, then one `apt-get install`), configures and builds with CMake
# into build/, then runs what was asked:
#   scripts/setup.sh demo    the main job: `probeproxy demo` on the built-in level
#   scripts/setup.sh test    every test (CTest)
#   scripts/setup.sh build   install, build and fetch the real-map corpus only
#   scripts/setup.sh module  install and build only the Python module (the Blender add-on's)
#   scripts/setup.sh sanitize  the unit and end-to-end tests built with AddressSanitizer and
#                            UBSan, in build-asan/ (the suite levels come from build/; about
#                            an hour on 2 cores from clean, so not part of `test`)
# Idempotent: a second run installs nothing and rebuilds only what changed.
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build="${PROBEPROXY_BUILD_DIR:-$here/build}"
job="${1:-build}"

packages=(
  build-essential cmake pkg-config
  libcgal-dev libgmp-dev libmpfr-dev libeigen3-dev   # hulls, fits, oriented boxes
  libopenmesh-dev                                    # convexity checks, simplification
  libembree-dev libtbb-dev                           # ray casting, threads
  libassimp-dev                                      # glTF/GLB, OBJ, PLY, OFF level meshes
  libzip-dev                                         # Quake 3 .pk3 archives (zip)
  libroaring-dev                                     # compressed sets of floor samples (layout)
  libopenimageio-dev openimageio-tools               # EXR/HDR/PNG cubemaps and reports
  libglm-dev nlohmann-json3-dev libcli11-dev
  pybind11-dev python3-dev                           # the Blender add-on's module
  libgtest-dev libbenchmark-dev valgrind             # tests, benchmarks, instruction counts
  blender python3-matplotlib                         # test levels, reference renders, charts
  python3-distributed                                # layout's candidates on Dask (scripts/layout_dask.py)
  clang-14 libclang-rt-14-dev                        # the fuzz targets (libFuzzer, sanitizers)
  godot3-server                                      # the Godot round trip (Godot 3, headless)
  godot3-runner                                      # Godot 3 renders the probes (scripts/render_check.py)
  xvfb                                               # the add-on screenshot (scripts/addon_screenshot.py)
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${missing[*]}" >&2
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo="sudo"
  $sudo apt-get update
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y --no-install-recommends "${missing[@]}"
fi

cmake -S "$here" -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
targets=()
[ "$job" = module ] && targets=(--target probeproxy_py)
cmake --build "$build" -j"$(nproc)" "${targets[@]}"

# The real-map corpus: Debian's nexuiz-data, downloaded (not installed) and unpacked under
# build/corpus/ once, then one scene per map with a probe per spawn point: the tuning set in
# build/corpus/scenes/, the validation set (never tuned on) in build/corpus/validation/.
# Cached: a second run fetches nothing and rewrites no scene whose bytes are the same.
# The demo and the add-on's module do not need it.
if [ "$job" = test ] || [ "$job" = build ] || [ "$job" = sanitize ]; then
  data=$("$here/scripts/corpus/fetch_nexuiz.sh" "$build")
  /usr/bin/python3 "$here/scripts/corpus/write_scenes.py" "$build/plugin/cli/probeproxy" \
    "$data/data.pk3" "$build/corpus/scenes"
  /usr/bin/python3 "$here/scripts/corpus/write_scenes.py" "$build/plugin/cli/probeproxy" \
    "$data/data.pk3" "$build/corpus/validation" --set validation
fi

case "$job" in
  demo) "$build/plugin/cli/probeproxy" demo --out "$build/demo" ;;
  test) ctest --test-dir "$build" --output-on-failure -j"$(nproc)" ;;
  build | module) ;;
  sanitize)
    # The suite levels once in build/ (Blender renders them) and the corpus (setup.sh build has
    # fetched it), then every unit and e2e test of a sanitized tree reading them. A sanitizer report stops the program, so it fails its test.
    ctest --test-dir "$build" -R '^suite_generate$' --output-on-failure
    asan="$here/build-asan"
    cmake -S "$here" -B "$asan" -DCMAKE_BUILD_TYPE=Release -DPROBEPROXY_SANITIZE=ON \
      -DPROBEPROXY_SUITE_DIR="$build/scenes" >/dev/null
    cmake --build "$asan" -j"$(nproc)"
    [ -e "$asan/corpus" ] || ln -s "$build/corpus" "$asan/corpus"  # the real maps, fetched once
    ASAN_OPTIONS=detect_leaks=1 LSAN_OPTIONS="suppressions=$here/tests/fuzz/lsan.supp" \
      ctest --test-dir "$asan" -L 'unit|e2e' -E '^suite_generate$' -FA '^suite$' \
      --output-on-failure -j"$(nproc)"
    ;;
  *) echo "usage: scripts/setup.sh [demo|test|build|module|sanitize]" >&2; exit 2 ;;
esac
