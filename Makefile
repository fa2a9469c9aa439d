# Relief's two set-up commands (see README.md). Both install what they need first.
#   make run    build the editor (Release) and open it on the bundled bricks sample
#   make test   build with warnings as errors, AddressSanitizer and UBSan, run every test
#               under Xvfb (what CI runs, through .ci/run)
JOBS ?= $(shell nproc)
RUN_BUILD := build/release

.PHONY: run build test deps format format-check clean

deps:
	tools/install-deps.sh

build: deps
	cmake -S . -B $(RUN_BUILD) -G Ninja -DCMAKE_BUILD_TYPE=Release -DRELIEF_BUILD_TESTS=OFF
	cmake --build $(RUN_BUILD) -j $(JOBS)

run: build
	$(RUN_BUILD)/app/relief $(ARGS)

test: deps
	tools/run-tests.sh

format:
	tools/check-format.sh --fix

format-check:
	tools/check-format.sh

clean:
	rm -rf build
