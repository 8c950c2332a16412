# cad2osmag — one-command setup, demo, tests and benchmarks.
# Everything installs on a fresh Debian 12 machine as root: `make demo` and `make test` run
# `make install` first, which is idempotent.
SHELL := /bin/bash
ROOT  := $(abspath $(dir $(lastword $(MAKEFILE_LIST))))
VENV  := $(ROOT)/.venv
PY    := $(VENV)/bin/python
APT_PACKAGES := qgis python3-qgis qgis-providers python3-venv python3-gdal gdal-bin osmium-tool xvfb \
                python3-dev build-essential libproj-dev proj-bin \
                libeigen3-dev libopencv-core-dev libopencv-imgproc-dev qttools5-dev-tools
STAMP := $(VENV)/.installed
KERNELS := algorithms/cad2osmag_kernels_aot.built

.PHONY: install kernels demo test test-quick bench bench-route evaluate evaluate-cad clean help translations package test-qgis340

help:
	@echo "make demo        install what is missing, build the sample building and convert it (out/demo/)"
	@echo "make test        install what is missing and run the whole test suite"
	@echo "make test-quick  the suite without the slow real-data tests"
	@echo "make bench       whole pipeline on every shared drawing: time, CPU, memory, figures, scaling, gallery (docs/benchmarks.md) [BENCH_ARGS=...]"
	@echo "make evaluate [DATA=dir] [OUT=dir]  score segmentation on DATA (default ../shared/data/grid_gt; any folder"
	@echo "                  laid out like it); OUT gets scores.csv and pictures of the worst maps"
	@echo "make evaluate-cad [DATA=dir]  convert every DXF/DWG of DATA (default: the shared ArchWeb plans and DWG"
	@echo "                  sheets) and print per plan: conversion, room-name texts inside an area / naming an"
	@echo "                  area of their own, largest component, areas, passages, named areas, conflicts"
	@echo "make translations  update i18n/*.ts from the sources and compile the .qm files"
	@echo "make bench-route osmAG route planning vs grid A* (docs/benchmarks.md, own section)"
	@echo "make package     build dist/cad2osmag-<version>.zip for QGIS's Install from ZIP"
	@echo "make test-qgis340  the suite on QGIS 3.40 LTR (Debian 13 root filesystem, built on first use)"

install: $(STAMP) $(KERNELS)

# the segmentation's kernels built ahead of time (scripts/build_kernels.py: no numba import per process);
# rebuilt when the kernels change; a failed build is not an error (numba or numpy run instead)
$(KERNELS): $(STAMP) algorithms/_kernels_nb.py algorithms/kernels.py scripts/build_kernels.py
	$(PY) scripts/build_kernels.py
	touch $(KERNELS)

kernels: $(KERNELS)

$(STAMP): requirements.txt requirements-dev.txt constraints-build.txt scripts/install.sh scripts/setup-profile.sh
	bash scripts/install.sh "$(APT_PACKAGES)"
	touch $(STAMP)

demo: install
	bash scripts/demo.sh

# Both cores (pytest-xdist, requirements-dev.txt): a test file stays on one worker (module fixtures are
# computed once), the heaviest files start first (tests/conftest.py). TEST_JOBS=0 runs in one process.
TEST_JOBS ?= 2
PYTEST_PAR := $(if $(filter 0,$(TEST_JOBS)),,-n $(TEST_JOBS) --dist loadfile)
test: install
	QT_QPA_PLATFORM=offscreen $(PY) -m pytest tests -ra $(PYTEST_PAR)

test-quick: install
	QT_QPA_PLATFORM=offscreen $(PY) -m pytest tests -ra -m "not slow" $(PYTEST_PAR)

bench: install
	$(PY) scripts/bench.py --write docs/benchmarks.md $(BENCH_ARGS)

bench-route: install
	$(PY) scripts/bench_route.py --pairs 50 --write docs/benchmarks.md

DATA ?=
OUT ?=
evaluate: install
	$(PY) scripts/evaluate_grids.py $(if $(DATA),--data $(DATA),) $(if $(OUT),--out $(OUT),)

evaluate-cad: install
	$(PY) scripts/evaluate_cad.py $(if $(DATA),--data $(DATA),)

# i18n/*.ts from the sources (keeps existing translations), then .qm with Qt's lrelease (qttools5-dev-tools)
translations:
	python3 i18n/update_ts.py
	lrelease i18n/cad2osmag_de.ts i18n/cad2osmag_zh_CN.ts

package:
	python3 scripts/package.py

# QGIS 3.40 LTR / Python 3.13 / numpy 2 in a Debian 13 chroot (/var/cache/cad2osmag/trixie); extra
# pytest arguments in PYTEST_ARGS, e.g. make test-qgis340 PYTEST_ARGS='-m "not slow"'
test-qgis340:
	bash scripts/qgis340-test.sh $(PYTEST_ARGS)

clean:
	rm -rf out .pytest_cache dist
