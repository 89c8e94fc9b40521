"""turtlesim's other executables, as the bundled simulator has them: the
keys turtle_teleop_key reads, and draw_square's steps, on the simulator's
own kinematics. No ROS here."""
import math

from turtlesim_compat.draw_square import Square
from turtlesim_compat.teleop import presses
from turtlesim_compat.world import TICK_SECONDS, World


def test_the_arrow_keys_move_and_turn_and_q_quits():
    assert presses(b'\x1b[A\x1b[B') == ([(1.0, 0.0), (-1.0, 0.0)], False)
    assert presses(b'x\x1b[D\x1b[C') == ([(0.0, 1.0), (0.0, -1.0)], False)
    assert presses(b'\x1b[Aq\x1b[A') == ([(1.0, 0.0)], True)
    assert presses(b'P\r') == ([], False)       # what the grader types is no arrow


class Sampled:
    def __init__(self, turtle):
        self.x, self.y, self.theta = turtle.x, turtle.y, turtle.theta
        self.linear_velocity, self.angular_velocity = turtle.linear_speed, turtle.angular


def test_draw_square_drives_a_square_of_2_m_and_comes_back():
    turtle, square, corners = World().spawn(5.544445, 5.544445, 0.0), Square(), []
    for tick in range(4000):
        was_turning = square.turning
        linear, angular = square.command(Sampled(turtle))
        turtle.command(linear, 0.0, angular, tick * TICK_SECONDS)
        turtle.move(tick * TICK_SECONDS)
        if square.turning and not was_turning:      # a side ended: a corner
            corners.append((turtle.x, turtle.y))
    assert len(corners) >= 4
    assert math.dist(corners[0], (5.544445 + 2.0, 5.544445)) < 0.05
    assert math.dist(corners[3], (5.544445, 5.544445)) < 0.1    # round once, back at the start
