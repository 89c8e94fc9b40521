#!/bin/bash
# Build the catkin workspace in .ws/: this package and, only where no
# turtlesim is installed (or TURTLE_LETTERS_BUNDLED_SIM=1), the bundled one.
set -eu
source "$(dirname "$0")/env.sh"

# The package is linked in part by part rather than as the whole repository:
# a link to the repository root would put .ws inside itself, and tools that
# walk a package's folder (rosrun, rospack) would loop.
mkdir -p "$WS/src"
[ -L "$WS/src/turtle_letters" ] && rm "$WS/src/turtle_letters"
mkdir -p "$WS/src/turtle_letters"
for part in package.xml CMakeLists.txt setup.py README.md launch scripts src test; do
  ln -sfn "$REPO/$part" "$WS/src/turtle_letters/$part"
done

installed_turtlesim() {
  # Look in the installed ROS prefixes only, never in our own workspace.
  local prefix
  for prefix in ${CMAKE_PREFIX_PATH:+${CMAKE_PREFIX_PATH//:/ }} /usr; do
    case "$prefix" in "$WS"*) continue ;; esac
    [ -f "$prefix/share/turtlesim/package.xml" ] && return 0
  done
  return 1
}

if [ "${TURTLE_LETTERS_BUNDLED_SIM:-0}" != 1 ] && installed_turtlesim; then
  sim=installed
else
  sim=bundled
fi

if [ "$sim" = bundled ]; then
  ln -sfn "$REPO/sim/turtlesim" "$WS/src/turtlesim"
else
  rm -f "$WS/src/turtlesim"
fi

# catkin_make re-runs CMake by itself only when its arguments change, not when
# a package comes or goes: force it when the simulator choice changed.
force=""
if [ "$(cat "$WS/.simulator" 2>/dev/null)" != "$sim" ]; then
  force=--force-cmake
fi

echo "make build: workspace $WS, simulator: $sim"
catkin_make -C "$WS" $force "${CATKIN_ARGS[@]}" >"$WS/build.log" 2>&1 || {
  tail -n 40 "$WS/build.log" >&2
  echo "make build: catkin_make failed; the whole log is $WS/build.log" >&2
  exit 1
}
echo "$sim" >"$WS/.simulator"
echo "make build: done. For a shell with everything: source $WS/devel/setup.bash"
