"""What the tests and the benchmark share: real nodes as processes, waits on
conditions, recorded poses, a real terminal, accuracy figures, CPU and
memory of a process."""
