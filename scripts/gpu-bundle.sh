#!/usr/bin/env bash
# Packs a build for scripts/gpu-check.sh on a GPU machine that has none of Debian's packages
# (docs/opencl-devices.md, A GPU): the working tree travels on its own; this folder holds the
# rest, and its run.sh runs the check there.
#   bundle.tar.xz   the binaries the check runs, stripped, and every library `ldd` lists but the C
#                   runtime's (libstdc++ and libgcc_s apart, taken only if the machine's fail)
#   cpu-images/     the feature scenes rendered here (scripts/gpu-check.sh --cpu-images), so
#                   that the check can say which GPU images are PoCL's bytes
#   course.tar      ../shared/course-scenes where this checkout has it, for the Course tests
#   run.sh          on the GPU machine, from the tree's root: `bash BUNDLE/run.sh`; logs and
#                   bench.*.json go to $GPU_CHECK_OUT (default /tmp/gpu-check)
# The tests find the tree, its course scenes and the build's programs where this build was
# configured (their compiled-in folders): run.sh links those paths when they do not exist, or
# moves its own links of an earlier run (a link there is replaced, a folder left alone), and
# removes what it unpacked when it ends.
#
#   scripts/gpu-bundle.sh DIR           $CLRENDER_BUILD_DIR overrides build/
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${CLRENDER_BUILD_DIR:-$root/build}"
[ $# -eq 1 ] || { echo "usage: scripts/gpu-bundle.sh DIR" >&2; exit 2; }
out="$1"
binaries=(clrender clrender_tests clrender_bench clrender_make_forest clrender_make_textures)
for binary in "${binaries[@]}"; do
    [ -x "$build/$binary" ] || { echo "gpu-bundle.sh: no $build/$binary: build it first" >&2; exit 1; }
done
build_dir="$(cd "$build" && pwd)"
source_dir="$(sed -n 's/^CMAKE_HOME_DIRECTORY:INTERNAL=//p' "$build/CMakeCache.txt")"
[ -n "$source_dir" ] || { echo "gpu-bundle.sh: $build/CMakeCache.txt names no source folder" >&2; exit 1; }

mkdir -p "$out"
staging="$(mktemp -d)"
trap 'rm -rf "$staging"' EXIT
mkdir -p "$staging/bin" "$staging/lib/fallback"
for binary in "${binaries[@]}"; do
    cp "$build/$binary" "$staging/bin/"
    strip "$staging/bin/$binary"
done
# The C runtime is the machine's own (a newer glibc runs these binaries); libstdc++ and libgcc_s
# wait in lib/fallback for a machine whose own are older than this build's.
for binary in "${binaries[@]}"; do ldd "$build/$binary"; done | awk '/=> \//{print $3}' | sort -u |
    while read -r library; do
        case "$(basename "$library")" in
            libc.so.* | libm.so.* | libpthread.so.* | libdl.so.* | librt.so.* | ld-linux*) ;;
            libstdc++.so.* | libgcc_s.so.*) cp -L "$library" "$staging/lib/fallback/" ;;
            *) cp -L "$library" "$staging/lib/" ;;
        esac
    done
tar -cJf "$out/bundle.tar.xz" -C "$staging" .

rm -rf "$out/cpu-images"
bash "$root/scripts/gpu-check.sh" --cpu-images "$out/cpu-images"
if [ -d "$source_dir/../shared/course-scenes" ]; then
    tar -cf "$out/course.tar" -C "$source_dir/../shared" course-scenes
fi

cat > "$out/run.sh" << EOF
#!/usr/bin/env bash
# Made by scripts/gpu-bundle.sh: unpacks the bundle beside the tree (the current folder) and
# runs scripts/gpu-check.sh with the GPU.
set -uo pipefail
bundle="\$(cd "\$(dirname "\${BASH_SOURCE[0]}")" && pwd)"
tree="\$PWD"
[ -f "\$tree/scripts/gpu-check.sh" ] || { echo "run.sh: run it from the tree's root" >&2; exit 2; }
# A link at \$2 to \$1, where there is nothing or a link (of an earlier run); a folder stays.
link_to() {
    if [ -L "\$2" ] || [ ! -e "\$2" ]; then
        mkdir -p "\$(dirname "\$2")" && ln -sfn "\$1" "\$2"
    else
        echo "run.sh: \$2 is not a link: the tests use what is there"
    fi
}
link_to "\$tree" "$source_dir"  # where the tests look for the tree
if [ -f "\$bundle/course.tar" ] && [ ! -e "$source_dir/../shared/course-scenes" ]; then
    mkdir -p "$source_dir/../shared" && tar -xf "\$bundle/course.tar" -C "$source_dir/../shared"
fi
build="\$(mktemp -d)"
trap 'rm -rf "\$build"' EXIT
tar -xJf "\$bundle/bundle.tar.xz" -C "\$build"
link_to "\$build/bin" "$build_dir"  # where the tests look for clrender and its test cache
export LD_LIBRARY_PATH="\$build/lib"
if ! "\$build/bin/clrender" --version > /dev/null 2>&1; then
    export LD_LIBRARY_PATH="\$build/lib:\$build/lib/fallback"
    echo "run.sh: with the bundle's libstdc++"
fi
if ! "\$build/bin/clrender" --list-devices 2>&1 | grep -q '(GPU'; then
    driver="\$(find / -xdev -name 'libnvidia-opencl.so.1' 2>/dev/null | head -n 1)"
    if [ -n "\$driver" ]; then  # NVIDIA's OpenCL driver, which no .icd file names here
        mkdir -p "\$build/icd" && echo "\$driver" > "\$build/icd/nvidia.icd"
        export OCL_ICD_VENDORS="\$build/icd"
    fi
fi
cd "$source_dir"
CLRENDER_BUILD_DIR="\$build/bin" GPU_CHECK_OUT="\${GPU_CHECK_OUT:-/tmp/gpu-check}" \\
    GPU_CHECK_CPU_IMAGES="\$bundle/cpu-images" bash scripts/gpu-check.sh
EOF
chmod +x "$out/run.sh"
echo "gpu-bundle.sh: $out ($(du -sh "$out" | cut -f1)); on the GPU machine, from the tree's root: bash $out/run.sh"
