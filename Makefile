# Two commands do everything on a fresh machine: `make run` and `make test`.
# Each target runs what it needs first; the work is in tools/.
SHELL := /bin/bash
ARGS ?=

.PHONY: deps build run test bench clean

deps:
	@bash tools/deps.sh

build: deps
	@bash tools/build.sh

run: build
	@bash tools/run.sh $(ARGS)

test: build
	@bash tools/test.sh

bench: build
	@bash tools/bench.sh $(ARGS)

clean:
	rm -rf .ws
