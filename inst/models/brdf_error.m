## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn  {lafortune} {@var{e} =} brdf_error (@var{model}, @var{S})
## @deftypefnx {lafortune} {@var{e} =} brdf_error (@var{model}, @var{S}, @var{metric})
## @deftypefnx {lafortune} {[@var{e}, @var{info}] =} brdf_error (@dots{})
## @deftypefnx {lafortune} {@var{E} =} brdf_error (@{@var{m1}, @var{m2}, @dots{}@}, @var{S}, @{@var{metric1}, @dots{}@})
## Error of an analytic model against a table of BRDF samples, by a named
## metric: the one place where the toolbox's error metrics are defined (the
## fitter minimises the same sums).
##
## @var{model} is an analytic model of any type (a Lafortune model, see
## @code{lafortune_eval}, or another, see @code{brdf_model}), evaluated by
## @code{material_eval}; @var{S} a
## table with fields @code{wi}, @code{wo} (N x 3 unit directions) and
## @code{rgb} (N x 3 reference values), such as @code{merl_plane},
## @code{merl_samples} or @code{merl_scene} return.  When @var{S} has a
## field @code{weight} (N values, >= 0, not all zero; a row or a column,
## checked as lafortune_fit checks it) the means are weighted by it: for
## @code{merl_samples} tables that makes them integrals over direction pairs
## (mean over the kept region's measure).  With y = @code{S.rgb}, f the model,
## s = @code{S.weight} (1 when absent) and, per channel,
## delta = 0.01 times the median of the positive data (weighted by s), and
## f + delta meaning max (f, 0) + delta:
##
## @table @code
## @item "plain"
## (default) sqrt (sum (s (f - y)^2) / sum (s)): the rms error.
## @item "cosine"
## Ngan et al. 2005: the residual times cos theta_i,
## sqrt (sum (s cos^2 theta_i (f - y)^2) / sum (s)), cos theta_i at each
## sample.  On the hemisphere, @code{merl_samples (..., "measure", "cosine")}
## with @code{"plain"} is the exact quadrature of Ngan et al.'s integral (its
## weights integrate the cosine over each bin; @code{"cosine"} is refused
## there), while @code{"cosine"} with solid-angle weights takes the cosine at
## the bins' grid points, an approximation of the same integral (README,
## "Measurements behind the design", says by how much).
## @item "relative"
## sqrt (sum (s ((f - y) / max (y, delta))^2) / sum (s)).
## @item "log"
## after Loew et al. 2012: sqrt (sum (s (log (f + delta) - log (y + delta))^2) / sum (s)).
## @item "cuberoot"
## after Fores et al. 2012: the rms of (f + delta)^(1/3) - (y + delta)^(1/3).
## @item "psnr"
## for a scene table only (@code{S.kind} = @code{"scene"}): the PSNR in dB
## of the image rendered with the model against the reference image,
## 10 log10 (peak^2 / MSE), MSE = sum_k weight_k mean_c ((f - y) irradiance)^2.
## @end table
##
## A scene table (made by @code{merl_scene}) has the fields @code{kind} =
## @code{"scene"}, @code{wi}, @code{wo}, @code{rgb} (the reference BRDF),
## @code{weight} (N x 1: each sample's share of the image, the fraction of
## all the image's pixel samples that see the angle pair lit; sum <= 1),
## @code{irradiance} (N x 1 or N x 3: the light's irradiance times
## cos theta_i there, so radiance = BRDF .* irradiance) and optionally
## @code{peak} (the reference image's maximum, as @code{img_psnr}; default
## max (rgb .* irradiance)).  The MSE is the image's exactly when every pixel
## sees one angle pair, and up to the averaging within pixels otherwise.
##
## @var{e} is 1 x 3 (per channel R, G, B), a scalar for @code{"psnr"}.
## Scaling model and data by c > 0 (delta scales with the data) scales
## @code{"plain"} and @code{"cosine"} by c, @code{"cuberoot"} by c^(1/3) and
## leaves @code{"relative"}, @code{"log"} and @code{"psnr"} unchanged.
## @var{info} holds @code{metric}, @code{delta} (1 x 3), @code{degree} (that
## power of c), @code{ss} (1 x 3 weighted sums of squares), @code{norm}
## (their divisor), @code{peak} (@code{"psnr"}; NaN otherwise),
## @code{relative} (1 x 3: @var{e} over the error of the model that is 0
## everywhere, 0 where @var{e} is 0; for @code{"plain"} the rmse relative to
## the rms of the data, the fitters' @code{rel_rmse}) and
## @code{spec}, the metric's definition as a least-squares fitter uses it:
## per-sample weights @code{spec.w} (N x 3), transformed data @code{spec.ty}
## (N x 3) and handles @code{spec.t (f, c)}, @code{spec.dt (f, c)} (the
## transform of channel c's model values and its derivative), so that
## @code{sqrt (spec.w(:,c)) .* (spec.t (f, c) - spec.ty(:,c))} is the
## residual vector and @code{ss(c)} its squared norm.  The model is
## evaluated once, by @code{material_eval}.
##
## Several models on one table: with @var{model} a cell array of K models
## and @var{metric} a name or a cell array of M names, @var{E} is
## K x 3 x M (K x 1 x M when every metric is @code{"psnr"}, which cannot be
## combined with the others) and @var{info} K x M; row k of metric j is
## bit for bit @code{brdf_error (@var{model}@{k@}, @var{S}, @var{metric}@{j@})}.
## The table is checked, its delta computed and each model evaluated once:
## compare every fit of a material this way.
##
## @example
## @group
## brdf = merl_standin ("red-plastic");
## S = merl_samples (brdf, "max_samples", 20000);
## m = lafortune_fit (S, 1);
## [brdf_error(m, S); brdf_error(m, S, "log")]
## E = brdf_error (@{m, lafortune_fit(S, 2)@}, S, @{"plain", "log"@});
## E(2,:,1)                          # the 2-lobe fit's plain rms error
## @end group
## @end example
## @seealso{lafortune_fit, merl_samples, merl_plane, img_psnr}
## @end deftypefn
function [e, info] = brdf_error (model, S, metric = "plain")
  if (nargin < 2 || nargin > 3)
    print_usage ();
  endif
  models = listed (model, "MODEL", "model", "lafortune:badModel");
  metrics = listed (metric, "METRIC", "name", "lafortune:badMetric").';
  for k = 1:numel (models)
    models{k} = __lafortune_check_model__ (models{k}, "brdf_error");
  endfor
  S = check_table (S, "brdf_error", 1);
  ## the metrics' definitions: the table's delta (its weighted medians) once
  specs = cell (1, numel (metrics));
  delta = [];
  for j = 1:numel (metrics)
    specs{j} = metric_spec (metrics{j}, S, "brdf_error", delta);
    delta = specs{j}.delta;
  endfor
  psnr = strcmp (metrics, "psnr");
  if (any (psnr) && ! all (psnr))
    error ("lafortune:badMetric",
           "brdf_error: \"psnr\" (one value per model) cannot be combined with the per-channel metrics %s",
           strjoin (metrics(! psnr), ", "));
  endif
  K = numel (models);
  M = numel (metrics);
  e = zeros (K, 3 - 2 * all (psnr), M);
  info = struct ("metric", cell (K, M), "delta", [], "degree", [], "ss", [], "norm", [],
                 "peak", [], "relative", [], "spec", []);
  e0 = cell (1, M);
  for k = 1:K
    f = material_eval (models{k}, S.wi, S.wo);
    for j = 1:M
      spec = specs{j};
      ss = zeros (1, 3);
      for c = 1:3
        ss(c) = spec.ss (f(:,c), c);
      endfor
      e(k,:,j) = spec.finish (ss);
      if (nargout > 1)
        if (isempty (e0{j}))           # the zero model's error
          e0{j} = spec.finish (arrayfun (@(c) spec.ss (zeros (rows (f), 1), c), 1:3));
        endif
        info(k,j) = struct ("metric", metrics{j}, "delta", spec.delta, "degree", spec.degree,
                            "ss", ss, "norm", spec.norm, "peak", spec.peak,
                            "relative", relative_error (e(k,:,j), e0{j}), "spec", spec);
      endif
    endfor
  endfor
endfunction

## X as a column cell: {X}, or the cell vector X itself (not empty)
function c = listed (x, name, what, id)
  c = {x};
  if (iscell (x))
    if (isempty (x) || ! isvector (x))
      error (id, "brdf_error: %s must be a %s or a non-empty cell vector of %ss, got a cell of size %s",
             name, what, what, mat2str (size (x)));
    endif
    c = x(:);
  endif
endfunction

%!demo
%! ## the metrics of a 1-lobe fit to a 2-lobe material, over the hemisphere
%! truth = struct ("rho_d", [0.05 0.1 0.02], "Cxy", [-1 -1 -1; -0.7 -0.7 -0.7], ...
%!                 "Cz", [1 1 1; 0.72 0.72 0.72], "e", [200 200 200; 8 8 8]);
%! S = merl_samples (merl_synth (truth), "max_samples", 20000, "views", false);
%! m = lafortune_fit (S, 1);
%! for name = {"plain", "cosine", "relative", "log", "cuberoot"}
%!   printf ("%-9s %s\n", name{1}, mat2str (brdf_error (m, S, name{1}), 4));
%! endfor

%!shared m, S
%! ## a Lambertian model: f = [0.1 0.2 0.4] everywhere
%! m = struct ("rho_d", pi * [0.1 0.2 0.4], "Cxy", zeros (0, 3), "Cz", zeros (0, 3), "e", zeros (0, 3));
%! S = struct ("wi", [0 0 1; sind(60) 0 cosd(60)], "wo", [0 0 1; 0 0 1],
%!             "rgb", [0.2 0.2 0.2; 0.1 0.3 0.5]);

%!test
%! ## hand-computed: residuals f - y are [-0.1 0 0.2; 0 -0.1 -0.1]
%! assert (brdf_error (m, S), sqrt ([0.01 0.01 0.05] / 2), 1e-15);
%! assert (brdf_error (m, S, "plain"), sqrt ([0.01 0.01 0.05] / 2), 1e-15);
%! ## cos theta_i = 1 and 0.5
%! assert (brdf_error (m, S, "cosine"), sqrt ([0.01, 0.0025, 0.04 + 0.0025] / 2), 1e-15);
%! ## delta = 0.01 median = [0.0015 0.0025 0.0035]
%! [e, info] = brdf_error (m, S, "relative");
%! assert (info.delta, [0.0015 0.0025 0.0035], 1e-16);
%! assert (e, sqrt ([0.25, (0.1/0.3)^2, 1 + 0.04] / 2), 1e-14);
%! d = [0.0015 0.0025 0.0035];
%! L = @(x, c) log (x + d(c));
%! assert (brdf_error (m, S, "log"),
%!         sqrt ([(L(0.1,1) - L(0.2,1))^2, (L(0.2,2) - L(0.3,2))^2, (L(0.4,3) - L(0.2,3))^2 + (L(0.4,3) - L(0.5,3))^2] / 2), 1e-14);
%! C = @(x, c) (x + d(c)) ^ (1/3);
%! assert (brdf_error (m, S, "cuberoot"),
%!         sqrt ([(C(0.1,1) - C(0.2,1))^2, (C(0.2,2) - C(0.3,2))^2, (C(0.4,3) - C(0.2,3))^2 + (C(0.4,3) - C(0.5,3))^2] / 2), 1e-14);

%!test
%! ## relative: over the error of the zero model, the rms of the data for plain
%! [e, info] = brdf_error (m, S);
%! assert (info.relative, e ./ sqrt ([0.05 0.13 0.29] / 2), 1e-15);
%! z = brdf_model ("lafortune", "rho_d", 0);
%! [e, info] = brdf_error (m, S, "log");
%! assert (info.relative, e ./ brdf_error (z, S, "log"), 1e-15);

%!test
%! ## weights: the mean is weighted, a zero weight drops the sample
%! Sw = S; Sw.weight = [3; 1];
%! assert (brdf_error (m, Sw), sqrt ([3 * 0.01, 0.01, 3 * 0.04 + 0.01] / 4), 1e-15);
%! Sw.weight = [1; 0];
%! assert (brdf_error (m, Sw), [0.1 0 0.2], 1e-15);
%! assert (brdf_error (m, Sw, "cosine"), [0.1 0 0.2], 1e-15);

%!test
%! ## scene table: the image MSE is sum_k weight_k mean_c ((f - y) E)^2
%! Sc = S; Sc.kind = "scene"; Sc.weight = [0.25; 0.5]; Sc.irradiance = [2; 1];
%! mse = (0.25 * 4 * (0.01 + 0 + 0.04) + 0.5 * (0 + 0.01 + 0.01)) / 3;
%! [e, info] = brdf_error (m, Sc, "psnr");
%! assert (info.peak, 0.5);                     # max (rgb .* irradiance)
%! assert (e, 10 * log10 (0.25 / mse), 1e-12);
%! Sc.peak = 2;
%! assert (brdf_error (m, Sc, "psnr"), 10 * log10 (4 / mse), 1e-12);
%! Sc.irradiance = [2 2 2; 1 1 1];
%! assert (brdf_error (m, Sc, "psnr"), 10 * log10 (4 / mse), 1e-12);
%! ## the model itself: Inf
%! Sc.rgb = lafortune_eval (m, Sc.wi, Sc.wo);
%! assert (brdf_error (m, Sc, "psnr"), Inf);

%!test
%! ## scaling model and data by c: plain, cosine by c; relative, log, psnr
%! ## unchanged; cuberoot by c^(1/3)
%! mm = struct ("rho_d", [0.3 0.2 0.1], "Cxy", [-1 -1 -1; 0.5 0.5 0.5], "Cz", [1 1 1; 0.6 0.6 0.6], "e", [30 20 10; 2 2 2]);
%! t = (5:10:75)';
%! [TI, TO] = ndgrid (t, -t);
%! Ss = struct ("wi", [sind(TI(:)) 0*TI(:) cosd(TI(:))], "wo", [sind(TO(:)) 0*TO(:) cosd(TO(:))]);
%! Ss.rgb = lafortune_eval (mm, Ss.wi, Ss.wo) .* (1 + 0.1 * sin (1:rows (Ss.wi))');
%! Ss.weight = 1 + mod ((1:rows (Ss.wi))', 3);
%! Ss.kind = "scene"; Ss.irradiance = Ss.wi(:,3);
%! c = 7.5;
%! mc = mm; mc.rho_d *= c; mc.Cxy *= c ^ (1/2); mc.Cz *= c ^ (1/2);   # lobe 2 has e = 2
%! mc.Cxy(1,:) = mm.Cxy(1,:) .* c .^ (1 ./ mm.e(1,:)); mc.Cz(1,:) = mm.Cz(1,:) .* c .^ (1 ./ mm.e(1,:));
%! Sc = Ss; Sc.rgb *= c;
%! assert (lafortune_eval (mc, Ss.wi, Ss.wo), c * lafortune_eval (mm, Ss.wi, Ss.wo), 1e-12);
%! for name = {"plain", "cosine", "relative", "log", "cuberoot", "psnr"}
%!   [e1, i1] = brdf_error (mm, Ss, name{1});
%!   e2 = brdf_error (mc, Sc, name{1});
%!   assert (e2, c ^ i1.degree * e1, 1e-10 * abs (e1));
%! endfor

%!test
%! ## several models and metrics at once: each row bit for bit the one call's
%! m2 = struct ("rho_d", [0.2 0.1 0.3], "Cxy", [-0.9 -1 -0.8], "Cz", [0.8 1 0.9], "e", [5 9 3]);
%! Sw = S; Sw.weight = [2; 1];
%! names = {"plain", "cosine", "relative", "log", "cuberoot"};
%! [E, I] = brdf_error ({m, m2, m}, Sw, names);
%! assert (size (E), [3 3 5]);
%! assert (size (I), [3 5]);
%! mm = {m, m2, m};
%! for k = 1:3
%!   for j = 1:5
%!     [e1, i1] = brdf_error (mm{k}, Sw, names{j});
%!     assert (E(k,:,j), e1);
%!     assert (I(k,j).relative, i1.relative);
%!     assert (I(k,j).ss, i1.ss);
%!     assert (I(k,j).delta, i1.delta);
%!     assert (I(k,j).metric, names{j});
%!   endfor
%! endfor
%! assert (any (E(1,:,1) != E(2,:,1)));
%! ## one model in a cell, one metric in a cell: the plain call's shape
%! assert (brdf_error ({m2}, Sw, {"log"}), brdf_error (m2, Sw, "log"));
%! ## psnr alone: one column
%! Sc = S; Sc.kind = "scene"; Sc.weight = [0.25; 0.5]; Sc.irradiance = [2; 1];
%! P = brdf_error ({m, m2}, Sc, "psnr");
%! assert (P, [brdf_error(m, Sc, "psnr"); brdf_error(m2, Sc, "psnr")]);

%!error id=lafortune:badMetric brdf_error ({struct("rho_d", [0 0 0], "Cxy", [], "Cz", [], "e", [])}, struct ("wi", [0 0 1], "wo", [0 0 1], "rgb", [1 1 1], "kind", "scene", "weight", 1, "irradiance", 1), {"plain", "psnr"})
%!error <cannot be combined> brdf_error ({struct("rho_d", [0 0 0], "Cxy", [], "Cz", [], "e", [])}, struct ("wi", [0 0 1], "wo", [0 0 1], "rgb", [1 1 1], "kind", "scene", "weight", 1, "irradiance", 1), {"plain", "psnr"})
%!error <non-empty cell vector of models> brdf_error ({}, struct ("wi", [0 0 1], "wo", [0 0 1], "rgb", [1 1 1]))
%!error <non-empty cell vector of names> brdf_error (struct ("rho_d", [0 0 0], "Cxy", [], "Cz", [], "e", []), struct ("wi", [0 0 1], "wo", [0 0 1], "rgb", [1 1 1]), {})
%!error <METRIC must be one of> brdf_error (struct ("rho_d", [0 0 0], "Cxy", [], "Cz", [], "e", []), struct ("wi", [0 0 1], "wo", [0 0 1], "rgb", [1 1 1]), {"plain", "huber"})
%!error id=lafortune:badModel brdf_error ({struct("rho_d", [0 0 0], "Cxy", [], "Cz", [], "e", []), 3}, struct ("wi", [0 0 1], "wo", [0 0 1], "rgb", [1 1 1]))
%!error <Invalid call> brdf_error (1)
%!error id=lafortune:badModel brdf_error (struct ("rho_d", 1), struct ("wi", [0 0 1], "wo", [0 0 1], "rgb", [1 1 1]))
%!error id=lafortune:badSamples brdf_error (struct ("rho_d", [0 0 0], "Cxy", [], "Cz", [], "e", []), struct ("wi", [0 0 1]))
%!error id=lafortune:badSamples brdf_error (struct ("rho_d", [0 0 0], "Cxy", [], "Cz", [], "e", []), struct ("wi", [0 0 1], "wo", [0 0 1], "rgb", [1 NaN 1]))
%!error id=lafortune:badSamples brdf_error (struct ("rho_d", [0 0 0], "Cxy", [], "Cz", [], "e", []), struct ("wi", [0 0 1], "wo", [0 0 1], "rgb", [1 1]))
%!error id=lafortune:notUnit brdf_error (struct ("rho_d", [0 0 0], "Cxy", [], "Cz", [], "e", []), struct ("wi", [0 0 2], "wo", [0 0 1], "rgb", [1 1 1]))
%!error <METRIC must be one of> brdf_error (struct ("rho_d", [0 0 0], "Cxy", [], "Cz", [], "e", []), struct ("wi", [0 0 1], "wo", [0 0 1], "rgb", [1 1 1]), "huber")
%!error id=lafortune:badMetric brdf_error (struct ("rho_d", [0 0 0], "Cxy", [], "Cz", [], "e", []), struct ("wi", [0 0 1], "wo", [0 0 1], "rgb", [1 1 1]), 3)
%!error <needs a scene table> brdf_error (struct ("rho_d", [0 0 0], "Cxy", [], "Cz", [], "e", []), struct ("wi", [0 0 1], "wo", [0 0 1], "rgb", [1 1 1]), "psnr")
%!test
%! ## the tables lafortune_fit accepts: a weight as a row, an empty weight
%! w = [3 1];
%! e1 = brdf_error (m, setfield (S, "weight", w'));
%! assert (brdf_error (m, setfield (S, "weight", w)), e1);
%! assert (brdf_error (m, setfield (S, "weight", [])), brdf_error (m, S));
%! T = struct ("wi", repmat ([sind(30) 0 cosd(30)], 4, 1), "wo", repmat ([-sind(30) 0 cosd(30)], 4, 1),
%!             "rgb", [1 2 3; 1 2 3; 2 3 4; 2 3 4] / 10, "weight", [1 2 3 4]);
%! [mf, info] = lafortune_fit (T, 1);
%! assert (brdf_error (mf, T), info.rmse, 1e-12);

%!error <S.weight must be N x 1> brdf_error (struct ("rho_d", [0 0 0], "Cxy", [], "Cz", [], "e", []), struct ("wi", [0 0 1], "wo", [0 0 1], "rgb", [1 1 1], "weight", -1))
%!error <S.weight must be N x 1> brdf_error (struct ("rho_d", [0 0 0], "Cxy", [], "Cz", [], "e", []), struct ("wi", [0 0 1], "wo", [0 0 1], "rgb", [1 1 1], "weight", [1; 1]))
%!error <already Ngan's cosine measure> brdf_error (struct ("rho_d", [0 0 0], "Cxy", [], "Cz", [], "e", []), struct ("wi", [0 0 1], "wo", [0 0 1], "rgb", [1 1 1], "weight", 1, "measure", "cosine"), "cosine")
%!error <needs the fields weight> brdf_error (struct ("rho_d", [0 0 0], "Cxy", [], "Cz", [], "e", []), struct ("wi", [0 0 1], "wo", [0 0 1], "rgb", [1 1 1], "kind", "scene"), "psnr")
%!error <S.irradiance must be N x 1 or N x 3> brdf_error (struct ("rho_d", [0 0 0], "Cxy", [], "Cz", [], "e", []), struct ("wi", [0 0 1], "wo", [0 0 1], "rgb", [1 1 1], "kind", "scene", "weight", 1, "irradiance", [1 1]), "psnr")
%!error <S.peak must be> brdf_error (struct ("rho_d", [0 0 0], "Cxy", [], "Cz", [], "e", []), struct ("wi", [0 0 1], "wo", [0 0 1], "rgb", [1 1 1], "kind", "scene", "weight", 1, "irradiance", 1, "peak", 0), "psnr")
%!error <no peak> brdf_error (struct ("rho_d", [0 0 0], "Cxy", [], "Cz", [], "e", []), struct ("wi", [0 0 1], "wo", [0 0 1], "rgb", [0 0 0], "kind", "scene", "weight", 1, "irradiance", 1), "psnr")

%!test
%! ## the derivative that a fitter gets matches the transform; the residual
%! ## vector's squared norm is ss
%! S = struct ("wi", repmat ([0 0 1], 5, 1), "wo", repmat ([0 0 1], 5, 1),
%!             "rgb", [0 0.01 0.1 1 10]' * [1 2 3]);
%! f = [0 1e-4 0.05 0.7 12]';
%! m0 = struct ("rho_d", [0 0 0], "Cxy", zeros (0, 3), "Cz", zeros (0, 3), "e", zeros (0, 3));
%! for name = {"plain", "cosine", "relative", "log", "cuberoot"}
%!   [~, info] = brdf_error (m0, S, name{1});
%!   sp = info.spec;
%!   for c = 1:3
%!     h = 1e-6 * (f + 1e-3);
%!     fd = (sp.t (f + h, c) - sp.t (f, c)) ./ h;
%!     assert (sp.dt (f, c), fd, 1e-4 * abs (fd) + 1e-12);
%!     assert (sp.t (S.rgb(:,c), c), sp.ty(:,c), 1e-15);
%!     r = sqrt (sp.w(:,c)) .* (sp.t (zeros (5, 1), c) - sp.ty(:,c));
%!     assert (sumsq (r), info.ss(c), 1e-14 * info.ss(c));
%!   endfor
%! endfor
