# The folders of a benchmark script, sourced at its start:
#   . "$(dirname "$0")/bench_dirs.sh" NAME "${1:-}" "${2:-}"
# sets root (the checkout), build (the script's BUILD_DIR argument, else root/build), work (its
# WORK_DIR argument, else a fresh /tmp/sagrid-NAME.XXXXXX; created; absolute) and sagrid.
root=$(cd "$(dirname "$0")/../.." && pwd)
build=$(cd "${2:-$root/build}" && pwd)
work=${3:-$(mktemp -d "/tmp/sagrid-$1.XXXXXX")}
mkdir -p "$work"
work=$(cd "$work" && pwd)
sagrid=$build/sagrid
