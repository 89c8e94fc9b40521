"""The turtle's ROS plumbing: its pose stream, its cmd_vel, its pen and the
canvas. The stop on shutdown lives here, so nothing that moves the turtle can
leave it coasting."""
import queue
import threading
import time

import rospy
from geometry_msgs.msg import Twist
from std_srvs.srv import Empty
from turtlesim.msg import Pose
from turtlesim.srv import SetPen

POSE_TIMEOUT = 1.0      # s without a pose: the simulator is gone
POSES_KEPT = 1000       # 16 s of ticks: the drawing thread reads far faster


class DrawingAborted(RuntimeError):
    pass


class TurtleDriver:
    """Subscribes `turtle1/pose`; publishes `turtle1/cmd_vel`; calls
    `turtle1/set_pen` and `clear`."""

    def __init__(self):
        self._poses = queue.Queue(maxsize=POSES_KEPT)
        self.latest_pose = None
        self._publish_lock = threading.Lock()
        self._stopping = False                 # once set, only the stop goes out
        self._cmd_vel = rospy.Publisher('turtle1/cmd_vel', Twist, queue_size=10)
        self._set_pen = rospy.ServiceProxy('turtle1/set_pen', SetPen)
        self._clear = rospy.ServiceProxy('clear', Empty)
        rospy.Subscriber('turtle1/pose', Pose, self._on_pose, queue_size=100, tcp_nodelay=True)
        rospy.on_shutdown(self._on_shutdown)

    def _on_pose(self, msg):
        self.latest_pose = msg
        if self._poses.full():          # idle: nobody reads; keep only the newest
            self._poses.get_nowait()
        self._poses.put_nowait(msg)

    def wait_for_pose(self):
        """The latest pose, once there is one; says once that it waits."""
        if self.latest_pose is None:
            rospy.loginfo('Waiting for turtlesim: no pose on %s yet; the drawing starts when it comes',
                          rospy.resolve_name('turtle1/pose'))
        while self.latest_pose is None and not rospy.is_shutdown():
            try:
                self._poses.get(timeout=0.5)
            except queue.Empty:
                pass
        if self.latest_pose is None:
            raise DrawingAborted('shutting down')
        return self.latest_pose

    def drop_stale_poses(self):
        """Poses from before now would count ticks that are not ours."""
        while not self._poses.empty():
            self._poses.get_nowait()

    def next_pose(self):
        try:
            pose = self._poses.get(timeout=POSE_TIMEOUT)
        except queue.Empty:
            raise DrawingAborted(f'no pose from turtlesim for {POSE_TIMEOUT:g} s') from None
        if rospy.is_shutdown():
            raise DrawingAborted('shutting down')
        return pose

    def publish(self, command):
        twist = Twist()
        twist.linear.x, twist.linear.y, twist.angular.z = command
        with self._publish_lock:
            if not self._stopping:
                self._cmd_vel.publish(twist)

    def stop(self):
        """Stop the turtle now rather than let it coast for turtlesim's 1 s timeout."""
        try:
            self.publish((0.0, 0.0, 0.0))
        except rospy.ROSException:
            pass    # already shut down: the shutdown hook sent the stop

    def set_pen(self, pen, down):
        """Lowering the pen sets its colour and width too (turtlesim's set_pen)."""
        self._set_pen(*pen, 0 if down else 1)

    def clear(self):
        self._clear()

    def _on_shutdown(self):
        """The last word on cmd_vel is a stop, even with a drawing under way."""
        with self._publish_lock:
            self._stopping = True
            self._cmd_vel.publish(Twist())
        # The publisher's queue thread sends it; give it a moment before
        # rospy closes the topic (the turtle is at most one tick away).
        time.sleep(0.1)
