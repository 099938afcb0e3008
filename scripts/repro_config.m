## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn  {} {@var{c} =} repro_config ()
## @deftypefnx {} {@var{c} =} repro_config (@var{file})
## Settings of `make reproduce` and `make database`.
##
## The materials and settings are written once, in the project's
## @file{config.mk} (or @var{file}), which the Makefile includes too: one
## @code{NAME ?= value} per line.  A variable set in the environment (the
## make command line passes its variables there) overrides the file; with
## QUICK=1, @code{NAME_QUICK} replaces @code{NAME} unless NAME itself is set.
##
## Fields: @code{results} (RESULTS: the output folder), @code{data_dir}
## (DATA_DIR: where the steps read MATERIAL.binary; default RESULTS/data),
## @code{merl_dir} (MERL_DIR), @code{quick}, @code{database} (DATABASE=1: the
## steps of `make database`, which record a failure instead of stopping),
## @code{mesh}, @code{scene}, @code{materials}, @code{methods} (METHODS
## crossed with MODELS by repro_method: @code{scene}, @code{scene_ggx},
## ...), @code{models} (MODELS, the model types), @code{metals} (METALS:
## the database report's split), @code{lobes},
## @code{max_angle}, @code{hemi_samples}, @code{size}, @code{spp},
## @code{spp_study}, @code{pov_aa}, @code{pov_threads}, @code{torus}, @code{fail_flip},
## @code{fail_flip_gain}, @code{fail_flip_drop}, @code{published} (a table of
## published fits, for the database's baseline row), and @code{paper_psnr}
## (the paper's numbers).
## @end deftypefn
function c = repro_config (file)
  if (nargin < 1)
    file = fullfile (fileparts (mfilename ("fullpath")), "..", "config.mk");
  endif
  v = read_config (file);
  c.results = env_or ("RESULTS", "results");
  c.data_dir = env_or ("DATA_DIR", fileparts (repro_files ("data", c.results, "")));
  c.merl_dir = env_or ("MERL_DIR", "data/merl");
  c.quick = str2double (env_or ("QUICK", "0")) == 1;
  c.database = str2double (env_or ("DATABASE", "0")) == 1;
  c.mesh = env_or ("MESH", "");
  get = @(name) setting (v, name, c.quick);
  c.scene = get ("SCENE");
  c.materials = words (get ("MATERIALS"));
  c.models = words (get ("MODELS"));
  if (isempty (c.models))
    error ("lafortune:badConfig", "repro_config: MODELS is empty: expected model types, such as lafortune");
  endif
  c.methods = repro_method (words (get ("METHODS")), c.models);
  c.metals = words (get ("METALS"));
  c.lobes = number (get ("LOBES"), "LOBES");
  c.max_angle = number (get ("MAX_ANGLE"), "MAX_ANGLE");
  c.hemi_samples = number (get ("HEMI_SAMPLES"), "HEMI_SAMPLES");
  c.size = number (get ("SIZE"), "SIZE");
  c.spp = number (get ("SPP"), "SPP");
  c.spp_study = number (get ("SPP_STUDY"), "SPP_STUDY");
  c.env_map = strtrim (get ("ENV_MAP"));
  c.env_samples = number (get ("ENV_SAMPLES"), "ENV_SAMPLES");
  c.env_reference = number (get ("ENV_REFERENCE"), "ENV_REFERENCE");
  c.pov_aa = number (get ("POV_AA"), "POV_AA");
  c.pov_threads = number (get ("POV_THREADS"), "POV_THREADS");
  c.torus = number (get ("TORUS"), "TORUS");
  c.study = get ("STUDY");
  if (! any (strcmp (c.study, {"0", "1", "auto"})))
    error ("lafortune:badConfig", "repro_config: STUDY is '%s': expected 0, 1 or auto", c.study);
  endif
  c.study = strcmp (c.study, "1") || (strcmp (c.study, "auto") && isempty (c.mesh));
  c.study_tables = words (get ("STUDY_TABLES"));
  c.study_weights = words (get ("STUDY_WEIGHTS"));
  c.study_light = number (get ("STUDY_LIGHT"), "STUDY_LIGHT");
  c.study_table_spp = number (get ("STUDY_TABLE_SPP"), "STUDY_TABLE_SPP");
  c.published = strtrim (get ("PUBLISHED"));
  c.judge = judge_lights (words (get ("JUDGE")));
  c.judge_samples = number (get ("JUDGE_SAMPLES"), "JUDGE_SAMPLES");
  c.judge_spp = number (get ("JUDGE_SPP"), "JUDGE_SPP");
  c.fail_flip = number (get ("FAIL_FLIP"), "FAIL_FLIP");
  c.fail_flip_gain = number (get ("FAIL_FLIP_GAIN"), "FAIL_FLIP_GAIN");
  c.fail_flip_drop = number (get ("FAIL_FLIP_DROP"), "FAIL_FLIP_DROP");
  ## the paper's PSNR (256 x 512 image of the Happy Buddha, 128 rays per pixel)
  c.paper_psnr = struct ("green_metallic_paint", [29.27 31.44 31.02],
                         "red_plastic", [28.12 27.56 27.81]);
endfunction

function v = read_config (file)
  txt = fileread (file);
  v = struct ();
  for line = strsplit (txt, "\n")
    s = regexprep (line{1}, "#.*$", "");
    tok = regexp (s, '^\s*([A-Z][A-Z0-9_]*)\s*\?=\s*(.*?)\s*$', "tokens", "once");
    if (isempty (tok))
      if (! isempty (strtrim (s)))
        error ("lafortune:badConfig", "repro_config: %s: cannot read the line '%s': expected NAME ?= value",
               file, strtrim (line{1}));
      endif
      continue;
    endif
    v.(tok{1}) = tok{2};
  endfor
endfunction

## the held-out lights of JUDGE: struct array with name (the word), label,
## type ("environment", "directional"), map (its name) and direction
function J = judge_lights (w)
  J = struct ("name", {}, "label", {}, "type", {}, "map", {}, "direction", {});
  for i = 1:numel (w)
    if (any (w{i} == ","))
      d = str2double (strsplit (w{i}, ","));
      if (numel (d) != 3 || any (! isfinite (d)) || norm (d) == 0)
        error ("lafortune:badConfig",
               "repro_config: JUDGE has '%s': expected a light probe's name or a direction X,Y,Z", w{i});
      endif
      J(end+1) = struct ("name", w{i}, "label", sprintf ("light from [%s]", strjoin (strsplit (w{i}, ","), " ")),
                         "type", "directional", "map", "", "direction", d / norm (d));
    elseif (! isempty (regexp (w{i}, '^[a-z][a-z0-9_-]*$', "once")))
      J(end+1) = struct ("name", w{i}, "label", w{i}, "type", "environment", "map", w{i}, "direction", []);
    else
      error ("lafortune:badConfig",
             "repro_config: JUDGE has '%s': expected a light probe's name or a direction X,Y,Z", w{i});
    endif
  endfor
endfunction

function x = setting (v, name, quick)
  x = getenv (name);
  if (! isempty (x))
    return;
  endif
  ## set empty on make's command line (the Makefile lists those names:
  ## getenv cannot tell an empty variable from a missing one)
  if (any (strcmp (name, strsplit (getenv ("LAFORTUNE_EMPTY")))))
    return;
  endif
  qname = [name "_QUICK"];
  if (quick && ! isempty (getenv (qname)))
    x = getenv (qname);
  elseif (quick && isfield (v, qname))
    x = v.(qname);
  elseif (isfield (v, name))
    x = v.(name);
  else
    error ("lafortune:badConfig", "repro_config: no setting %s in config.mk or the environment", name);
  endif
endfunction

## the words of S (separated by blanks; none for an empty S)
function w = words (s)
  w = strsplit (strtrim (s));
  w(cellfun ("isempty", w)) = [];
endfunction

function x = number (s, name)
  x = str2double (strsplit (strtrim (s)));
  if (isempty (x) || any (! isfinite (x)))
    error ("lafortune:badConfig", "repro_config: %s is '%s': expected numbers separated by spaces",
           name, s);
  endif
endfunction

function v = env_or (name, def)
  v = getenv (name);
  if (isempty (v))
    v = def;
  endif
endfunction
