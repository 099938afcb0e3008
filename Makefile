# lafortune: Lafortune-model fits of measured BRDF data (GNU Octave package)
#
#   make reproduce   the paper's results in results/ (fits, renders, PSNR, report)
#   make check       build the package, install it into a scratch prefix, run all tests
#   make bench       benchmark tables (fit speed, lookups, renders, EXR, POV-Ray)
#   make dist        lafortune-<version>.tar.gz for `pkg install`
#   make install     pkg install the tarball for the current user
#   make deps        install missing Debian packages (as root) or say how

SHELL := /bin/bash
VERSION := $(shell sed -n 's/^Version: *//p' DESCRIPTION)
TARBALL := lafortune-$(VERSION).tar.gz
OCTAVE ?= octave-cli
OCT := $(OCTAVE) --no-gui --norc --no-history
# the MERL-format stand-ins shipped beside the project (tests, benchmarks)
MERL_PROXY_DIR ?= $(abspath ../shared/data/merl-proxy)
export MERL_PROXY_DIR
# real MERL .binary files, when a user has them (make reproduce)
MERL_DIR ?= data/merl
QUICK ?= 0
DEB_PACKAGES := octave octave-optim liboctave-dev libopenexr-dev pkg-config povray gnuplot-nox fonts-dejavu-core fonts-freefont-otf

.PHONY: all deps check bench dist install reproduce clean distclean

all: dist

deps:
	@if command -v dpkg-query >/dev/null 2>&1; then \
	  missing=""; \
	  for p in $(DEB_PACKAGES); do \
	    dpkg-query -W -f='$${Status}' $$p 2>/dev/null | grep -q "install ok installed" || missing="$$missing $$p"; \
	  done; \
	  if [ -z "$$missing" ]; then echo "deps: all Debian packages present"; \
	  elif [ "$$(id -u)" = 0 ]; then \
	    echo "deps: installing$$missing"; \
	    apt-get update -q && DEBIAN_FRONTEND=noninteractive apt-get install -y -q $$missing || exit 1; \
	  else \
	    echo "deps: missing Debian packages:$$missing"; \
	    echo "deps: run as root:  apt-get update && apt-get install -y$$missing"; \
	    exit 1; \
	  fi; \
	else \
	  miss=""; \
	  for t in octave-cli mkoctfile povray gnuplot pkg-config; do command -v $$t >/dev/null 2>&1 || miss="$$miss $$t"; done; \
	  pkg-config --exists OpenEXR 2>/dev/null || miss="$$miss OpenEXR(pkg-config)"; \
	  fc-list 2>/dev/null | grep -q FreeSans || miss="$$miss FreeSans(GNU FreeFont: Octave's default figure font)"; \
	  if [ -n "$$miss" ]; then echo "deps: not a Debian system, and missing:$$miss (and the Octave package optim)"; exit 1; fi; \
	  echo "deps: not a Debian system; octave-cli, mkoctfile, povray, gnuplot, OpenEXR and FreeSans found"; \
	fi
	@mkdir -p $(HOME)/.local/share/octave

# the package's files: tracked or new (not ignored) files under inst/ and src/
PKG_FILES = DESCRIPTION COPYING INDEX NEWS README.md \
  $(shell git ls-files --cached --others --exclude-standard inst src 2>/dev/null || find inst src -type f)

dist: $(TARBALL)

$(TARBALL): $(PKG_FILES)
	@rm -rf build/lafortune-$(VERSION) && mkdir -p build/lafortune-$(VERSION)
	@tar cf - $(filter-out %.oct %.o %.cc-tst,$(PKG_FILES)) | tar xf - -C build/lafortune-$(VERSION)
	@tar czf $(TARBALL).tmp -C build lafortune-$(VERSION) && mv $(TARBALL).tmp $(TARBALL)
	@echo "dist: $(TARBALL)"

install: deps dist
	$(OCT) --eval 'warning ("off", "Octave:shadowed-function"); pkg install $(TARBALL)'

check: deps dist
	@$(MAKE) --no-print-directory -C src
	LAFORTUNE_TOP=$(CURDIR) $(OCT) scripts/run_tests.m $(abspath $(TARBALL))

bench: deps
	$(MAKE) -C src
	@for b in scripts/bench_*.m; do echo "== $$b"; $(OCT) --path src $$b || exit 1; echo; done

# ---- make reproduce: incremental steps; each writes its outputs atomically ----
ifeq ($(QUICK),1)
RESULTS ?= results/quick
else
RESULTS ?= results
endif
MESH ?=
SCENE ?= sphere
export RESULTS MERL_DIR QUICK MESH SCENE
MATS := green-metallic-paint red-plastic
R := $(RESULTS)
# a change to the toolbox's code makes every step out of date
CODE := $(wildcard inst/*.m inst/private/*.m src/*.cc) scripts/repro_config.m scripts/repro_scene.m \
  $(R)/settings.json
octrun = $(OCT) --path $(CURDIR)/inst --path $(CURDIR)/src --path $(CURDIR)/scripts \
  --eval 'warning ("off", "Octave:shadowed-function"); pkg load optim; $(1)'
OUTPUTS := $(R)/report.md $(R)/summary.json

reproduce: deps
	@$(MAKE) --no-print-directory -C src
	@$(MAKE) --no-print-directory -s $(OUTPUTS)
	@echo "reproduce: done: $(R)/report.md, $(R)/summary.json, figures in $(R)/figures"

.PHONY: FORCE
FORCE:

$(R)/settings.json: FORCE
	@$(call octrun,repro_settings ())

$(R)/data/%.binary: FORCE
	@$(call octrun,repro_data ("$*"))

$(R)/fit/%.json: $(R)/data/%.binary scripts/repro_fit.m $(CODE)
	@$(call octrun,repro_fit ("$*"))

$(R)/render/%-measured.json: $(R)/data/%.binary scripts/repro_render_measured.m $(CODE)
	@$(call octrun,repro_render_measured ("$*"))

$(R)/render/%-fits.json: $(R)/fit/%.json $(R)/render/%-measured.json scripts/repro_render_fits.m $(CODE)
	@$(call octrun,repro_render_fits ("$*"))

$(R)/spp/%.json: $(R)/render/%-measured.json scripts/repro_spp.m $(CODE)
	@$(call octrun,repro_spp ("$*"))

STEP_OUT := $(foreach m,$(MATS),$(R)/fit/$(m).json $(R)/render/$(m)-fits.json $(R)/spp/$(m).json)

$(R)/figures/spp.png: $(STEP_OUT) scripts/repro_figures.m $(CODE)
	@$(call octrun,repro_figures ())

$(OUTPUTS) &: $(R)/figures/spp.png $(STEP_OUT) scripts/repro_report.m $(CODE)
	@$(call octrun,repro_report ())

.SECONDARY:

clean:
	rm -rf build $(TARBALL) $(TARBALL).tmp
	$(MAKE) -C src clean

distclean: clean
	rm -rf results
