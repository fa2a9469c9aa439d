# A batch pipeline for many materials with relief-cli and make (docs/pipelines.md). For every
# <name>_height.png in IN it makes, in OUT:
#   <name>_normal.png     normal map from the height (Scharr kernel, OpenGL convention)
#   <name>_ao.png         ambient occlusion from the height
#   <name>_normal.dds     the normal map in BC5 with mips (two channels, Z rebuilt)
#   <name>_preview.png    a POM render of the height with the new normal map
# Each relief-cli call is independent, so `make -j N` runs N at once and a second run redoes
# only what changed. Usage:
#   make -f docs/examples/materials.mk -j4 IN=scans OUT=out [CLI=relief-cli] [STRENGTH=8]
# The preview needs an X display: run under xvfb-run -a -s '-noreset' on a server (without
# -noreset Xvfb resets between jobs and a job connecting meanwhile is refused).
CLI ?= relief-cli
IN ?= in
OUT ?= out
STRENGTH ?= 8

heights := $(wildcard $(IN)/*_height.png)
names := $(patsubst $(IN)/%_height.png,%,$(heights))

all: $(foreach n,$(names),$(addprefix $(OUT)/$(n)_,normal.png normal.dds ao.png preview.png))

$(OUT):
	mkdir -p $@

$(OUT)/%_normal.png: $(IN)/%_height.png | $(OUT)
	$(CLI) generate normal --in $< --out $@ --kernel scharr --strength $(STRENGTH)

$(OUT)/%_ao.png: $(IN)/%_height.png | $(OUT)
	$(CLI) generate ao --in $< --out $@

$(OUT)/%_normal.dds: $(OUT)/%_normal.png
	$(CLI) compress --in $< --format bc5 --normal --mips --out $@

$(OUT)/%_preview.png: $(IN)/%_height.png $(OUT)/%_normal.png
	$(CLI) render --height $< --normal $(OUT)/$*_normal.png --technique pom --size 640x360 \
	  --out $@

.PHONY: all
# A failed command leaves no half-written target behind (relief-cli writes atomically too).
.DELETE_ON_ERROR:
