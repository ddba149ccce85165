#!/usr/bin/env bash
# Run time against error (docs/error-benchmark.md): builds clrender_error_bench (Release, into
# build-error/ or $CLRENDER_ERROR_BUILD_DIR), runs it, and writes docs/error-benchmark.md and
# .json from the run and docs/error-benchmark.png from the JSON. Arguments go to the
# benchmark, e.g.
#   scripts/error_bench.sh --target-psnr 40
#   scripts/error_bench.sh --size 960x540 --repeat 5 --scenes showcase@48,demo
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${CLRENDER_ERROR_BUILD_DIR:-$root/build-error}"

bash "$root/scripts/install-deps.sh" >&2
# The plot needs matplotlib, which only this script uses, so it is installed here rather than
# by install-deps.sh. Debian's python3-matplotlib goes to the system Python, which a python3
# earlier on PATH (pyenv, a virtual environment) does not see: use whichever has it, and
# install the package if neither does.
python=python3
if ! "$python" -c 'import matplotlib' 2>/dev/null; then
  python=/usr/bin/python3
  if ! "$python" -c 'import matplotlib' 2>/dev/null; then
    sudo=""
    [ "$(id -u)" -eq 0 ] || sudo="sudo"
    $sudo apt-get update -q >&2
    DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -q --no-install-recommends python3-matplotlib >&2
  fi
fi

cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DCLRENDER_BUILD_BENCH=ON >&2
cmake --build "$build" -j"$(nproc)" --target clrender_error_bench >&2
# From the repository, so that the command line quoted in the document has short paths.
cd "$root"
"$build/clrender_error_bench" --json docs/error-benchmark.json --markdown docs/error-benchmark.md "$@"
"$python" scripts/plot_error_bench.py docs/error-benchmark.json docs/error-benchmark.png
echo "error_bench: wrote docs/error-benchmark.md, .json and .png" >&2
