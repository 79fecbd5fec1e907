# seispulse: quick start is `make run` and `make test` (see `make help`).
#
# deps   system packages (apt: gfortran liblapack-dev pkg-config; openmpi-bin libopenmpi-dev
#        for the MPI driver; python3-dev python3-venv for Debian's own python only) and a
#        virtual environment .venv with the Python tools
# build  meson setup + compile in build/ (the f2py extension is built with .venv's python);
#        their output goes to build/meson-logs/*-output.txt, printed only when a step fails
# run    build, then the batch driver on input/example.nml (tables go under out/)
# test   everything: meson suites, a -fcheck=all/-ffpe-trap build, install and pip checks,
#        the doc-comment checker and the API reference (FORD)
# doc    the HTML API reference of the Fortran library with FORD (installed into .venv if
#        missing): $(BUILDDIR)/doc/api/index.html
# fuzz   fuzzing campaigns, one target after the other, FUZZ_SECONDS each (default 600):
#        AFL++ on the record reader and on the driver (instrumented build in build-fuzz/),
#        atheris on the Python entry points; afl++ (apt) and atheris (pip) installed when
#        missing; exit status 1 when a crash or a hang was found (fuzz/README.md)
# build, run and test also let .venv's python `import seispulse` (pylink, below)
#
# Variables: PYTHON (interpreter the venv is made from, default python3), BUILDDIR (build).

SHELL := /bin/bash
.SHELLFLAGS := -eu -o pipefail -c
.DEFAULT_GOAL := help
.DELETE_ON_ERROR:

PYTHON   ?= python3
BUILDDIR ?= build
VENV     := .venv
VENV_BIN := $(CURDIR)/$(VENV)/bin
VENV_PY  := $(VENV_BIN)/python
STAMP    := $(VENV)/.seispulse-deps
PIP_PKGS := 'numpy>=1.24' meson meson-python ninja pytest mpmath scipy matplotlib pyslammer eqsig \
            pandas hypothesis
# meson and ninja from the venv (ninja is found on PATH)
MESON    := PATH="$(VENV_BIN):$$PATH" $(VENV_BIN)/meson
DRIVER   := $(BUILDDIR)/driver/seispulse
EXAMPLE  := input/example.nml

FUZZ_SECONDS ?= 600

.PHONY: help deps sysdeps venv pylink build run test doc clean fuzz fuzzdeps

help:
	@echo 'seispulse make targets:'
	@echo '  make run     build, then run the driver on $(EXAMPLE) (tables go under out/)'
	@echo '  make test    build and run every test suite; last line "N passed, N failed"'
	@echo '  make build   configure ($(BUILDDIR)/, meson) and compile only'
	@echo '  make doc     HTML API reference with FORD: $(BUILDDIR)/doc/api/index.html'
	@echo '  make fuzz    fuzz the record reader, the driver and Python, FUZZ_SECONDS=$(FUZZ_SECONDS) each'
	@echo '  make deps    install system packages if missing and the .venv Python tools'
	@echo '  make pylink  let .venv/bin/python import seispulse from $(BUILDDIR)/python (build, run'
	@echo '               and test do it too)'
	@echo '  make clean   remove build directories (keeps .venv; drops the link into them)'
	@echo 'Variables: PYTHON=$(PYTHON) (interpreter for .venv)'

deps: sysdeps $(STAMP)

# System packages. Cheap checks; apt-get only runs when something is missing. Open MPI
# (mpifort, mpirun) makes the driver the MPI build (meson option mpi, auto) and lets make
# test run it over ranks; without apt-get (or root/sudo) it is only reported missing.
# Python headers and venv support come from apt only for Debian's own /usr python; any
# other interpreter (pyenv, conda, uv, ...) ships its own.
PY_HAS_HEADERS := import os, sys, sysconfig; \
    sys.exit(not os.path.isfile(os.path.join(sysconfig.get_paths()["include"], "Python.h")))
PY_HAS_VENV    := import venv, ensurepip
PY_IS_DEBIAN   := import sys; sys.exit(not sys.base_prefix == "/usr")

sysdeps:
	@command -v $(PYTHON) >/dev/null 2>&1 || { \
	    echo "error: '$(PYTHON)' not found; install Python 3 (apt-get install python3) or set PYTHON=..." >&2; \
	    exit 1; }; \
	pkgs=""; missing=""; \
	for p in gfortran gcc pkg-config; do \
	    command -v $$p >/dev/null 2>&1 || missing="$$missing $$p"; done; \
	if [ -z "$$missing" ] && ! pkg-config --exists lapack; then missing=" lapack.pc"; fi; \
	[ -z "$$missing" ] || pkgs=" gfortran liblapack-dev pkg-config"; \
	mpipkgs=""; \
	{ command -v mpifort && command -v mpirun; } >/dev/null 2>&1 || mpipkgs=" openmpi-bin libopenmpi-dev"; \
	pylack=""; pypkgs=""; \
	$(PYTHON) -c '$(PY_HAS_HEADERS)' || { pylack="$$pylack Python.h"; pypkgs="$$pypkgs python3-dev"; }; \
	if ! $(VENV)/bin/python -c '' >/dev/null 2>&1 && ! $(PYTHON) -c '$(PY_HAS_VENV)' >/dev/null 2>&1; then \
	    pylack="$$pylack venv/ensurepip"; pypkgs="$$pypkgs python3-venv"; fi; \
	if [ -n "$$pylack" ]; then \
	    if [ -f /etc/debian_version ] && $(PYTHON) -c '$(PY_IS_DEBIAN)'; then \
	        pkgs="$$pkgs$$pypkgs"; missing="$$missing$$pylack"; \
	    else \
	        echo "error: $$($(PYTHON) -c 'import sys; print(sys.executable)') lacks:$$pylack;" \
	             "install them for that interpreter, or use another one: make PYTHON=..." >&2; \
	        exit 1; \
	    fi; \
	fi; \
	if [ -n "$$mpipkgs" ]; then \
	    if [ -z "$$pkgs" ] && { ! command -v apt-get >/dev/null 2>&1 || \
	         { [ "$$(id -u)" != 0 ] && ! command -v sudo >/dev/null 2>&1; }; }; then \
	        echo "deps: no mpifort/mpirun: the driver is built without MPI (install Open MPI" \
	             "or MPICH for the MPI build)"; \
	        exit 0; \
	    fi; \
	    missing="$$missing mpifort/mpirun"; pkgs="$$pkgs$$mpipkgs"; \
	fi; \
	[ -n "$$pkgs" ] || exit 0; \
	echo "deps: missing$$missing -> apt-get install$$pkgs"; \
	if ! command -v apt-get >/dev/null 2>&1; then \
	    echo "error: no apt-get here; install gfortran, LAPACK (with lapack.pc), pkg-config" \
	         "and the Python headers yourself" >&2; \
	    exit 1; fi; \
	if [ "$$(id -u)" = 0 ]; then sudo=""; \
	elif command -v sudo >/dev/null 2>&1; then sudo="sudo"; \
	else echo "error: need root or sudo to run: apt-get install$$pkgs" >&2; exit 1; fi; \
	$$sudo env DEBIAN_FRONTEND=noninteractive apt-get update -q; \
	$$sudo env DEBIAN_FRONTEND=noninteractive apt-get install -y -q $$pkgs; \
	for p in gfortran gcc pkg-config; do \
	    command -v $$p >/dev/null 2>&1 || { echo "error: $$p still missing after apt-get" >&2; exit 1; }; done; \
	pkg-config --exists lapack || { echo "error: pkg-config finds no lapack after apt-get" >&2; exit 1; }; \
	[ -z "$$mpipkgs" ] || { command -v mpifort && command -v mpirun; } >/dev/null 2>&1 \
	    || { echo "error: still no mpifort/mpirun after apt-get" >&2; exit 1; }; \
	$(PYTHON) -c '$(PY_HAS_HEADERS)' || { echo "error: still no Python.h after apt-get" >&2; exit 1; }; \
	$(VENV)/bin/python -c '' >/dev/null 2>&1 || $(PYTHON) -c '$(PY_HAS_VENV)' \
	    || { echo "error: still no venv/ensurepip after apt-get" >&2; exit 1; }

# Python tools in .venv, once (again when this Makefile changes). A broken venv (e.g. its
# base interpreter is gone) is recreated.
$(STAMP): Makefile | sysdeps
	@if ! $(VENV)/bin/python -c 'import sys' >/dev/null 2>&1; then \
	    echo "deps: creating $(VENV) with $(PYTHON)"; \
	    rm -rf $(VENV); \
	    $(PYTHON) -m venv $(VENV); \
	fi
	@echo "deps: pip install $(PIP_PKGS) into $(VENV)"
	$(VENV_PY) -m pip install -q --disable-pip-version-check --upgrade pip
	$(VENV_PY) -m pip install -q --disable-pip-version-check --upgrade $(PIP_PKGS)
	@touch $@

venv: $(STAMP)

# `import seispulse` from .venv: a file seispulse-build.pth in its site-packages names
# $(BUILDDIR)/python, where meson builds the package (extension and .py copies), so every
# rebuild is importable at once, with no reinstall step. Written only when it changes.
# The link follows the last make: `make build BUILDDIR=/tmp/x` points .venv there until a
# make with the default BUILDDIR (make clean drops a link into a build dir it removes). A
# seispulse pip-installed into .venv comes first on sys.path: pylink warns about it.
PTH_LINE := $(abspath $(BUILDDIR))/python
PTH_FILE = $$($(VENV_PY) -c 'import sysconfig; print(sysconfig.get_paths()["purelib"])' \
	2>/dev/null)/seispulse-build.pth
pylink: $(STAMP)
	@pth=$(PTH_FILE); \
	[ "$$(cat "$$pth" 2>/dev/null)" = '$(PTH_LINE)' ] || { \
	    echo '$(PTH_LINE)' > "$$pth"; \
	    echo "pylink: $(VENV)/bin/python imports seispulse from $(PTH_LINE) ($$pth)"; }; \
	origin=$$(cd / && $(VENV_PY) -c 'import importlib.util as u; \
	    s = u.find_spec("seispulse"); print(s.origin if s else "")' 2>/dev/null); \
	case "$$origin" in '$(PTH_LINE)'/*|"") ;; *) \
	    echo "pylink: warning: $(VENV)/bin/python imports seispulse from $$origin, not" \
	         "from $(PTH_LINE) (pip uninstall seispulse to use the build)" >&2;; esac

# Configure once; meson regenerates by itself when meson.build files change. A new venv
# (newer stamp) reconfigures, so -Dpython always names this venv's interpreter.
$(BUILDDIR)/build.ninja: $(STAMP)
	@reconf=""; [ ! -f $(BUILDDIR)/meson-private/coredata.dat ] || reconf="--reconfigure"; \
	log=$(BUILDDIR)/meson-logs/setup-output.txt; mkdir -p $(BUILDDIR)/meson-logs; \
	echo "meson setup $$reconf $(BUILDDIR) -Dpython=$(VENV_PY) (output: $$log)"; \
	$(MESON) setup $$reconf $(BUILDDIR) -Dpython=$(VENV_PY) >$$log 2>&1 || { cat $$log; exit 1; }
	@touch $@

build: sysdeps $(BUILDDIR)/build.ninja pylink
	@log=$(BUILDDIR)/meson-logs/compile-output.txt; \
	echo "meson compile -C $(BUILDDIR) (output: $$log)"; \
	$(MESON) compile -C $(BUILDDIR) >$$log 2>&1 || { cat $$log; exit 1; }; \
	! grep -B4 -E '^Warning:|: warning:' $$log || echo "*** compiler warnings: see $$log"

run: build
	$(abspath $(DRIVER)) $(EXAMPLE)

# run_tests.py configures/compiles build/ itself, so that a compile error is one counted
# failure and the other stages still run.
test: deps pylink
	@$(VENV_PY) tools/run_tests.py --builddir $(BUILDDIR)

# FORD (pip, into .venv when missing) on doc/ford.md: src/ and the theory pages doc/*.md
doc: $(STAMP)
	@$(VENV_PY) tools/make_doc.py --builddir $(BUILDDIR)

# afl++ from apt and atheris from pip, each only when missing; a failure here is not
# fatal: fuzz/run.sh then reports the target as not run
fuzzdeps: $(STAMP)
	@if ! command -v afl-fuzz >/dev/null 2>&1 || [ ! -f /usr/lib/afl/afl-compiler-rt.o ]; then \
	    if [ "$$(id -u)" = 0 ]; then sudo=""; elif command -v sudo >/dev/null 2>&1; then sudo="sudo"; \
	    else sudo="none"; fi; \
	    if command -v apt-get >/dev/null 2>&1 && [ "$$sudo" != none ]; then \
	        echo "fuzzdeps: missing afl-fuzz -> apt-get install afl++"; \
	        $$sudo env DEBIAN_FRONTEND=noninteractive apt-get update -q || true; \
	        $$sudo env DEBIAN_FRONTEND=noninteractive apt-get install -y -q afl++ || true; \
	    else echo "fuzzdeps: no afl-fuzz and no way to apt-get install afl++" >&2; fi; \
	fi
	@$(VENV_PY) -c 'import atheris' >/dev/null 2>&1 || { \
	    echo "fuzzdeps: pip install atheris into $(VENV)"; \
	    $(VENV_PY) -m pip install -q --disable-pip-version-check atheris || true; }

fuzz: build fuzzdeps
	@if command -v afl-fuzz >/dev/null 2>&1; then \
	    MESON="$(VENV_BIN)/meson" PATH="$(VENV_BIN):$$PATH" fuzz/build.sh \
	        || echo "fuzz: the instrumented build failed; AFL++ targets skipped" >&2; fi
	@FUZZ_SECONDS=$(FUZZ_SECONDS) PYTHON=$(VENV_PY) PYBUILD=$(abspath $(BUILDDIR))/python \
	    fuzz/run.sh

clean:
	rm -rf $(BUILDDIR) build-check build-install build-fuzz
	@pth=$(PTH_FILE); case "$$(cat "$$pth" 2>/dev/null)" in \
	    '$(abspath $(BUILDDIR))/python'|'$(abspath build-check)/python'|'$(abspath build-install)/python') \
	        rm -f "$$pth"; echo "clean: removed $$pth (it named a removed build dir)";; esac
