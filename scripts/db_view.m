## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {@var{V} =} db_view (@var{sm})
## What the template report_database (report_fill) shows of `make
## database`'s summary @var{sm} (db_summary): the summary itself, with its
## numbers arranged in the rows of the report's tables and its lists of
## materials put in words.  It computes no measure: every number is the
## summary's.
## @end deftypefn
function V = db_view (sm)
  V = sm;
  st = sm.settings;
  lobes = st.lobes;
  V.n_materials = numel (sm.materials);
  V.n_failed = numel (sm.materials) - sm.processed;
  V.lobes_list = mat2str (lobes);
  V.lobes_comma = strjoin (arrayfun (@num2str, lobes, "uniformoutput", false), ", ");
  V.methods_list = strjoin (st.methods, " ");
  V.models_list = strjoin (st.models, " ");
  V.kmin = min (lobes);
  V.kmax = max (lobes);
  V.kmin_s = plural (V.kmin);
  V.kmin_verb = merge (V.kmin == 1, "s", "");
  V.fig_psnr = repro_files ("fig_psnr_lobes", "", "");
  V.fig_flip = repro_files ("fig_flip_lobes", "", "");
  V.verdict_short = merge (isempty (st.judge), "in-sample FLIP", "held-out FLIP");
  V.has_noise = isfinite (sm.heldout.noise.median);
  ## the summary across materials, one row per method and lobe count
  V.summary_rows = struct ([]);
  for m = st.methods
    s = sm.methods.(m{1});
    for j = 1:numel (lobes)
      r = struct ("label", s.label, "lobes", lobes(j));
      for f = {"median_psnr", "median_flip", "median_deltae", "median_hue", "worst_psnr", "best_psnr", ...
               "worst_flip", "median_psnr_rt", "median_flip_rt", "median_deltae_rt", "median_hue_rt", ...
               "median_cos_rmse", "median_flip_heldout", "median_deltae_heldout"}
        r.(f{1}) = s.(f{1})(j);
      endfor
      r.worst_material = s.worst_material{j};
      r.worst_flip_material = s.worst_flip_material{j};
      V.summary_rows = [V.summary_rows, r];
    endfor
  endfor
  V = published_view (V, sm);
  ## the pairs PSNR and FLIP rank differently
  pct = @(d, n) 100 * d / max (n, 1);
  V.within_pct = pct (sm.rank_disagreement.pov.within_differ, sm.rank_disagreement.pov.within_pairs);
  V.across_pct = pct (sm.rank_disagreement.pov.across_differ, sm.rank_disagreement.pov.across_pairs);
  V.has_recommended = any (strcmp (st.methods, sm.flip_rises.method));
  V.rises_verdict = names_rise (sm.flip_rises.verdict_steps);
  V.rises_in_sample = names_rise (sm.flip_rises.in_sample_steps);
  ## where the Lafortune model fails
  V.has_lafortune = ! isempty (sm.lafortune_methods);
  V.has_fails = ! isempty (sm.fails);
  V.n_fails = numel (sm.fails);
  for k = 1:numel (sm.fails)
    V.fails{k}.lobes_s = plural (sm.fails{k}.lobes);
  endfor
  V.method_rows = struct ([]);
  for m = st.methods
    s = sm.methods.(m{1});
    change = sprintf ("FLIP %%+.3f from %d to %d lobes", V.kmin, V.kmax);
    V.method_rows = [V.method_rows, struct("label", s.label,
                                           "high", names_val (s.fails_high, s.fails_high_flip, "FLIP %.3f"),
                                           "flat", names_val (s.fails_flat, s.fails_flat_change, change),
                                           "falls", names_rise (s.falls_steps),
                                           "falls_in_sample", names_rise (s.falls_in_sample_steps))];
  endfor
  V.has_failed = ! isempty (sm.failed);
  V = models_view (V, sm);
  V = materials_view (V, sm);
endfunction

## the published fits' section
function V = published_view (V, sm)
  P = sm.published;
  V.has_published = ! isempty (P.materials);
  V.n_published = numel (P.materials);
  V.has_recommended_1 = ! isempty (P.recommended_flip);
  V.has_not_better = ! isempty (P.not_better);
  V.has_tied = ! isempty (P.tied);
  V.published_rows = struct ([]);
  for n = 1:numel (P.materials)
    r = struct ("material", P.materials{n}, "psnr", P.psnr(n), "flip", P.flip(n), "deltae", P.deltae(n),
                "hue", P.hue(n), "flip_in_sample", P.flip_in_sample(n), "recommended_psnr", NaN,
                "recommended_flip", NaN, "noise_flip", P.noise_flip(n));
    if (V.has_recommended_1)
      r.recommended_psnr = P.recommended_psnr(n);
      r.recommended_flip = P.recommended_flip(n);
    endif
    V.published_rows = [V.published_rows, r];
  endfor
endfunction

## the models compared
function V = models_view (V, sm)
  S = sm.models;
  lobes = sm.settings.lobes;
  V.models_titles = strjoin (cellfun (@(m, t) sprintf ("%s (%s)", m, t), S.models, S.titles,
                                      "uniformoutput", false), ", ");
  V.metals_or_none = merge (isempty (S.metals), "none", strjoin (S.metals, ", "));
  V.lobe_heads = struct ("lobes", num2cell (lobes), "lobes_s", arrayfun (@plural, lobes, "uniformoutput", false));
  V.best_rows = struct ([]);
  for b = S.best
    x = b{1};
    ## the models tied with the best (within the noise floor), "" for none
    tie = x.tied;
    tie(cellfun (@(t) ! any (t == ","), tie)) = {""};
    cells = struct ("has", num2cell (! isnan (x.flip)), "model", x.model, "flip", num2cell (x.flip),
                    "method", x.method, "tie", tie);
    V.best_rows = [V.best_rows, struct("material", x.material, "metal", x.metal, "cells", cells)];
  endfor
  V.model_rows = struct ([]);
  for t = fieldnames (S.per_model)'
    s = S.per_model.(t{1});
    for j = 1:numel (lobes)
      alb = "-";
      if (s.albedo_fits(j) > 0)
        alb = sprintf ("%d of %d", s.albedo_above_1(j), s.albedo_fits(j));
      endif
      r = struct ("model", s.model, "lobes", lobes(j), "albedo", alb);
      for f = {"params", "bytes", "json_bytes", "median_flip", "median_flip_metals", "median_flip_nonmetals", ...
               "median_deltae", "best_on"}
        r.(f{1}) = s.(f{1})(j);
      endfor
      V.model_rows = [V.model_rows, r];
    endfor
  endfor
  V.has_lafortune_model = any (strcmp (S.models, "lafortune"));
  V.only_lafortune = V.has_lafortune_model && numel (S.models) == 1;
  V.has_loses = ! isempty (S.lafortune_loses);
endfunction

## every material's numbers, one row per method; the times per stage
function V = materials_view (V, sm)
  V.material_rows = {};
  for i = 1:numel (sm.materials)
    mat = sm.materials{i};
    if (! sm.ok(i))
      V.material_rows{end+1} = struct ("material", mat, "ok", false);
      continue;
    endif
    for m = sm.settings.methods
      r = struct ("material", mat, "ok", true, "method", m{1},
                  "sheet", sprintf ("%s/%s", repro_files ("db_material", "", mat), sm.sheets(i).file));
      for q = {"psnr", "flip", "deltae", "hue"}
        r.(q{1}) = sm.(q{1}).(m{1})(i,:);
        r.([q{1} "_rt"]) = sm.([q{1} "_rt"]).(m{1})(i,:);
      endfor
      V.material_rows{end+1} = r;
    endfor
  endfor
  V.stage_rows = struct ([]);
  for s = fieldnames (sm.stage_time)'
    t = sm.stage_time.(s{1});
    V.stage_rows = [V.stage_rows, struct("stage", s{1}, "median", median (t), "max", max (t), "total", sum (t))];
  endfor
endfunction

## the materials with their steps where one more lobe renders worse, e.g.
## "gold (1 → 2 lobes: FLIP +0.120, PSNR -1.20 dB)", or "none"
function s = names_rise (R)
  if (isempty (R))
    s = "none";
    return;
  endif
  t = {};
  for r = R(:)'
    st = cellfun (@(x) sprintf ("%d → %d lobes: FLIP %+.3f, PSNR %+.2f dB", x.from, x.to, x.flip, x.psnr),
                  r{1}.steps, "uniformoutput", false);
    t{end+1} = sprintf ("%s (%s)", r{1}.material, strjoin (st, "; "));
  endfor
  s = strjoin (t, ", ");
endfunction

## the materials NAMES with their values V, e.g. "gold (FLIP 0.612)", or "none"
function s = names_val (names, v, fmt)
  if (isempty (names))
    s = "none";
  else
    s = strjoin (arrayfun (@(j) sprintf (["%s (" fmt ")"], names{j}, v(j)), 1:numel (names),
                           "uniformoutput", false), ", ");
  endif
endfunction

function s = plural (k)
  s = merge (k == 1, "", "s");
endfunction
