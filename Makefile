# Relief's two set-up commands (see README.md). Both install what they need first.
#   make run    build the editor (Release) and open it on the bundled bricks sample
#   make test   build with warnings as errors, AddressSanitizer and UBSan, run every test
#               under Xvfb (what CI runs, through .ci/run)
#   make package  a Release build with Debian's hardening flags, packaged as a .deb by CPack
#               (build/package/relief_<version>_amd64.deb; README.md, "Install")
JOBS ?= $(shell nproc)
RUN_BUILD := build/release
PACKAGE_BUILD := build/package

.PHONY: run build test package deps format format-check clean

deps:
	tools/install-deps.sh

build: deps
	cmake -S . -B $(RUN_BUILD) -G Ninja -DCMAKE_BUILD_TYPE=Release -DRELIEF_BUILD_TESTS=OFF
	cmake --build $(RUN_BUILD) -j $(JOBS)

run: build
	$(RUN_BUILD)/app/relief $(ARGS)

test: deps
	tools/run-tests.sh

# dpkg-buildflags gives the compiler and linker flags Debian builds packages with (stack
# protector, fortify, relro, bind-now), which lintian checks for.
package: deps
	cmake -S . -B $(PACKAGE_BUILD) -G Ninja -DCMAKE_BUILD_TYPE=Release -DRELIEF_BUILD_TESTS=OFF \
	  -DRELIEF_BUILD_TOOLS=OFF -DRELIEF_PRECOMPILED_HEADERS=OFF -DRELIEF_UNITY_BUILD=OFF \
	  -DCMAKE_CXX_FLAGS="$$(DEB_BUILD_MAINT_OPTIONS=hardening=+all dpkg-buildflags --get CXXFLAGS) $$(DEB_BUILD_MAINT_OPTIONS=hardening=+all dpkg-buildflags --get CPPFLAGS)" \
	  -DCMAKE_EXE_LINKER_FLAGS="$$(DEB_BUILD_MAINT_OPTIONS=hardening=+all dpkg-buildflags --get LDFLAGS)"
	cmake --build $(PACKAGE_BUILD) -j $(JOBS)
	cd $(PACKAGE_BUILD) && cpack

format:
	tools/check-format.sh --fix

format-check:
	tools/check-format.sh

clean:
	rm -rf build
