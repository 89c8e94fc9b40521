"""The lab's letter, in the lab's own words. No ROS here.

On "P", in timed mode, the controller's turtle runs exactly these six calls
(turtle.py: rotate turns counter-clockwise at ~angular_speed, move drives
ahead at ~linear_speed, each timed). The turtle starts them at the letter's
lower-left corner, facing +x, as turtle1 stands when turtlesim starts.

Everything else in the package takes the N from here: the builtin font's N
is the path these calls trace (letters/font.py), so the layout, the
feedback and smooth modes and the grader all use the N written below.
Change a number and the turtle draws, and the grader expects, your change.
"""

LAB_SIZE = 3.0      # m: the N's height as written here; ~size scales every move


def draw_the_labs_n(turtle):
    """Rotate 90 deg, move 3.0 m, rotate 225 deg, move 3.5 m, rotate 135 deg, move 3.0 m."""
    turtle.rotate(90)
    turtle.move(3.0)
    turtle.rotate(225)
    turtle.move(3.5)
    turtle.rotate(135)
    turtle.move(3.0)
