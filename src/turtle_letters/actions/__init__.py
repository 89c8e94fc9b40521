"""A drawing as a request: which are taken, the draw action's server and client, progress."""
