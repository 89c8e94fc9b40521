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
for part in package.xml CMakeLists.txt setup.py README.md config doc launch web scripts src srv action test; do
  ln -sfn "$REPO/$part" "$WS/src/turtle_letters/$part"
done

without_workspace() {
  # A path list without our own workspace's entries.
  local entry kept=""
  local IFS=:
  for entry in $1; do
    case "$entry" in "$WS"|"$WS"/*|"") ;; *) kept="${kept:+$kept:}$entry" ;; esac
  done
  echo "$kept"
}

installed_turtlesim() {
  # Where ROS itself would find turtlesim, leaving our workspace out: on the
  # package path (a source or devel-space underlay puts its src/ there), then
  # in the install prefixes, as catkin's find_package does.
  local found prefix
  found=$(ROS_PACKAGE_PATH=$(without_workspace "${ROS_PACKAGE_PATH:-}") \
          rospack find turtlesim 2>/dev/null) && [ -n "$found" ] && { echo "$found"; return 0; }
  for prefix in $(without_workspace "${CMAKE_PREFIX_PATH:-}" | tr : ' ') /usr; do
    [ -f "$prefix/share/turtlesim/package.xml" ] && { echo "$prefix/share/turtlesim"; return 0; }
  done
  return 1
}

if [ "${TURTLE_LETTERS_BUNDLED_SIM:-0}" != 1 ] && found=$(installed_turtlesim); then
  sim="installed:$found"
  echo "make build: turtlesim: the one installed at $found"
  rm -f "$WS/src/turtlesim"
else
  sim=bundled
  if [ "${TURTLE_LETTERS_BUNDLED_SIM:-0}" = 1 ]; then
    echo "make build: turtlesim: the bundled one (TURTLE_LETTERS_BUNDLED_SIM=1), $REPO/sim/turtlesim"
  else
    echo "make build: turtlesim: the bundled one, $REPO/sim/turtlesim (none found on" \
         "ROS_PACKAGE_PATH or CMAKE_PREFIX_PATH)"
  fi
  ln -sfn "$REPO/sim/turtlesim" "$WS/src/turtlesim"
fi

# A build of the other simulator leaves its turtlesim in devel/ (and install/),
# found before the one now chosen: start those afresh when the choice changes.
if [ -f "$WS/.simulator" ] && [ "$(cat "$WS/.simulator")" != "$sim" ]; then
  echo "make build: the simulator changed since the last build: building afresh"
  rm -rf "$WS/build" "$WS/devel" "$WS/install"
fi

echo "make build: workspace $WS"
catkin_make -C "$WS" "${CATKIN_ARGS[@]}" >"$WS/build.log" 2>&1 || {
  tail -n 40 "$WS/build.log" >&2
  echo "make build: catkin_make failed; the whole log is $WS/build.log" >&2
  exit 1
}
echo "$sim" >"$WS/.simulator"
echo "make build: done. For a shell with everything: source $WS/devel/setup.bash"
