#!/bin/bash
# Install what the project needs, and nothing when all of it is present.
set -eu
source "$(dirname "$0")/env.sh"

# On every platform: the compiler catkin's top-level CMake project needs, and
# what the tests and the headless run use. numpy, tf and tf2 are also what a
# course's ROS Noetic desktop machine offers the student code the grader runs,
# and matplotlib (rqt_plot's, in every desktop install) only that;
# Tesseract reads the letters a person sees, scipy measures how far ink lies
# from a letter's strokes; fonttools with Liberation's and DejaVu's bold fonts
# give block letters (the reader's, and the benchmark's); pytest-xdist runs
# the unit tests two at a time.
COMMON="bubblewrap g++ git hershey-fonts-data iproute2 python3-numpy python3-pytest
        python3-pytest-xdist python3-pyqt5 python3-tqdm python3-yaml python3-tornado tmux
        tesseract-ocr tesseract-ocr-eng python3-tesserocr python3-pil python3-fonttools
        fonts-dejavu-core fonts-liberation python3-scipy python3-matplotlib"
if [ -d /opt/ros/noetic ]; then
  # Ubuntu 20.04 with ROS Noetic: the real turtlesim. (Its chromium is a snap:
  # the viewer's browser test says it has no chromium-driver there, and skips.)
  WANT="$COMMON ros-noetic-ros-base ros-noetic-turtlesim ros-noetic-rostest ros-noetic-std-srvs
        ros-noetic-geometry-msgs ros-noetic-message-generation ros-noetic-message-runtime
        ros-noetic-actionlib ros-noetic-actionlib-msgs ros-noetic-sensor-msgs ros-noetic-image-view
        ros-noetic-tf ros-noetic-tf2-ros"
else
  # Debian (12) or Ubuntu without /opt/ros: Debian's ROS 1 packages; the
  # simulator comes bundled, since Debian has no turtlesim.
  WANT="$COMMON ros-core-dev python3-rospy python3-rostest python3-roslaunch python3-rostopic
        python3-rosservice rosout python3-std-msgs python3-std-srvs python3-geometry-msgs
        ros-std-srvs libstd-srvs-dev rosbash rospack-tools python3-svgelements
        python3-actionlib ros-actionlib-msgs libactionlib-msgs-dev python3-actionlib-msgs
        python3-sensor-msgs ros-image-view chromium chromium-driver python3-selenium
        python3-tf libtf-dev python3-tf2-ros libtf2-ros-dev"
fi

if ! command -v dpkg-query >/dev/null || ! command -v apt-get >/dev/null; then
  echo "make deps: this is not a Debian or Ubuntu machine (no apt-get)." >&2
  echo "  Install ROS 1 Noetic (rospy, roslaunch, rostest, catkin, std_msgs, std_srvs," >&2
  echo "  geometry_msgs, message_generation, and turtlesim if available), PyQt5, pytest" >&2
  echo "  and tmux yourself, then run 'make build'." >&2
  exit 1
fi

# The SVG reader: Debian packages it; Ubuntu 20.04 does not, so there it
# comes from PyPI, for the system Python that ROS runs on.
svgelements_from_pypi() {
  [ -d /opt/ros/noetic ] || return 0
  /usr/bin/python3 -c 'import svgelements' 2>/dev/null && return 0
  echo "make deps: installing svgelements (PyPI) for /usr/bin/python3"
  $SUDO apt-get install -y -qq python3-pip >/dev/null && $SUDO /usr/bin/python3 -m pip install -q svgelements
}

missing=""
for pkg in $WANT; do
  status=$(dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null || true)
  [ "$status" = "install ok installed" ] || missing="$missing $pkg"
done

SUDO=""
if [ -z "$missing" ]; then
  [ "$(id -u)" = 0 ] || ! command -v sudo >/dev/null || SUDO=sudo
  svgelements_from_pypi
  echo "make deps: everything needed is installed."
  exit 0
fi

if [ "$(id -u)" != 0 ]; then
  if command -v sudo >/dev/null; then SUDO=sudo; else
    echo "make deps: missing packages:$missing" >&2
    echo "  Not root and no sudo: install them as root with apt-get install." >&2
    exit 1
  fi
fi
echo "make deps: installing:$missing"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
# shellcheck disable=SC2086
if ! $SUDO apt-get install -y -qq $missing; then
  echo "make deps: apt-get could not install:$missing" >&2
  echo "  Debian 12 (bookworm) and Ubuntu 20.04 with ROS Noetic are supported." >&2
  exit 1
fi
svgelements_from_pypi
