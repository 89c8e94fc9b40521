"""Letters and line art as strokes, where they go, and the plan that draws them: no ROS."""
