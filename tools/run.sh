#!/bin/bash
# `make run`: the lab, from this terminal. Extra arguments go to roslaunch.
set -eu
source "$(dirname "$0")/env.sh"
source_workspace

args=()
for arg in "$@"; do
  # roslaunch starts the controller in ROS_HOME: a file is named from here.
  case "$arg" in
    svg:=/*|svg:=) ;;
    svg:=*) arg="svg:=$PWD/${arg#svg:=}" ;;
  esac
  args+=("$arg")
done
picture=""
if [ -z "${DISPLAY:-}${WAYLAND_DISPLAY:-}" ] && [ "$(cat "$WS/.simulator")" = bundled ]; then
  picture="${TURTLE_LETTERS_PICTURE:-$REPO/.ws/canvas.png}"
  echo "make run: no display, so the simulator runs headless; when you stop it (Ctrl-C)"
  echo "          the picture is saved to $picture"
  args=("canvas_png:=$picture" "${args[@]}")
elif [ -z "${DISPLAY:-}${WAYLAND_DISPLAY:-}" ]; then
  echo "make run: no display, so turtlesim runs headless (the real turtlesim cannot save a picture)."
fi
echo "make run: press P in this terminal to draw; from another terminal:"
echo "          rostopic pub -1 /chatter std_msgs/String \"data: 'P'\""

# Ctrl-C reaches roslaunch from the terminal; this script only waits for it
# to finish so that it can say where the picture went.
trap true INT TERM
started=$(date +%s)
roslaunch turtle_letters draw_letter.launch "${args[@]}" || status=$?
if [ -n "$picture" ] && [ -f "$picture" ] && [ "$(stat -c %Y "$picture")" -ge "$started" ]; then
  echo "make run: the picture is in $picture"
fi
exit "${status:-0}"
