"""Many students on one turtlesim: parts of the canvas, the room, spares, liveness, network."""
