# lafortune: the ONE place for the materials and settings of `make reproduce`
# and `make database`.  The Makefile includes this file; the Octave steps read
# it through scripts/repro_config.m.  Any value can be overridden on the make
# command line or in the environment, e.g.  make reproduce SPP=16
#
# Format (so that both readers agree): one `NAME ?= value` per line, the value
# one or more words or numbers separated by spaces; `#` starts a comment.
# NAME_QUICK is the value used instead of NAME when QUICK=1 (classroom run).

# materials of `make reproduce` (`make database` takes every *.binary in MERL_DIR)
MATERIALS ?= green-metallic-paint red-plastic
# fit methods: inplane = the paper's (plane of incidence), hemisphere = the
# whole valid hemisphere (solid-angle weights), scene = the recommended fit for
# the best picture (the angle pairs the scene's pixels see, image weights);
# `make reproduce` needs inplane, `make database` takes any of them
METHODS ?= inplane hemisphere scene
LOBES ?= 1 2 3
# grazing angles beyond this (degrees) are left out of the fits
MAX_ANGLE ?= 80
# samples of the hemisphere fit
HEMI_SAMPLES ?= 40000
HEMI_SAMPLES_QUICK ?= 5000
# the scene: built-in sphere (default), spheres or torus; MESH=file.ply replaces it
SCENE ?= sphere
# image size in pixels, height then width (the paper: 512 high, 256 wide)
SIZE ?= 512 256
SIZE_QUICK ?= 128 64
# samples per pixel of the measured-data render (rt_render)
SPP ?= 128
SPP_QUICK ?= 8
# `make reproduce`: samples per pixel of the error-against-run-time study
SPP_STUDY ?= 1 2 4 8 16 32 64
SPP_STUDY_QUICK ?= 1 2 4
# `make reproduce`: the study of which fit looks right (scripts/repro_study.m):
# every table of STUDY_TABLES fitted with every weighting of STUDY_WEIGHTS (and
# the scene table with image weights), each fit rendered in the scene and in a
# second scene lit from STUDY_LIGHT.  STUDY: 1 on, 0 off, auto (on for the
# built-in scenes, off with MESH: a mesh's renders take seconds each; off in
# the QUICK classroom run)
STUDY ?= auto
STUDY_QUICK ?= 0
STUDY_TABLES ?= inplane hemisphere scene
STUDY_WEIGHTS ?= plain cosine relative log
STUDY_LIGHT ?= 1 0.3 0.6
# samples per pixel of the scene table (merl_scene; METHODS scene and the study)
STUDY_TABLE_SPP ?= 4
STUDY_TABLE_SPP_QUICK ?= 1
# POV-Ray anti-aliasing of the fits' renders
POV_AA ?= 4
POV_AA_QUICK ?= 2
# POV-Ray's render threads: 0 = all cores; `make -j N` (N > 1) uses 1 per job
# unless POV_THREADS is given on the command line
POV_THREADS ?= 0
# torus scene resolution (major, minor)
TORUS ?= 128 64
TORUS_QUICK ?= 48 24
# `make database`: a material "fails" (the Lafortune model cannot represent it)
# when its best render is below FAIL_PSNR dB, or when going from 1 to the most
# lobes gains less than FAIL_GAIN dB (as the paper found for red plastic)
FAIL_PSNR ?= 30
FAIL_GAIN ?= 0.5
# ... and a fit method "falls" on a material when one more lobe renders worse
# by more than FAIL_DROP dB
FAIL_DROP ?= 0.1
