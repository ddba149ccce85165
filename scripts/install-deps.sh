#!/usr/bin/env bash
# Installs what clrender needs to build, render and test, from Debian's archive only.
# Safe to run again: packages already present are skipped, and apt is only asked when
# something is missing.
#   install-deps.sh        everything below: what every script and test needs
#   install-deps.sh demo   only what building clrender and running scripts/demo.sh needs
set -euo pipefail

# Building clrender and clrender_make_forest, and rendering the demo (scripts/demo.sh).
demo_packages=(
  build-essential cmake pkg-config
  ocl-icd-opencl-dev opencl-clhpp-headers pocl-opencl-icd
  nlohmann-json3-dev libstb-dev libcli11-dev libpng-dev zlib1g-dev
  # ISA-L's igzip: the PNG outputs' fast deflate
  libisal-dev
  # SHA-256 (libcrypto) for the keys and checksums of the caches
  libssl-dev
  # XXH3 for the checksums of the caches' entry payloads
  libxxhash-dev
  # EXR output (-o frame.exr): OpenEXR 3 and its CMake config
  libopenexr-dev
  # --video (the demo's showcase.mp4)
  ffmpeg
  # JPEG input: libjpeg-turbo decodes billboard JPEGs (also the fuzz seed generator's writer)
  libjpeg62-turbo-dev
  # OBJ meshes: tinyobjloader parses the files (host/scene/obj_reader.cpp)
  libtinyobjloader-dev
  # `clrender view`'s web server (host/view/, part of clrender) and its tests' HTTP client
  libcpp-httplib-dev
)

# The tests, the benchmarks and the other scripts, besides.
packages=(
  "${demo_packages[@]}"
  clinfo
  googletest libgtest-dev
  # the man page, made from --help at build time (cmake/write_man_page.cmake)
  help2man
  parallel
  # clrender_bench's Embree peer (scripts/bench.sh, docs/benchmarks.md)
  libembree-dev
  # scripts/bench_povray.sh and its test: POV-Ray renders clrender's scenes for comparison
  povray
  # scripts/fuzz.sh: clang with libFuzzer and the sanitizer runtimes (its seed generator writes
  # JPEGs with libjpeg, above). (gcc's ASan and UBSan runtimes, which scripts/sanitize.sh uses,
  # come with build-essential.)
  clang libclang-rt-14-dev
  # scripts/oclgrind.sh: the OpenCL simulator that checks every memory access of the kernels
  oclgrind
  # tests/app/scene_schema_test.cpp: a real JSON Schema validator checks docs/scene.schema.json
  # against the bad-scene catalogue, so that the schema and the scene loader cannot drift apart
  python3-jsonschema
  # the render farm's tests (tests/farm/): a two-node Slurm cluster on this machine
  slurmctld slurmd slurm-client munge
  # scripts/install-intel-opencl.sh: pip downloads Intel's CPU OpenCL runtime (wheels from
  # PyPI, the one thing Debian does not package) for scripts/second-opencl.sh
  python3 python3-pip
  # tests/browser/ and scripts/bench_viewer.sh: clrender view's page driven in headless Chromium
  chromium chromium-driver python3-selenium
  # tests/browser/*_test.js: the page's scripts (viewer/camera.js, viewer/live.js) run in Node.js
  nodejs
)

case "${1:-all}" in
  all) ;;
  demo) packages=("${demo_packages[@]}") ;;
  *) echo "usage: install-deps.sh [all|demo]" >&2; exit 1 ;;
esac

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all packages present"
  exit 0
fi

echo "install-deps: installing ${missing[*]}"
sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -q
$sudo apt-get install -y -q --no-install-recommends "${missing[@]}"
