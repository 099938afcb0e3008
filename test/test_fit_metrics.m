## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## Integration tests of lafortune_fit with the metrics of metric_spec (the one
## definition, which brdf_error reports): every "weight" name, the
## reported errors equal to brdf_error's, the (a, c) merging exact for
## per-sample weights and transforms, scene tables ("psnr").  Run from the
## package root with
##   addpath ("inst"); pkg load optim; test ("test/test_fit_metrics.m")

%!function S = __plane (m, step)
%!  [TI, TO] = ndgrid (0:step:80, -80:step:80);
%!  wi = [sind(TI(:)) 0*TI(:) cosd(TI(:))];
%!  wo = [sind(TO(:)) 0*TO(:) cosd(TO(:))];
%!  S = struct ("wi", wi, "wo", wo, "rgb", lafortune_eval (m, wi, wo));
%!endfunction
%!function S = __scene (m, step, seed)
%!  ## a scene table: every angle pair twice, with different shares of the
%!  ## image, irradiance (N x 1: the same in each channel) and noisy values
%!  S = __plane (m, step);
%!  n = rows (S.wi);
%!  r = [(1:n)'; (1:n)'];
%!  rand ("state", seed); randn ("state", seed);
%!  S = struct ("kind", "scene", "wi", S.wi(r,:), "wo", S.wo(r,:),
%!              "rgb", S.rgb(r,:) .* (1 + 0.1 * randn (2 * n, 3)),
%!              "weight", rand (2 * n, 1) / (2 * n), "irradiance", 2 * S.wi(r,3) .* (0.5 + rand (2 * n, 1)));
%!endfunction

%!shared truth
%! truth = struct ("rho_d", [0.2 0.1 0.05], "Cxy", [-1 -1 -1; -0.6 -0.6 -0.6], ...
%!                 "Cz", [1 1 1; 0.65 0.65 0.65], "e", [60 60 60; 4 4 4]);

%!test
%! ## every weighting: the reported errors are brdf_error's, and the
%! ## fit's own metric (info.error) too; weighted, noisy table
%! warning ("off", "lafortune:notConverged", "local");
%! S = __plane (truth, 3);
%! randn ("state", 1); rand ("state", 1);
%! S.rgb .*= 1 + 0.1 * randn (size (S.rgb));
%! S.weight = 0.5 + rand (rows (S.wi), 1);
%! for w = {"plain", "cosine", "relative", "log", "cuberoot"}
%!   [m, info] = lafortune_fit (S, 2, "weight", w{1});
%!   tol = 1e-12;
%!   assert (info.error, brdf_error (m, S, w{1}), tol * max (brdf_error (m, S, w{1})));
%!   assert (info.rmse, brdf_error (m, S, "plain"), tol * max (info.rmse));
%!   assert (info.cos_rmse, brdf_error (m, S, "cosine"), tol * max (info.cos_rmse));
%!   assert (info.log_rmse, brdf_error (m, S, "log"), tol * max (info.log_rmse));
%!   assert (info.rel_rmse, info.rmse ./ sqrt (sum (S.weight .* S.rgb .^ 2) / sum (S.weight)), 1e-12);
%! endfor

%!test
%! ## each weighting minimises its own metric: the fit made for a metric is
%! ## no worse in it than the fits made for the others
%! warning ("off", "lafortune:notConverged", "local");
%! S = __plane (truth, 3);
%! randn ("state", 2);
%! S.rgb .*= 1 + 0.2 * randn (size (S.rgb));
%! names = {"plain", "cosine", "relative", "log", "cuberoot"};
%! for i = 1:numel (names)
%!   m{i} = lafortune_fit (S, 1, "weight", names{i}, "tries", 3);
%! endfor
%! for i = 1:numel (names)
%!   own = brdf_error (m{i}, S, names{i});
%!   for k = 1:numel (names)
%!     assert (all (own <= brdf_error (m{k}, S, names{i}) * (1 + 1e-6)), ...
%!             sprintf ("%s fit against the %s fit", names{i}, names{k}));
%!   endfor
%! endfor

%!test
%! ## merging samples of equal (a, c) is exact whatever their weights: a
%! ## scene table with every pair twice (different weights, irradiance and
%! ## values) fits as the table of merged pairs does with "plain" weights
%! ## W = sum (weight irradiance^2) and the W-weighted mean values ("psnr");
%! ## likewise "relative" (weights 1 / max (y, delta)^2 differ per sample)
%! warning ("off", "lafortune:notConverged", "local");
%! S = __scene (truth, 4, 3);
%! n = rows (S.wi) / 2;
%! k = (1:n)';
%! w = S.weight .* S.irradiance .^ 2;
%! W = w(k) + w(k+n);
%! M = struct ("wi", S.wi(k,:), "wo", S.wo(k,:), "rgb", (w(k) .* S.rgb(k,:) + w(k+n) .* S.rgb(k+n,:)) ./ W, ...
%!             "weight", W);
%! ## (converged tightly: the two problems differ in their scale, so leasqr's
%! ## paths differ by rounding; at the default tol they agree to about 1e-5)
%! [ms, is] = lafortune_fit (S, 2, "weight", "psnr", "tol", 1e-14);
%! mm = lafortune_fit (M, 2, "weight", "plain", "tol", 1e-14);
%! fs = lafortune_eval (ms, M.wi, M.wo); fm = lafortune_eval (mm, M.wi, M.wo);
%! assert (max (abs (fs(:) - fm(:))) <= 1e-7 * max (fm(:)));
%! assert (is.error, brdf_error (ms, S, "psnr"), 1e-10);
%! assert (isscalar (is.error));
%! ## relative: per-sample weights from the metric, delta from all samples
%! S2 = rmfield (S, {"kind", "irradiance"});
%! [~, info] = brdf_error (truth, S2, "relative");
%! wr = S2.weight ./ max (S2.rgb, info.delta) .^ 2;
%! [mr, ir] = lafortune_fit (S2, 1, "weight", "relative", "tol", 1e-14);
%! for c = 1:3
%!   Wc = wr(k,c) + wr(k+n,c);
%!   Mc = struct ("wi", M.wi, "wo", M.wo, "weight", Wc, ...
%!                "rgb", repmat ((wr(k,c) .* S2.rgb(k,c) + wr(k+n,c) .* S2.rgb(k+n,c)) ./ Wc, 1, 3));
%!   mc = lafortune_fit (Mc, 1, "channels", c, "tol", 1e-14);
%!   fr = lafortune_eval (mr, M.wi, M.wo)(:,c); fc = lafortune_eval (mc, M.wi, M.wo)(:,c);
%!   assert (max (abs (fr - fc)) <= 1e-7 * max (fc));
%! endfor
%! assert (ir.error, brdf_error (mr, S2, "relative"), 1e-12);

%!test
%! ## a scene-weighted fit is the best of the fits in the scene's PSNR
%! warning ("off", "lafortune:notConverged", "local");
%! S = __scene (truth, 4, 5);
%! mp = lafortune_fit (S, 1, "weight", "psnr");
%! for w = {"plain", "cosine", "relative", "log"}
%!   mw = lafortune_fit (rmfield (S, {"kind", "irradiance"}), 1, "weight", w{1});
%!   assert (brdf_error (mp, S, "psnr") >= brdf_error (mw, S, "psnr") - 1e-9, w{1});
%! endfor

%!test
%! ## scale invariance in the weightings the fitter's own tests leave out
%! warning ("off", "lafortune:notConverged", "local");
%! S = __scene (truth, 8, 4);
%! [m1, i1] = lafortune_fit (S, 1, "weight", "psnr");
%! [n1, j1] = lafortune_fit (S, 1, "weight", "cuberoot");
%! f1 = lafortune_eval (m1, S.wi, S.wo); g1 = lafortune_eval (n1, S.wi, S.wo);
%! for c = [1e-12 1e12]
%!   Sc = S; Sc.rgb = c * S.rgb;
%!   [mc, ic] = lafortune_fit (Sc, 1, "weight", "psnr");
%!   nc = lafortune_fit (Sc, 1, "weight", "cuberoot");
%!   assert (max (abs (lafortune_eval (mc, S.wi, S.wo)(:) / c - f1(:))) <= 1e-9 * max (f1(:)));
%!   assert (max (abs (lafortune_eval (nc, S.wi, S.wo)(:) / c - g1(:))) <= 1e-9 * max (g1(:)));
%!   assert (ic.error, i1.error, 1e-9);
%! endfor

%!test
%! ## zero weights: left out of the fit, in the errors as brdf_error has them
%! S = __scene (truth, 8, 6);
%! S.weight(1:3:end) = 0;
%! [m, info] = lafortune_fit (S, 1, "weight", "psnr");
%! assert (info.error, brdf_error (m, S, "psnr"), 1e-10);
%! assert (info.rmse, brdf_error (m, S, "plain"), 1e-12 * max (info.rmse));

%!test
%! ## the table's name goes into every model (and so into exports)
%! S = __plane (truth, 8);
%! S.name = "synthetic-2";
%! [m, ~, ms] = lafortune_fit (S, 2);
%! assert (m.name, "synthetic-2");
%! assert (ms{1}.name, "synthetic-2");
%! assert (ms{2}.name, "synthetic-2");
%! S.name = "";
%! assert (! isfield (lafortune_fit (S, 1), "name"));

%!error <"psnr" needs a scene table> lafortune_fit (__plane (truth, 8), 1, "weight", "psnr")
%!error id=lafortune:badMetric lafortune_fit (setfield (__plane (truth, 8), "measure", "cosine"), 1, "weight", "cosine")
%!error id=lafortune:badOption lafortune_fit (__plane (truth, 8), 1, "weight", "psnr2")

%!test
%! ## a scene table with a prior: the reported errors are on the table itself,
%! ## as brdf_error has them (the prior is only in the fit)
%! warning ("off", "lafortune:notConverged", "local");
%! S = __scene (truth, 8, 7);
%! P = __plane (truth, 5);
%! S.prior = struct ("wi", P.wi, "wo", P.wo, "rgb", 1.3 * P.rgb);
%! S.prior_weight = 0.5;
%! [m, info, ms] = lafortune_fit (S, 2, "weight", "psnr");
%! T = rmfield (S, {"prior", "prior_weight"});
%! assert (info.error, brdf_error (m, T, "psnr"), 1e-10);
%! assert (info.rmse, brdf_error (m, T, "plain"), 1e-12 * max (info.rmse));
%! assert (info.history(1,:), brdf_error (ms{1}, T, "plain"), 1e-12 * max (info.rmse));
%! assert (info.trace{1}(end,2), info.rmse(1), 1e-12);

%!test
%! ## a table of fewer than 4 samples is fitted with its prior: the minimum
%! ## counts the prior's rows too
%! warning ("off", "lafortune:notConverged", "local");
%! S = __scene (truth, 8, 7);
%! S = struct ("wi", S.wi(1:3,:), "wo", S.wo(1:3,:), "rgb", S.rgb(1:3,:), "weight", S.weight(1:3));
%! P = __plane (truth, 5);
%! S.prior = struct ("wi", P.wi, "wo", P.wo, "rgb", P.rgb);
%! S.prior_weight = 1;
%! [m, info] = lafortune_fit (S, 1);
%! assert (info.n, 3 + rows (P.wi));
%! assert (info.rmse, brdf_error (m, rmfield (S, {"prior", "prior_weight"})), 1e-12 * max (info.rmse));
%!error <at least 4 samples, got 3> lafortune_fit (struct ("wi", repmat ([0 0 1], 3, 1), "wo", repmat ([0 0 1], 3, 1), "rgb", ones (3, 3)), 1)

%!test
%! ## samples on the horizon: 0 in the reported errors, as lafortune_eval has it
%! warning ("off", "lafortune:notConverged", "local");
%! [TI, TO] = ndgrid (0:5:90, -90:5:90);
%! wi = [sind(TI(:)) 0*TI(:) cosd(TI(:))];
%! wo = [sind(TO(:)) 0*TO(:) cosd(TO(:))];
%! S = struct ("wi", wi, "wo", wo, "rgb", lafortune_eval (truth, wi, wo) + 0.01);
%! [m, info] = lafortune_fit (S, 1);
%! assert (info.rmse, brdf_error (m, S, "plain"), 1e-12 * max (info.rmse));
