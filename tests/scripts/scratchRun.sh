# Sourced by the test scripts that take <source dir> <binary dir>: a scratch directory $work
# removed at exit, the build's applications on PATH, GPIC_DIR for the tutorials' scripts.
set -euo pipefail
source_dir=$1 binary_dir=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export GPIC_DIR=$source_dir
export PATH=$binary_dir/bin:$PATH
