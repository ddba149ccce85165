#!/usr/bin/env bash
# Intel's CPU OpenCL runtime as a second OpenCL implementation beside PoCL, for checking the
# kernels on two compilers (scripts/second-opencl.sh, docs/opencl-devices.md). From PyPI's
# wheels only, unpacked into a user folder: nothing is pip-installed and nothing under /etc
# changes. Idempotent: the wheels and the unpacked runtime are kept and reused.
#
#   scripts/install-intel-opencl.sh        folder: $CLRENDER_INTEL_OPENCL_DIR, else
#                                          ~/.cache/clrender-intel-opencl (beside, not inside,
#                                          clrender's own cache folder, whose sub-folders
#                                          clrender manages)
# Then, to see Intel's device beside the system's (clrender --list-devices):
#   source ~/.cache/clrender-intel-opencl/env.sh
# which sets OCL_ICD_VENDORS (a vendors folder holding the system's .icd files and Intel's)
# and LD_LIBRARY_PATH (Intel's libraries, without its own libOpenCL.so, so that Debian's ICD
# loader stays the one clrender uses).
set -euo pipefail
prefix="${CLRENDER_INTEL_OPENCL_DIR:-$HOME/.cache/clrender-intel-opencl}"
# Pinned, so that CI checks against one known runtime; raise them together.
wheels=(intel-opencl-rt==2026.2.0 intel-cmplr-lib-rt==2026.2.0 tbb==2023.2.0)

mkdir -p "$prefix/wheels"
if [ "$(find "$prefix/wheels" -name '*.whl' | wc -l)" -lt "${#wheels[@]}" ]; then
    python3 -m pip download --quiet --no-deps --dest "$prefix/wheels" "${wheels[@]}"
fi

# The runtime looks for its compiler and builtin libraries beside libintelocl.so, so every
# wheel's data/lib goes into one folder; unpacked under a temporary name, then renamed, so an
# interrupted run never leaves a half-unpacked lib/.
if [ ! -f "$prefix/lib/libintelocl.so" ]; then
    rm -rf "$prefix/lib.partial"
    python3 - "$prefix/wheels" "$prefix/lib.partial" <<'PY'
import os, sys, zipfile
wheels, out = sys.argv[1], sys.argv[2]
os.makedirs(out)
for name in sorted(os.listdir(wheels)):
    with zipfile.ZipFile(os.path.join(wheels, name)) as wheel:
        for member in wheel.infolist():
            parts = member.filename.split("/")
            if len(parts) != 4 or parts[1:3] != ["data", "lib"] or not parts[3]:
                continue
            if parts[3].startswith("libOpenCL.so"):
                continue  # Intel's own ICD loader: Debian's must stay the one that loads
            target = os.path.join(out, parts[3])
            with wheel.open(member) as source, open(target, "wb") as sink:
                sink.write(source.read())
            os.chmod(target, 0o755)
PY
    rm -rf "$prefix/lib"
    mv "$prefix/lib.partial" "$prefix/lib"
fi

# The vendors folder replaces /etc/OpenCL/vendors for the ICD loader: the system's drivers
# (PoCL) and Intel's CPU runtime by absolute path.
mkdir -p "$prefix/vendors"
find "$prefix/vendors" -name '*.icd' -delete
for icd in /etc/OpenCL/vendors/*.icd; do
    [ -e "$icd" ] && cp "$icd" "$prefix/vendors/"
done
echo "$prefix/lib/libintelocl.so" > "$prefix/vendors/intel-cpu.icd"

cat > "$prefix/env.sh" <<ENV
export OCL_ICD_VENDORS="$prefix/vendors"
export LD_LIBRARY_PATH="$prefix/lib\${LD_LIBRARY_PATH:+:\$LD_LIBRARY_PATH}"
ENV
echo "install-intel-opencl.sh: Intel's CPU OpenCL runtime in $prefix; use it with: source $prefix/env.sh"
