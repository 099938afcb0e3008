## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {[@var{sm}, @var{X}] =} db_summary (@var{c}, @var{D})
## The numbers of `make database`'s report, computed once from the
## materials' records @var{D} (db_report reads them: @code{material},
## @code{ok}, @code{error}, @code{rec}, one field per step) with the
## settings @var{c} (repro_config).  @var{sm} is summary.json, and all that
## report.md says (db_report fills the template report_database from it):
## the settings, per method and lobe count the medians and extremes
## (@code{methods}), the published fits, the pairs PSNR and FLIP rank
## differently, the FLIP rises, the failures, the models compared
## (db_models), the times per stage, the measures per material.  @var{X}
## holds every measure, materials x lobes per renderer and method
## (@code{X.flip.pov.scene}; @code{heldout}, the means over JUDGE's
## lights, @code{light}, each light's, and @code{verdict}, the measure
## every verdict is made on; @code{X.noise}, materials x 1, the verdicts'
## noise floor: repro_judge's FLIP between two renders of the measured
## data, the mean over the lights, NaN without them; @code{X.noise_light},
## materials x lights), for table.csv and the plots.  Two fits of a
## material whose verdicts differ by no more than its floor tie
## (repro_tie): the published baseline, the best model, where Lafortune
## loses and the FLIP rises say so rather than rank them.
## @end deftypefn
function [sm, X] = db_summary (c, D)
  mats = c.materials;
  ok = find ([D.ok]);
  X = measures (c, D, ok);
  sm = struct ("materials", {mats}, "processed", numel (ok), "failed", {{}}, "methods", struct ());
  sm.methods = across (c, D, ok, X);
  sm.published = published (c, D, ok, X);
  sm.rank_disagreement = disagreement (c, ok, X);
  sm.flip_rises = db_verdicts (c, ok, X, "rises");
  ## the methods that fit the Lafortune model (its verdicts: fails, db_view)
  mp = cellfun (@repro_method, c.methods);
  sm.lafortune_methods = c.methods(strcmp ({mp.model}, "lafortune"));
  sm.fails = db_verdicts (c, ok, X, "fails", sm.lafortune_methods);
  for m = c.methods
    sm.methods.(m{1}) = db_verdicts (c, ok, X, "method", m{1}, sm.methods.(m{1}));
  endfor
  for i = find (! [D.ok])
    sm.failed{end+1} = struct ("material", mats{i}, "error", D(i).error);
  endfor
  sm.models = db_models (c, D, ok, mats, X);
  steps = repro_files ().steps;
  for s = {steps([steps.database]).name}
    t = arrayfun (@(i) D(i).rec.(s{1}).time, ok);
    if (isempty (t))
      t = NaN;
    endif
    sm.stage_time.(s{1}) = t(:)';
  endfor
  sm.psnr = X.psnr.pov;
  sm.psnr_rt = X.psnr.rt;
  sm.flip = X.flip.pov;
  sm.flip_rt = X.flip.rt;
  sm.deltae = X.deltae.pov;
  sm.deltae_rt = X.deltae.rt;
  sm.hue = X.hue.pov;
  sm.hue_rt = X.hue.rt;
  sm.verdict = X.verdict;
  sm.heldout = struct ("lights", {{c.judge.label}}, "flip", X.flip.heldout, "deltae", X.deltae.heldout,
                       "psnr", X.psnr.heldout, "hue", X.hue.heldout, "noise_flip", X.noise_light,
                       "noise_flip_mean", X.noise, "noise", noise_stats (c, ok, X));
  scene = repro_scene (c);
  sm.settings = struct ("scene", scene.name, "width", scene.width, "height", scene.height,
                        "spp", scene.spp, "pov_antialias", c.pov_aa, "max_angle", c.max_angle,
                        "lobes", c.lobes, "methods", {c.methods}, "models", {c.models},
                        "metals", {c.metals}, "quick", c.quick,
                        "fail_flip", c.fail_flip, "fail_flip_gain", c.fail_flip_gain,
                        "fail_flip_drop", c.fail_flip_drop, "judge", {{c.judge.name}},
                        "judge_samples", c.judge_samples, "judge_spp", c.judge_spp,
                        "merl_dir", c.merl_dir, "published", c.published,
                        "date", datestr (now (), "yyyy-mm-dd HH:MM"), "octave", OCTAVE_VERSION);
  ## the renderers' agreement on the same model, over every fit
  ag = [];
  for i = ok
    for m = c.methods
      ag = [ag, [D(i).rec.render_fits.(m{1}).renderers_psnr]];
    endfor
  endfor
  sm.renderers_psnr = struct ("worst", NaN, "median", NaN, "fits", numel (ag));
  if (! isempty (ag))
    sm.renderers_psnr.worst = min (ag);
    sm.renderers_psnr.median = median (ag);
  endif
  sm.sheets = arrayfun (@(d) sheet_files (d), D);
  sm.ok = [D.ok];
endfunction

## every measure (materials x lobes) per method and renderer: X.flip.pov.scene,
## X.deltae.rt.inplane, ...; held out: the means over JUDGE's lights
## (repro_judge, rt_render), which no fit was made for; every verdict is made
## on them ("verdict"), and on the in-sample POV-Ray renders only without
## held-out lights
function X = measures (c, D, ok)
  n = numel (c.materials);
  nk = numel (c.lobes);
  nj = numel (c.judge);
  X = struct ();
  for q = {"psnr", "flip", "deltae", "hue"}
    for r = {"pov", "rt"}
      for m = [c.methods, {"ngan2005"}]   # and the published fit, where there is one
        X.(q{1}).(r{1}).(m{1}) = nan (n, nk);
        for i = ok
          if (isfield (D(i).rec.render_fits, m{1}))
            X.(q{1}).(r{1}).(m{1})(i,:) = repro_row (D(i).rec.render_fits.(m{1}), [q{1} "_" r{1}], nk);
          endif
        endfor
      endfor
    endfor
  endfor
  for q = {"psnr", "flip", "deltae", "hue"}
    for m = [c.methods, {"ngan2005"}]
      X.(q{1}).heldout.(m{1}) = nan (n, nk);
      X.(q{1}).light.(m{1}) = nan (n, nk, nj);
      for i = ok
        if (isfield (D(i).rec.judge, m{1}))
          r = D(i).rec.judge.(m{1});
          k = min (numel (r), nk);
          X.(q{1}).heldout.(m{1})(i,1:k) = repro_row (r, [q{1} "_mean"], k);
          for l = 1:nj
            X.(q{1}).light.(m{1})(i,1:k,l) = arrayfun (@(x) x.(q{1})(l), r(1:k));
          endfor
        endif
      endfor
    endfor
    X.(q{1}).verdict = X.(q{1}).(merge (nj > 0, "heldout", "pov"));
  endfor
  ## the verdicts' noise floor: two renders of the measured data (NaN where
  ## the record has none: JUDGE empty, or a record older than the floor)
  X.noise = nan (n, 1);
  X.noise_light = nan (n, nj);
  for i = ok
    J = D(i).rec.judge;
    if (nj > 0 && isfield (J, "noise_flip") && isnumeric (J.noise_flip) && numel (J.noise_flip) == nj)
      X.noise_light(i,:) = J.noise_flip(:)';
      X.noise(i) = mean (X.noise_light(i,:));
    endif
  endfor
  if (nj > 0)
    X.verdict = sprintf ("held-out FLIP (the mean over %s, rt_render; no fit was made for these lights)",
                         strjoin ({c.judge.label}, ", "));
  else
    X.verdict = "in-sample FLIP (POV-Ray renders in the light the scene fits were made for: JUDGE is empty)";
  endif
endfunction

## per method and lobe count: the medians over the processed materials of
## every measure (in-sample by both renderers, held out), the worst and best
## PSNR, the worst FLIP, and the median cosine-weighted rmse of the fits
function S = across (c, D, ok, X)
  S = struct ();
  mats = c.materials;
  nk = numel (c.lobes);
  for m = c.methods
    s = struct ("label", repro_method (m{1}).label);
    for q = {"psnr", "flip", "deltae", "hue"}
      for r = {"", "_rt", "_heldout"}
        s.(["median_" q{1} r{1}]) = nan (1, nk);
      endfor
    endfor
    s.worst_psnr = s.best_psnr = s.worst_flip = s.median_cos_rmse = nan (1, nk);
    s.worst_material = s.worst_flip_material = repmat ({""}, 1, nk);
    for j = 1:nk
      x = X.psnr.pov.(m{1})(ok,j);
      if (isempty (x))
        continue;
      endif
      for q = {"psnr", "flip", "deltae", "hue"}
        s.(["median_" q{1}])(j) = median (X.(q{1}).pov.(m{1})(ok,j));
        s.(["median_" q{1} "_rt"])(j) = median (X.(q{1}).rt.(m{1})(ok,j));
        s.(["median_" q{1} "_heldout"])(j) = median (X.(q{1}).heldout.(m{1})(ok,j));
      endfor
      [s.worst_psnr(j), iw] = min (x);
      s.worst_material{j} = mats{ok(iw)};
      [s.worst_flip(j), iwf] = max (X.flip.pov.(m{1})(ok,j));
      s.worst_flip_material{j} = mats{ok(iwf)};
      s.best_psnr(j) = max (x);
      s.median_cos_rmse(j) = median (arrayfun (@(i) mean (D(i).rec.fit.(m{1}).errors.(repro_method (m{1}).base).cos_rmse(c.lobes(j),:)), ok));
    endfor
    S.(m{1}) = s;
  endfor
endfunction

## The baseline: the published 1-lobe fits (PUBLISHED, rendered by
## repro_render_fits and judged by repro_judge as the method ngan2005)
## against the recommended method's 1-lobe fit, on the verdicts' measure
function S = published (c, D, ok, X)
  S = struct ("materials", {{}}, "flip", [], "psnr", [], "deltae", [], "hue", [], "flip_in_sample", [],
              "recommended_flip", [], "recommended_psnr", [], "recommended_better", NaN, "not_better", {{}},
              "tied", {{}}, "noise_flip", []);
  has = ok(arrayfun (@(i) isfield (D(i).rec.render_fits, "ngan2005"), ok));
  if (isempty (has))
    return;
  endif
  S.materials = c.materials(has);
  for q = {"flip", "psnr", "deltae", "hue"}
    S.(q{1}) = X.(q{1}).verdict.ngan2005(has,1)';
  endfor
  S.flip_in_sample = X.flip.pov.ngan2005(has,1)';
  S.noise_flip = X.noise(has)';
  rec = "general";
  j1 = find (c.lobes == 1, 1);
  if (any (strcmp (c.methods, rec)) && ! isempty (j1))
    S.recommended_flip = X.flip.verdict.(rec)(has,j1)';
    S.recommended_psnr = X.psnr.verdict.(rec)(has,j1)';
    ## within the material's noise floor: a tie, neither better
    tie = repro_tie (S.recommended_flip, S.flip, X.noise(has)');
    win = S.recommended_flip < S.flip & ! tie;
    S.recommended_better = sum (win);
    S.tied = c.materials(has(tie));
    S.not_better = c.materials(has(! win & ! tie));
    S.medians = struct ("flip", median (S.flip), "recommended_flip", median (S.recommended_flip),
                        "psnr", median (S.psnr), "recommended_psnr", median (S.recommended_psnr));
  endif
endfunction

## the noise floor over the processed materials OK: its median, its
## largest and that material (NaN, "" without a floor)
function S = noise_stats (c, ok, X)
  S = struct ("median", NaN, "max", NaN, "max_material", "");
  x = X.noise(ok);
  if (any (isfinite (x)))
    S.median = median (x(isfinite (x)));
    [S.max, im] = max (x);
    S.max_material = c.materials{ok(im)};
  endif
endfunction

## How many pairs of fits PSNR and FLIP rank differently (one says the first
## is better, the other the second), within each material (all its fits) and
## across materials (the same method and lobe count), and how many of them
## by more than FAIL_FLIP_DROP of FLIP; the widest such pair (POV-Ray)
function S = disagreement (c, ok, X)
  S = struct ();
  gap = c.fail_flip_drop;
  nk = numel (c.lobes);
  for r = {"pov", "rt"}
    A = X.psnr.(r{1});
    B = X.flip.(r{1});
    w = a = zeros (1, 3);          # pairs, ranked differently, ... by more than GAP of FLIP
    best = [];
    for i = ok
      pa = cellfun (@(m) A.(m)(i,:), c.methods, "uniformoutput", false);
      pb = cellfun (@(m) B.(m)(i,:), c.methods, "uniformoutput", false);
      [n, e] = discordant ([pa{:}], [pb{:}], gap);
      w += n;
      ## the pair ranked differently with the largest FLIP difference (an example)
      if (strcmp (r{1}, "pov") && ! isempty (e) && (isempty (best) || e(1) > best(1)))
        best = [e i];
      endif
    endfor
    for m = c.methods
      for j = 1:nk
        a += discordant (A.(m{1})(ok,j), B.(m{1})(ok,j), gap);
      endfor
    endfor
    S.(r{1}) = struct ("within_pairs", w(1), "within_differ", w(2), "within_differ_gap", w(3),
                       "across_pairs", a(1), "across_differ", a(2), "across_differ_gap", a(3));
    if (! isempty (best))
      i = best(4);
      fit = @(q) struct ("method", c.methods{ceil (q / nk)}, "lobes", c.lobes(mod (q - 1, nk) + 1),
                         "psnr", X.psnr.pov.(c.methods{ceil (q / nk)})(i, mod (q - 1, nk) + 1),
                         "flip", X.flip.pov.(c.methods{ceil (q / nk)})(i, mod (q - 1, nk) + 1));
      S.widest = struct ("material", c.materials{i}, "preferred", fit (best(2)), "other", fit (best(3)));
    endif
  endfor
endfunction

## N = [pairs, ranked differently, ... with B apart by more than GAP]: pairs
## of entries where both A (PSNR: higher is better) and B (FLIP: lower is
## better) are finite, and those where A and B disagree; E = [FLIP gap,
## first, second] of the pair ranked differently with the largest FLIP gap
## (the first preferred by PSNR), empty when none
function [N, e] = discordant (a, b, gap)
  a = a(:);
  b = b(:);
  q = find (isfinite (a) & isfinite (b));
  [i, j] = find (triu (true (numel (q)), 1));
  i = q(i);
  j = q(j);
  da = a(i) - a(j);
  db = b(i) - b(j);
  bad = da .* db > 0;               # higher PSNR and higher FLIP
  N = [numel(i), nnz(bad), nnz(bad & abs (db) > gap)];
  e = [];
  if (N(2) > 0)
    [g, k] = max (abs (db) .* bad);
    if (da(k) > 0)
      e = [g, i(k), j(k)];
    else
      e = [g, j(k), i(k)];
    endif
  endif
endfunction

## the contact sheets of material record D ("" when it failed)
function s = sheet_files (d)
  s = struct ("file", "", "heldout_file", "");
  if (d.ok)
    s.file = d.rec.sheet.file;
    if (isfield (d.rec.sheet, "heldout_file") && ! isempty (d.rec.sheet.heldout_file))
      s.heldout_file = d.rec.sheet.heldout_file;
    endif
  endif
endfunction
