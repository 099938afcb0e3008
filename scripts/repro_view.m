## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {@var{V} =} repro_view (@var{sm}, @var{c})
## What the template report_reproduce (report_fill) shows of `make
## reproduce`'s summary @var{sm} (repro_summary): the summary itself, with
## its numbers arranged in the rows of the report's tables and a few of
## them put in words; the texts of the in-plane models' files (RESULTS/fit,
## from @var{c}, repro_config).  It computes no measure: every number is the
## summary's.
## @end deftypefn
function V = repro_view (sm, c)
  V = sm;
  st = sm.settings;
  mats = c.materials;
  nk = numel (c.lobes);
  V.run = merge (st.quick, "QUICK (classroom)", "full");
  V.scene_desc = st.mesh;
  if (isempty (st.mesh))
    V.scene_desc = sprintf ("the built-in scene '%s'; give MESH=happy_vrip.ply for the paper's Happy Buddha", st.scene_name);
  endif
  V.data_rows = {};
  V.material_names = struct ("material", mats, "words", strrep (mats, "-", " "),
                             "first_light", {""});
  for i = 1:numel (mats)
    d = sm.data.(repro_field (mats{i}));
    V.data_rows{end+1} = struct ("material", mats{i}, "file", strcmp (d.kind, "merl-file"), "path", d.path,
                                 "sha", d.sha256(1:min (12, end)), "what", d.what);
  endfor
  ## the PSNR table: the paper's method, then the other methods
  others = c.methods(! strcmp (c.methods, "inplane"));
  V.others = struct ("label", cellfun (@(m) repro_method (m).label, others, "uniformoutput", false));
  V.psnr_rows = {};
  V.fit_rows = {};
  for i = 1:numel (mats)
    s = sm.materials.(repro_field (mats{i}));
    for j = 1:nk
      paper = "-";
      if (! isnan (s.paper_psnr(j)))
        paper = sprintf ("%.2f dB", s.paper_psnr(j));
      endif
      o = struct ("pov", cellfun (@(m) s.(["psnr_" m "_pov"])(j), others, "uniformoutput", false),
                  "rt", cellfun (@(m) s.(["psnr_" m "_rt"])(j), others, "uniformoutput", false));
      V.psnr_rows{end+1} = struct ("material", mats{i}, "lobes", c.lobes(j), "paper", paper,
                                   "inplane_pov", s.psnr_inplane_pov(j), "inplane_rt", s.psnr_inplane_rt(j),
                                   "others", o, "renderers", s.renderers_psnr(j));
    endfor
    ## every fit: in-sample by both renderers, held out
    for m = c.methods
      for j = 1:nk
        r = struct ("material", mats{i}, "label", repro_method (m{1}).label, "lobes", c.lobes(j));
        for q = {"psnr", "flip", "deltae", "hue"}
          for rr = {"pov", "rt"}
            r.([q{1} "_" rr{1}]) = s.([q{1} "_" m{1} "_" rr{1}])(j);
          endfor
        endfor
        r.lights = num2cell (s.heldout_lights.(m{1})(j,:));
        r.flip_heldout = s.(["flip_" m{1} "_heldout"])(j);
        r.deltae_heldout = s.(["deltae_" m{1} "_heldout"])(j);
        V.fit_rows{end+1} = r;
      endfor
    endfor
  endfor
  V.measured_agree = strjoin (cellfun (@(m) sprintf ("%.1f dB (%s)", sm.materials.(repro_field (m)).renderers_psnr_measured, m),
                                       mats, "uniformoutput", false), ", ");
  V = heldout_view (V, sm, c);
  V = fits_view (V, sm, c, others);
  V = times_view (V, sm, c);
endfunction

## the held-out verdicts and the models compared
function V = heldout_view (V, sm, c)
  mats = c.materials;
  V.has_judge = ! isempty (c.judge);
  V.lights_list = strjoin (sm.heldout.lights, ", ");
  V.judge_spp_s = merge (c.judge_spp == 1, "", "s");
  if (V.has_judge)
    [V.material_names.first_light] = deal (c.judge(1).label);
  endif
  V.best_method_rows = V.noise_rows = {};
  if (V.has_judge)
    for i = 1:numel (mats)
      s = sm.materials.(repro_field (mats{i}));
      b = sm.heldout.best_method.(repro_field (mats{i}));
      t = arrayfun (@(j) best_text (c, s, b, j), 1:numel (c.lobes), "uniformoutput", false);
      V.best_method_rows{end+1} = struct ("material", mats{i}, "text", strjoin (t, "; "));
      V.noise_rows{end+1} = struct ("material", mats{i}, "lights", {num2cell(s.heldout_noise_flip)},
                                    "mean", s.heldout_noise_flip_mean);
    endfor
  endif
  V.models_list = strjoin ({sm.models.model}, ", ");
  V.judged_by = merge (V.has_judge, "the mean FLIP under the held-out lights (JUDGE)",
                        "the in-sample FLIP of their POV-Ray renders (JUDGE is empty)");
  V.model_rows = {};
  for i = 1:numel (mats)
    B = sm.best_model.(repro_field (mats{i}));
    for j = 1:numel (c.lobes)
      cells = arrayfun (@(M) struct ("flip", M.flip(i,j), "method", M.method{i,j}), sm.models);
      best = B.model{j};
      if (isfield (B, "tied") && ! strcmp (B.tied{j}, best))
        best = ["tie: " B.tied{j}];      # within the noise floor (repro_tie)
      endif
      V.model_rows{end+1} = struct ("material", mats{i}, "lobes", c.lobes(j), "cells", cells,
                                    "best", best);
    endfor
  endfor
endfunction

## the best method of a material at lobe slot J in words (S: its numbers,
## B: its best method and the methods tied with it), e.g. "2 lobes: general
## (0.1993)", or with a tie "3 lobes: tie within the noise floor 0.1842:
## general (0.1852), scene (0.2900)"
function t = best_text (c, s, b, j)
  k = sprintf ("%d lobe%s", c.lobes(j), merge (c.lobes(j) > 1, "s", ""));
  tied = strsplit (b.tied{j}, ", ");
  if (numel (tied) < 2)
    t = sprintf ("%s: %s (%.4f)", k, b.method{j}, b.flip(j));
  else
    f = cellfun (@(m) sprintf ("%s (%.4f)", m, s.(["flip_" m "_heldout"])(j)), tied, "uniformoutput", false);
    t = sprintf ("%s: tie within the noise floor %.4f: %s", k, b.noise_flip, strjoin (f, ", "));
  endif
endfunction

## the study, the fits' errors and the models' texts
function V = fits_view (V, sm, c, others)
  mats = c.materials;
  V.study_rows = {};
  for i = 1:numel (mats)
    if (! isfield (sm.study, repro_field (mats{i})))
      continue;
    endif
    R = sm.study.(repro_field (mats{i}));
    nl = max (c.lobes);
    rows = {};
    for m = R.methods(:)'
      pr = "-";
      if (all (isfinite (m.psnr_a_predicted)))
        pr = strjoin (arrayfun (@(v) sprintf ("%.1f", v), m.psnr_a_predicted(:)', "uniformoutput", false), " / ");
      endif
      rows{end+1} = struct ("table", m.table, "weight", m.weight,
                            "ab", struct ("a", num2cell (m.psnr_a(1:nl)), "b", num2cell (m.psnr_b(1:nl))),
                            "fa", {num2cell(m.flip_a(1:nl))}, "pred", pr, "fit_time", m.fit_time);
    endfor
    V.study_rows{end+1} = struct ("first", isempty (V.study_rows), "material", mats{i},
                                  "light_b", num2str (R.light_b(:)', "%.2f "), "ks", {num2cell(1:nl)},
                                  "rows", {rows});
  endfor
  tables = unique (cellfun (@(m) repro_method (m).base, c.methods, "uniformoutput", false), "stable");
  V.otables = tables(! strcmp (tables, "inplane"));
  V.error_rows = {};
  for i = 1:numel (mats)
    s = sm.materials.(repro_field (mats{i}));
    for m = c.methods
      e = s.errors.(m{1});
      for j = 1:numel (c.lobes)
        V.error_rows{end+1} = struct ("material", mats{i}, "method", m{1}, "lobes", c.lobes(j),
                                      "rmse", e.inplane.rmse(j), "rel_rmse", e.inplane.rel_rmse(j),
                                      "log_rmse", e.inplane.log_rmse(j), "cos_rmse", e.inplane.cos_rmse(j),
                                      "other", {cellfun(@(t) e.(t).rmse(j), V.otables, "uniformoutput", false)},
                                      "time", e.time(j));
      endfor
    endfor
  endfor
  V.model_texts = {};
  for i = 1:numel (mats)
    for k = c.lobes
      V.model_texts{end+1} = strtrim (fileread ([repro_files("model", c.results, mats{i}, "inplane", k) ".txt"]));
    endfor
  endfor
endfunction

## error against run time: the fits' traces, the renders against samples,
## the render times
function V = times_view (V, sm, c)
  mats = c.materials;
  chn = {"R", "G", "B"};
  V.trace_rows = V.spp_rows = V.env_rows = V.time_rows = {};
  for i = 1:numel (mats)
    s = sm.materials.(repro_field (mats{i}));
    for ch = 1:3
      t = s.trace(ch);
      V.trace_rows{end+1} = struct ("material", mats{i}, "channel", chn{ch}, "final", t.final, "t10", t.t10,
                                    "t1", t.t1, "total", t.total);
    endfor
    for j = 1:numel (s.spp)
      V.spp_rows{end+1} = struct ("material", mats{i}, "spp", s.spp(j), "reference", false,
                                  "time", s.spp_time(j), "psnr", s.spp_psnr(j));
    endfor
    V.spp_rows{end+1} = struct ("material", mats{i}, "spp", s.spp_reference, "reference", true,
                                "time", s.spp_reference_time, "psnr", NaN);
    for k = 1:numel (s.env_sampling)
      for j = 1:numel (s.env_samples)
        V.env_rows{end+1} = struct ("material", mats{i}, "sampling", s.env_sampling{k},
                                    "samples", s.env_samples(j), "reference", false,
                                    "time", s.env_by_time(k,j), "flip", s.env_by_flip(k,j),
                                    "relmse", s.env_by_relmse(k,j), "psnr", s.env_by_psnr(k,j));
      endfor
    endfor
    V.env_rows{end+1} = struct ("material", mats{i}, "sampling", "mis", "samples", s.env_reference,
                                "reference", true, "time", s.env_reference_time, "flip", NaN,
                                "relmse", NaN, "psnr", NaN);
    V.time_rows{end+1} = struct ("material", mats{i}, "render_time_measured", s.render_time_measured,
                                 "material_bytes", s.material_bytes, "render_time_pov", s.render_time_pov,
                                 "render_time_rt", s.render_time_rt);
  endfor
  s1 = sm.materials.(repro_field (mats{1}));
  V.env_map = s1.env_map;
  V.env_reference = s1.env_reference;
endfunction
