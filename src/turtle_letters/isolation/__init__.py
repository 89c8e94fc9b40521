"""What keeps untrusted code and files in their place: the sandbox, its cgroups, files read safely."""
