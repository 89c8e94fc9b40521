"""The room seen from any seat: the shared canvas rebuilt from the turtles' poses, served as a live page and an image."""
