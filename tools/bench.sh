#!/bin/bash
# `make bench ARGS="--reps 3 --letter N"`: see tools/bench.py.
set -eu
source "$(dirname "$0")/env.sh"
source_workspace
export WS
cd "$REPO"
exec "$ROS_PYTHON" tools/bench.py "$@"
