# lafortune: Lafortune-model fits of measured BRDF data (GNU Octave package)
#
#   make reproduce   the paper's results in results/ (fits, renders, PSNR, report)
#   make database    every MERL file of MERL_DIR: fits, renders, table, report, gallery
#   make check       build the package, install it into a scratch prefix, run all tests
#   make bench       benchmark tables (fit speed, lookups, renders, EXR, POV-Ray)
#   make dist        lafortune-<version>.tar.gz for `pkg install`
#   make install     pkg install the tarball for the current user
#   make deps        install missing Debian packages (as root) or say how
#                    (CLUSTER=1: also the ssh server and Slurm that make check's cluster tests run)

SHELL := /bin/bash
VERSION := $(shell sed -n 's/^Version: *//p' DESCRIPTION)
TARBALL := lafortune-$(VERSION).tar.gz
OCTAVE ?= octave-cli
OCT := $(OCTAVE) --no-gui --norc --no-history
# the environment of every Octave process started here (the pipeline's, the
# tests', the benchmarks'): Octave's arithmetic here is one thread working
# on large temporary arrays.  OpenBLAS's helper threads would spin between
# its calls (sched_yield), taking a processor from POV-Ray or from the
# other jobs; glibc's malloc would give each large freed array back to the
# kernel, which zeroes the pages again for the next one (HACKING.md,
# "Process environment").  A value set outside make is kept;
# LAFORTUNE_OWN_ENV names those set here (bench_database runs an older
# version without them)
ifeq ($(origin LAFORTUNE_OWN_ENV),undefined)
LAFORTUNE_OWN_ENV := $(foreach v,OPENBLAS_NUM_THREADS GLIBC_TUNABLES,$(if $(filter undefined,$(origin $(v))),$(v)))
endif
OPENBLAS_NUM_THREADS ?= 1
GLIBC_TUNABLES ?= glibc.malloc.mmap_threshold=33554432:glibc.malloc.trim_threshold=1073741824:glibc.malloc.top_pad=268435456
export OPENBLAS_NUM_THREADS GLIBC_TUNABLES LAFORTUNE_OWN_ENV
# the MERL-format stand-ins shipped beside the project (tests, benchmarks)
MERL_PROXY_DIR ?= $(abspath ../shared/data/merl-proxy)
export MERL_PROXY_DIR
# real MERL .binary files, when a user has them (make reproduce)
MERL_DIR ?= data/merl
QUICK ?= 0
DEB_PACKAGES := octave octave-optim liboctave-dev libopenexr-dev pkg-config povray gnuplot-nox fonts-dejavu-core fonts-freefont-otf parallel blender-data
# test dependencies (make deps CLUSTER=1): the real ssh server and Slurm cluster of make check
CLUSTER_PACKAGES := slurm-wlm munge openssh-server openssh-client

.PHONY: all deps check stability floor klights bench dist install reproduce database clean distclean

all: dist

deps:
	@if command -v dpkg-query >/dev/null 2>&1; then \
	  missing=""; \
	  for p in $(DEB_PACKAGES) $(if $(filter 1,$(CLUSTER)),$(CLUSTER_PACKAGES)); do \
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

# the stiff and extreme cases as a table (study_stability; issue 49): fails
# on any defect.  LAFORTUNE_STABILITY_MERL: a folder of MERL files whose
# darkest and sharpest materials join the table
stability: deps
	@$(MAKE) --no-print-directory -C src
	$(OCT) --path src --eval 'addpath (genpath ("inst")); addpath ("scripts"); exit (study_stability () > 0)'

# the sampling's studies (issue 45): the judge step's noise floor per
# material and density (study_floor; LAFORTUNE_FLOOR_MERL: a folder of MERL
# files), and how close K lights come to an environment map per material
# and K (study_klights; LAFORTUNE_KLIGHTS_MERL)
floor: deps
	@$(MAKE) --no-print-directory -C src
	$(OCT) --path src --eval 'addpath (genpath ("inst")); addpath ("scripts"); pkg load optim; study_floor ();'

klights: deps
	@$(MAKE) --no-print-directory -C src
	$(OCT) --path src --eval 'addpath (genpath ("inst")); addpath ("scripts"); pkg load optim; study_klights ();'

bench: deps
	$(MAKE) -C src
	@for b in $(filter-out scripts/bench_data.m,$(wildcard scripts/bench_*.m)); do \
	  echo "== $$b"; $(OCT) --path src $$b || exit 1; echo; done

# ---- configuration: the one list of materials and settings, also read by
# the Octave steps (scripts/repro_config.m); override any value on the command
# line, e.g. make reproduce SPP=16
include config.mk

ifeq ($(QUICK),1)
RESULTS ?= results/quick
else
RESULTS ?= results
endif
MESH ?=
export RESULTS MERL_DIR QUICK MESH
# the settings of config.mk set empty on the command line (JUDGE=, PUBLISHED=):
# the Octave steps cannot tell an empty environment variable from a missing one
CONFIG_NAMES := $(shell sed -n 's/^\([A-Z][A-Z0-9_]*\) *?=.*/\1/p' config.mk)
export LAFORTUNE_EMPTY := $(strip $(foreach v,$(CONFIG_NAMES),$\
  $(if $(and $(filter command line,$(origin $(v))),$(if $(strip $($(v))),,1)),$(v))))
octrun = $(OCT) --path $(CURDIR)/inst --path $(CURDIR)/src --path $(CURDIR)/scripts \
  --eval 'sigterm_dumps_octave_core (false); sighup_dumps_octave_core (false); \
  warning ("off", "Octave:shadowed-function"); pkg load optim; $(1)'
# POV-Ray's threads per render: all cores with one job, one per job with make -j N
pov_threads = $(if $(filter command line environment,$(origin POV_THREADS)),$(POV_THREADS),$\
  $(if $(filter-out -j1,$(filter -j%,$(MAKEFLAGS))),1,$(POV_THREADS)))
# one Octave process per material: a step's rule only adds the step to the
# material's queue, $(1)/queue/$(2) ($(1) the folder of the run, $(2) the
# material), and the material's run (scripts/repro_material.m, with the
# environment $(3)) does the queued
# steps in order (repro_step writes each one's JSON record), so that the MERL
# file is read, the scene traced and optim loaded once.  A rerun with nothing
# out of date queues nothing and starts no Octave.
# (the comma of the call is $(comma): a bare one would end octrun's argument)
comma := ,
queue_of = $(1)/queue/$(2)
queue_add = mkdir -p $(1)/queue && echo $(3) >> $(call queue_of,$(1),$(2))
octmat = if [ -s $(call queue_of,$(1),$(2)) ]; then $(3) POV_THREADS=$(pov_threads) $\
  $(call octrun,repro_material ("$(2)"$(comma) "$(call queue_of,$(1),$(2))")); fi

# ---- the pipeline's files and steps, and which project files each step may
# call: build/deps.mk, written by scripts/repro_deps.m from the one table of
# them, scripts/repro_files.m (FILE_kind := pattern under the results folder,
# % the material; REPRO_STEPS, DB_STEPS; SCRIPT_step, UP_step: the steps whose
# records a step reads), and from the code (DEPS_script, like a compiler's
# -MM), so that a change to a file under inst/ re-runs only the steps that
# may call it.  Without it (the goals below need no step) no step rule exists.
NO_STEP_GOALS := all deps check stability floor klights bench dist install clean distclean
ifneq ($(filter-out $(NO_STEP_GOALS),$(MAKECMDGOALS)),)
build/deps.mk: $(wildcard scripts/*.m inst/*.m inst/*/*.m inst/*/private/*.m src/*.cc) inst $(wildcard inst/*/ inst/*/private/) scripts
	@mkdir -p build
	@$(OCT) --path $(CURDIR)/inst --path $(CURDIR)/scripts --eval 'repro_deps ("$@")'
include build/deps.mk
endif
# FILE_$(1) of material $(2) under folder $(3); the records step $(1) reads
file_of = $(3)/$(subst %,$(2),$(FILE_$(1)))
ups_of = $(foreach u,$(UP_$(1)),$(call file_of,$(u),$(2),$(3)))

.PHONY: FORCE
FORCE:

# ---- make reproduce: incremental steps; each writes its outputs atomically ----
MATS := $(MATERIALS)
R := $(RESULTS)

# the steps at once: JOBS (0: one per core), unless make was given a -j
repro_jobs = $(if $(filter -j%,$(MAKEFLAGS)),,-j$(if $(filter 0,$(JOBS)),$(shell nproc 2>/dev/null || echo 1),$(JOBS)))

reproduce: deps
	@$(MAKE) --no-print-directory -C src
	@$(MAKE) --no-print-directory -s $(repro_jobs) $(R)/$(FILE_report) $(R)/$(FILE_summary)
	@echo "reproduce: done: $(R)/$(FILE_report), $(R)/$(FILE_summary), figures in $(dir $(R)/$(FILE_figures))"

ifdef FILE_fit
$(R)/$(FILE_settings): FORCE
	@$(call octrun,repro_settings ())

$(R)/$(FILE_data): FORCE
	@$(call octrun,repro_data ("$*"))

# one pattern rule per step: a step that reads no record reads the data, the
# settings and the mesh
define repro_rule
$(R)/$(FILE_$(1)): $(if $(UP_$(1)),$(call ups_of,$(1),%,$(R)),$(R)/$(FILE_data) $(R)/$(FILE_settings) $(MESH)) $$(DEPS_$(SCRIPT_$(1)))
	@$$(call queue_add,$(R),$$*,$(1))
endef
$(foreach s,$(REPRO_STEPS),$(eval $(call repro_rule,$(s))))

# the study: STUDY=1, or auto without a MESH; with QUICK=1, STUDY_QUICK unless
# STUDY is given on the command line (as repro_config reads them)
STUDY_EFF := $(if $(filter command line environment,$(origin STUDY)),$(STUDY),$\
  $(if $(filter 1,$(QUICK)),$(STUDY_QUICK),$(STUDY)))
STUDY_ON := $(if $(filter 1,$(STUDY_EFF)),1,$(if $(filter auto,$(STUDY_EFF)),$(if $(MESH),,1)))
mat_out = $(foreach s,$(filter-out $(if $(STUDY_ON),,study),$(REPRO_STEPS)),$(call file_of,$(s),$(1),$(R)))
STEP_OUT := $(foreach m,$(MATS),$(call mat_out,$(m)))

# a material's run: its queued steps, in one process
.PHONY: $(addprefix repro-,$(MATS))
$(foreach m,$(MATS),$(eval repro-$(m): $(call mat_out,$(m))))
$(addprefix repro-,$(MATS)):
	@$(call octmat,$(R),$(patsubst repro-%,%,$@))

$(R)/$(FILE_figures): $(STEP_OUT) $(DEPS_repro_figures) | $(addprefix repro-,$(MATS))
	@$(call octrun,repro_figures ())

$(R)/$(FILE_report) $(R)/$(FILE_summary) &: $(R)/$(FILE_figures) $(STEP_OUT) $(DEPS_repro_report) | $(addprefix repro-,$(MATS))
	@$(call octrun,repro_report ())
endif

# ---- make database: every *.binary in MERL_DIR, one target per material
# (db-MATERIAL), so that `make -j N database` runs N materials at once; each
# step's record is written last and atomically, so a killed run restarted
# finishes the rest and a rerun with nothing changed does nothing.
#   make database MERL_DIR=dir                     on this machine
#   make database MERL_DIR=dir HOSTS=file          per-material jobs on ssh hosts (GNU parallel)
#   scripts/db_slurm_submit MERL_DIR=dir           a Slurm job array and a merge job
ifeq ($(QUICK),1)
DB ?= results/quick/database
else
DB ?= results/database
endif
# (scripts/db_names: only the names that are safe in a rule, a command and
# a scene file; `database` and `db-list` name the files left out)
db_names = sh scripts/db_names '$(subst ','\'',$(MERL_DIR))'
DB_MATS := $(shell $(db_names))
DB_DATA := $(abspath $(MERL_DIR))
HOSTS ?=
PARALLEL ?= parallel
PARALLEL_OPTS ?=
# the environment that decides BLAS's arithmetic (OpenBLAS's kernels), which
# ssh does not carry: passed to the ssh hosts' jobs where it is set, so that
# a material's fits do not depend on which host made them (without it, a
# host whose shell lacks OPENBLAS_CORETYPE fits to other last bits)
PARALLEL_ENV ?= OPENBLAS_CORETYPE OPENBLAS_L2_SIZE OPENBLAS_NUM_THREADS OMP_NUM_THREADS
# a material's folder; one step of a material: $(1) step, $(2) material
dbdir = $(call file_of,db_material,$(1),$(DB))
dbrun = $(call octmat,$(DB),$(1),RESULTS=$(call dbdir,$(1)) DATA_DIR=$(DB_DATA) DATABASE=1)
# the record of step $(1) of material $(2)
dbrec = $(call file_of,$(1),$(2),$(call dbdir,$(2)))

# one rule per step and material: a step that reads no record reads the
# material's MERL file, the settings and the mesh
define db_step
$(call dbrec,$(2),$(1)): $(if $(UP_$(2)),$(call ups_of,$(2),$(1),$(call dbdir,$(1))),$\
  $(call file_of,merl,$(1),$(MERL_DIR)) $(DB)/$(FILE_settings) $(MESH)) $$(DEPS_$(SCRIPT_$(2)))
	@$$(call queue_add,$(DB),$(1),$(2))

endef
# db-MATERIAL: the material's queued steps, in one process
define db_material
$(foreach s,$(DB_STEPS),$(call db_step,$(1),$(s)))
.PHONY: db-$(1)
db-$(1): $(foreach s,$(DB_STEPS),$(call dbrec,$(s),$(1)))
	@$$(call dbrun,$(1))
endef
ifdef FILE_fit
$(foreach m,$(DB_MATS),$(eval $(call db_material,$(m))))
endif

DB_OUT := $(foreach k,table report summary gallery fig_psnr_lobes fig_flip_lobes,$(DB)/$(FILE_$(k)))

.PHONY: database db-list db-settings
database: deps
	@$(db_names) --warn > /dev/null
	@test -n "$(DB_MATS)" || { echo "database: no *.binary file with a material's name in MERL_DIR=$(MERL_DIR)" >&2; exit 1; }
	@$(MAKE) --no-print-directory -C src
ifneq ($(HOSTS),)
	@$(MAKE) --no-print-directory -s $(DB)/$(FILE_settings)
	$(PARALLEL) -q --sshloginfile $(HOSTS) --workdir $(CURDIR) --halt never \
	  $(foreach v,$(PARALLEL_ENV),$(if $(value $(v)),--env $(v))) $(PARALLEL_OPTS) \
	  make --no-print-directory -s db-{} $(MAKEOVERRIDES) MERL_DIR=$(DB_DATA) DB=$(abspath $(DB)) \
	  ::: $(DB_MATS) || true
endif
	@$(MAKE) --no-print-directory -s $(DB_OUT)
	@echo "database: done: $(DB)/$(FILE_report), $(DB)/$(FILE_table), $(DB)/$(FILE_gallery)"

# the materials, one per line (for job arrays)
db-list:
	@$(db_names) --warn > /dev/null
	@printf '%s\n' $(DB_MATS)

# the database's settings.json, made once before the per-material jobs of a
# cluster run: jobs that each wrote it would make it newer than the records
# of a job that had already finished, and the merge would do that material again
.PHONY: db-settings
db-settings:
	@$(MAKE) --no-print-directory -s $(DB)/$(FILE_settings)

ifdef FILE_fit
$(DB)/$(FILE_settings): FORCE
	@RESULTS=$(DB) DATABASE=1 $(call octrun,repro_settings ())

# rewritten only when the list of materials changes
$(DB)/$(FILE_materials): FORCE
	@mkdir -p $(DB) && printf '%s\n' $(DB_MATS) > $@.tmp && \
	  if cmp -s $@.tmp $@; then rm -f $@.tmp; else mv -f $@.tmp $@; fi

$(DB_OUT) &: $(DB)/$(FILE_materials) $(foreach m,$(DB_MATS),$(call dbrec,$(lastword $(DB_STEPS)),$(m))) $(DEPS_db_report) | $(addprefix db-,$(DB_MATS))
	@RESULTS=$(DB) DATABASE=1 MATERIALS="$(DB_MATS)" $(call octrun,db_report ())
endif

.SECONDARY:
.DELETE_ON_ERROR:

clean:
	rm -rf build $(TARBALL) $(TARBALL).tmp
	$(MAKE) -C src clean

distclean: clean
	rm -rf results
