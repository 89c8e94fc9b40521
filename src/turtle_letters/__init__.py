"""turtle_letters, the lab "control of the turtlesim using ROS": start with
controller.TurtleController, then lab.py (the six calls of the N), turtle.py
(rotate and move) and talker.py; each folder below holds one concern."""
