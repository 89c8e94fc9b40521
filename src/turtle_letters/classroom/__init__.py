"""Many students on one turtlesim: parts of the canvas, the room, spare turtles, liveness and network checks."""
