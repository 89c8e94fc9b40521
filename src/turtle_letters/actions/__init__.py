"""A drawing as a request: which are taken (jobs), the draw action's server and client, and progress."""
