## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {@var{S} =} db_verdicts (@var{c}, @var{ok}, @var{X}, "rises")
## @deftypefnx {} {@var{S} =} db_verdicts (@var{c}, @var{ok}, @var{X}, "fails", @var{lm})
## @deftypefnx {} {@var{S} =} db_verdicts (@var{c}, @var{ok}, @var{X}, "method", @var{m}, @var{S})
## The verdicts of `make database`'s summary (db_summary), on the measure
## every verdict is made on (@code{X.flip.verdict}: held-out FLIP, or
## in-sample without held-out lights), beside the in-sample POV-Ray FLIP;
## @var{ok} the processed materials (indices into @code{c.materials}).
##
## "rises": the materials where the recommended fit (general) renders worse
## with one more lobe (FLIP up by more than FAIL_FLIP_DROP), each with its
## steps (@code{from}, @code{to} lobes, the changes of @code{flip} and
## @code{psnr}).  "fails": the materials where the Lafortune model (its
## methods @var{lm}) fails:
## its best fit over its methods and lobe counts has FLIP above FAIL_FLIP,
## or that fit's method looks wrong with the fewest lobes and more lobes
## lower its FLIP by less than FAIL_FLIP_GAIN.  "method": the fields of
## method @var{m}'s verdicts added to @var{S}: the materials whose best FLIP
## is above FAIL_FLIP (@code{fails_high}, @code{fails_high_flip}), where
## more lobes do not help (@code{fails_flat}, @code{fails_flat_change}),
## where one more lobe renders worse (@code{falls}, @code{falls_steps},
## @code{largest_flip_rise}; the same in-sample, @code{falls_in_sample}).
## A rise of the verdicts' FLIP counts only where it exceeds the material's
## noise floor too (@code{X.noise}, db_summary: two renders of the measured
## data; within it the two lobe counts tie, repro_tie).
## @end deftypefn
function S = db_verdicts (c, ok, X, what, m, S)
  V = X.flip.verdict;
  ## the least rise that counts, per material: FAIL_FLIP_DROP, or the noise
  ## floor of the verdicts where larger (in-sample: no floor)
  lim = max (c.fail_flip_drop, X.noise(:));
  lim_p = repmat (c.fail_flip_drop, numel (c.materials), 1);
  switch (what)
    case "rises"
      rec = "general";                    # the recommended method
      S = struct ("method", rec, "verdict", {{}}, "largest_rise", NaN, "in_sample", {{}},
                  "verdict_steps", {{}}, "in_sample_steps", {{}});
      if (any (strcmp (c.methods, rec)))
        [up, rise] = falls_of (V.(rec), ok, lim);
        [up_p, rise_p] = falls_of (X.flip.pov.(rec), ok, lim_p);
        S.verdict = c.materials(up);
        S.largest_rise = max ([rise; 0]);
        S.in_sample = c.materials(up_p);
        S.verdict_steps = steps_of (c, up, V.(rec), X.psnr.verdict.(rec), lim);
        S.in_sample_steps = steps_of (c, up_p, X.flip.pov.(rec), X.psnr.pov.(rec), lim_p);
      endif
    case "fails"
      S = fails (c, ok, X, m);
    case "method"
      nk = numel (c.lobes);
      best = min (V.(m)(ok,:), [], 2);
      gain = V.(m)(ok,1) - V.(m)(ok,end);
      high = ok(best > c.fail_flip);
      flat = ok(! (gain >= c.fail_flip_gain) & nk > 1);
      [falls, rise] = falls_of (V.(m), ok, lim);
      [falls_rt, rise_rt] = falls_of (X.flip.pov.(m), ok, lim_p);
      S.fails_high = c.materials(high);
      S.fails_flat = c.materials(flat);
      S.falls = c.materials(falls);
      S.largest_flip_rise = max ([rise; 0]);
      S.falls_in_sample = c.materials(falls_rt);
      S.largest_flip_rise_in_sample = max ([rise_rt; 0]);
      S.fails_high_flip = min (V.(m)(high,:), [], 2)';
      S.fails_flat_change = (V.(m)(flat,end) - V.(m)(flat,1))';
      S.falls_steps = steps_of (c, falls, V.(m), X.psnr.verdict.(m), lim);
      S.falls_in_sample_steps = steps_of (c, falls_rt, X.flip.pov.(m), X.psnr.pov.(m), lim_p);
  endswitch
endfunction

## the materials where the Lafortune model fails (its methods LM), by its
## best fit
function out = fails (c, ok, X, lm)
  V = X.flip.verdict;
  Vp = X.psnr.verdict;
  F = X.flip.pov;
  nk = numel (c.lobes);
  out = {};
  if (isempty (lm))
    return;
  endif
  for i = ok
    fb = cellfun (@(m) min (V.(m)(i,:)), lm);
    [best, b] = min (fb);
    if (! isfinite (best))
      continue;
    endif
    mb = lm{b};
    [~, jb] = min (V.(mb)(i,:));
    gain = V.(mb)(i,1) - V.(mb)(i,end);
    why = {};
    if (best > c.fail_flip)
      why{end+1} = sprintf ("FLIP above %g", c.fail_flip);
    endif
    if (nk > 1 && V.(mb)(i,1) > c.fail_flip && ! (gain >= c.fail_flip_gain))
      why{end+1} = sprintf ("more lobes do not help (FLIP down by less than %g)", c.fail_flip_gain);
    endif
    if (isempty (why))
      continue;
    endif
    out{end+1} = struct ("material", c.materials{i}, "reason", strjoin (why, "; "), "method", mb,
                         "lobes", c.lobes(jb), "flip", best, "flip_in_sample", F.(mb)(i,jb),
                         "psnr", Vp.(mb)(i,jb), "best_psnr", max (cellfun (@(m) max (Vp.(m)(i,:)), lm)),
                         "flip_first", V.(mb)(i,1), "flip_last", V.(mb)(i,end),
                         "psnr_first", Vp.(mb)(i,1), "psnr_last", Vp.(mb)(i,end));
  endfor
endfunction

## The materials (indices into OK) whose FLIP X (materials x lobes) rises
## by more than their LIMIT (materials x 1) with one more lobe, and every
## material's largest rise
function [falls, rise] = falls_of (X, ok, limit)
  rise = zeros (numel (ok), 1);
  if (columns (X) > 1)
    rise = max (diff (X(ok,:), 1, 2), [], 2);
  endif
  falls = ok(rise > limit(ok));
endfunction

## the materials IDX with their steps where FLIP F rises by more than their
## LIMIT (materials x 1), each with the change of FLIP and of PSNR P
function out = steps_of (c, idx, F, P, limit)
  out = {};
  for i = idx(:)'
    d = diff (F(i,:));
    st = {};
    for j = find (d > limit(i))
      st{end+1} = struct ("from", c.lobes(j), "to", c.lobes(j+1), "flip", d(j), "psnr", P(i,j+1) - P(i,j));
    endfor
    out{end+1} = struct ("material", c.materials{i}, "steps", {st});
  endfor
endfunction
