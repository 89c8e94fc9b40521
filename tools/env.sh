# Sourced by the other tools: one place that sets up the ROS environment.
# shellcheck shell=bash

REPO="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
# The catkin workspace `make build` makes (the build tests make others).
WS="${TURTLE_LETTERS_WS:-$REPO/.ws}"
ROS_PYTHON=/usr/bin/python3     # ROS 1 runs on the system Python 3 only
# Every catkin_make call passes the same arguments: different ones make it
# configure the workspace all over again.
CATKIN_ARGS=(-DPYTHON_EXECUTABLE="$ROS_PYTHON" -DCATKIN_ENABLE_TESTING=ON -DCMAKE_BUILD_TYPE=Release)

# Nodes' and roslaunch's lines as they come, even into a pipe (make run |
# tee log): Python block-buffers output that does not go to a terminal.
export PYTHONUNBUFFERED=1

# A pyenv/conda/venv python3 first on PATH has no rospy; tools that say
# `env python3` (rostest's hztest, for one) must find the system one.
export PATH="/usr/bin:/bin:$PATH"
unset PYTHONHOME

# Stay on this machine unless the user chose otherwise.
if [ -z "${ROS_IP:-}${ROS_HOSTNAME:-}" ]; then
  export ROS_IP=127.0.0.1
fi
export ROS_MASTER_URI="${ROS_MASTER_URI:-http://127.0.0.1:11311}"

ros_source() {
  # setup.bash scripts read unset variables: relax `set -u` around them.
  local had_u=0
  case $- in *u*) had_u=1; set +u ;; esac
  # shellcheck disable=SC1090
  source "$1"
  [ "$had_u" = 1 ] && set -u
  return 0
}

# Not when ROS is set up already: sourcing it again would drop the underlay
# workspaces the user's shell has sourced.
if [ -z "${ROS_DISTRO:-}" ] && [ -f /opt/ros/noetic/setup.bash ]; then
  ros_source /opt/ros/noetic/setup.bash
fi

source_workspace() {
  if [ -f "$WS/devel/setup.bash" ]; then
    ros_source "$WS/devel/setup.bash"
  else
    echo "The workspace is not built yet: run 'make build' first." >&2
    return 1
  fi
}

# Qt (the simulator, the picture checks) warns when this is unset; give it
# the folder it would pick anyway.
if [ -z "${XDG_RUNTIME_DIR:-}" ]; then
  export XDG_RUNTIME_DIR="/tmp/runtime-$(id -u)"
  mkdir -p -m 700 "$XDG_RUNTIME_DIR"
fi
