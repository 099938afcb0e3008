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
# `make reproduce`: steps run at once (make -j), 0 = one per core; a -j of
# your own (make -j N reproduce) takes precedence
JOBS ?= 0
# fit methods: inplane = the paper's (plane of incidence), general = the
# recommended fit when the scene is not known (the whole valid hemisphere,
# the weighting chosen by renders in training views: lafortune_fit
# (merl_samples (B), n)), scene = the fit for the scene's own light (the
# angle pairs its pixels see, relative weights), hemisphere = the whole
# hemisphere with plain solid-angle weights; `make reproduce` needs
# inplane, `make database` takes any of them
METHODS ?= inplane general scene
# the analytic models fitted by every method (the types of brdf_model ():
# lafortune blinnphong ward cooktorrance ggx ashikhminshirley).  The
# Lafortune model keeps the method's name (scene); another model makes a
# method of its own, METHOD_MODEL (scene_ggx, inplane_shared_cooktorrance),
# with its own fits, renders, rows and columns.  `make reproduce` (the
# paper) fits lafortune; `make database MODELS="lafortune cooktorrance ggx"`
# compares them (report.md, "Models compared")
MODELS ?= lafortune
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
# `make reproduce`: error against run time under an environment light (the
# spp step, figures/env-samples.png): the measured data on the scene lit by
# the light probe ENV_MAP (a name of scene_make's "map": courtyard, ..., or
# sky, the built-in sky), one ray per pixel centre, ENV_SAMPLES light
# samples per pixel against ENV_REFERENCE of them (the converged render)
ENV_MAP ?= courtyard
ENV_SAMPLES ?= 1 4 16 64 256
ENV_SAMPLES_QUICK ?= 1 4 16
ENV_REFERENCE ?= 1024
ENV_REFERENCE_QUICK ?= 256
# held-out verdicts: every fit is also judged in the scene lit by each of
# these lights, which no fit was made for (rt_render, light samples from the
# trace's cache; img_compare against the measured data under the same
# light), and every verdict of the reports is made on them.  A word is a
# light probe of scene_make's "map" (courtyard, city, forest, interior,
# night, studio, sunrise, sunset: blender-data; sky: the built-in sky) or a
# directional light X,Y,Z (toward the light; 0.2,1,-0.4 is from behind and
# above: the grazing angles).  Empty (JUDGE=): in-sample only
JUDGE ?= courtyard forest 0.2,1,-0.4
# light samples per pixel sample of the environments, samples per pixel
JUDGE_SAMPLES ?= 64
JUDGE_SAMPLES_QUICK ?= 16
JUDGE_SPP ?= 1
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
# `make database`: published fits rendered beside the toolbox's, as a baseline
# (a table of lafortune_ngan's format: Ngan, Durand and Matusik 2005's 1-lobe
# Lafortune fits, made on the real measurements); a material the table does
# not have, or an empty value, gets none
PUBLISHED ?= ../shared/data/ngan2005/lafortune-1lobe.tsv
# POV-Ray anti-aliasing of the fits' renders
POV_AA ?= 4
POV_AA_QUICK ?= 2
# POV-Ray's render threads: 0 = all cores; `make -j N` (N > 1) uses 1 per job
# unless POV_THREADS is given on the command line
POV_THREADS ?= 0
# torus scene resolution (major, minor)
TORUS ?= 128 64
TORUS_QUICK ?= 48 24
# `make database`: where the Lafortune model fails, judged by HDR-FLIP
# (img_compare's q.flip: the mean per-pixel FLIP over the object's pixels, 0 =
# same, 1 = as different as it gets; a fit's POV-Ray render against that of
# the measured data).  A material fails when its best fit (lowest FLIP over
# methods and lobe counts) is above FAIL_FLIP, or when that fit's method is
# above FAIL_FLIP with 1 lobe and going to the most lobes lowers its FLIP by
# less than FAIL_FLIP_GAIN (more lobes do not help a picture that looks wrong;
# a material that 1 lobe already renders right does not fail for that).
#
# Units: NVIDIA's FLIP tool pools over ALL pixels, black background included
# (exposures 0..6); on this project's 256 x 512 sphere renders (the object
# covers 24 % of the frame) it gives 0.177 for a grey sphere for a teal paint,
# 0.199 for red-plastic's in-plane 1-lobe fit, 0.229 for a white-yellow
# sphere, 0.092 for a correctly coloured fit with a slightly broad highlight,
# 0.027-0.037 for the recommended (scene) fits.  q.flip is 4 to 5.5 times
# those (mean over the object, exposures from its luminance; up to 10 times
# for dark materials, whose body the 0..6 exposures leave black): the pairs
# of ../shared/data/flip-ref give 0.81 (grey for teal), 0.83 (red-plastic
# in-plane 1) and 0.16 (both 3-lobe scene fits).
#
# FAIL_FLIP 0.5, from the contact sheets of 6 materials at the default size
# (54 fits: the two proxies, aluminium, color-changing-paint1, beige-fabric,
# specular-blue-phenolic): the fits that look wrong (body of the wrong colour
# or brightness, highlight blown out) have 0.52-0.97; those that look right
# or nearly so 0.08-0.49 (recommended fits 0.08-0.17; right colour with the
# highlight too broad, displaced or faint 0.37-0.49).  One exception: a hue
# shift on a light body (specular-blue-phenolic hemisphere 3: 0.34, but dE
# 8.4 and hue 18 degrees, beside it in the report).  Near 0.5 the mean
# CIEDE2000 dE is 6-7, a difference seen at a glance (1: just noticeable);
# on NVIDIA's all-pixel scale 0.5 is 0.10-0.12, between the broad-highlight
# fit (0.092) and the wrong colours (0.177 and up).  QUICK's 64 x 128 renders
# give the same values to about 0.03: no FAIL_FLIP_QUICK.
# FAIL_FLIP_GAIN 0.05: several times the two renderers' disagreement on one
# model (up to 0.008); fits that stay as wrong go down by 0 to 0.024 from 1 to
# 3 lobes (aluminium's and color-changing-paint1's hemisphere and in-plane
# fits, aluminium's scene fits: 0.018), fits that visibly change by 0.13 or
# more.
# FAIL_FLIP_DROP 0.002: a method falls on a material when one more lobe
# raises its FLIP by more than this (the renders are deterministic, so a
# rise is the model's; the report lists it for both renderers).
FAIL_FLIP ?= 0.5
FAIL_FLIP_GAIN ?= 0.05
FAIL_FLIP_DROP ?= 0.002
# `make database`: the metals among the MERL materials, for the report's
# medians of metals and of the other materials apart (the split by which
# Ngan et al. 2005 and Lavoue et al. 2021 discuss their model comparisons).
# Neither paper's own list is kept in ../shared, so this one was made from
# the MERL database's 100 names: its conductors, bare metals and alloys,
# and hematite (an iron-oxide ore with a metallic lustre); not the metallic
# paints (flakes under a clear coat), nor two-layer-gold and two-layer-silver
# (coated).  Of the 26 materials of ../shared: aluminium, hematite, steel.
# Names not in the run are ignored.
METALS ?= alum-bronze aluminium black-oxidized-steel brass chrome chrome-steel grease-covered-steel hematite nickel ss440 steel tungsten-carbide
