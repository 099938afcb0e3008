## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn  {lafortune} {@var{model} =} lafortune_fit (@var{S}, @var{nlobes})
## @deftypefnx {lafortune} {@var{model} =} lafortune_fit (@var{S}, @var{nlobes}, @var{name}, @var{value}, @dots{})
## @deftypefnx {lafortune} {[@var{model}, @var{info}, @var{models}] =} lafortune_fit (@dots{})
## Fit an isotropic Lafortune model with @var{nlobes} lobes (1 to 8) to a
## table of BRDF samples, separately per RGB channel (or with lobes shared
## across the channels, @code{"color"}), with the optim package's
## @code{leasqr} (Levenberg-Marquardt).
##
## @var{S} is a struct with fields @code{wi}, @code{wo} (N x 3 unit
## directions, local frame) and @code{rgb} (N x 3), such as
## @code{merl_plane} (the paper's in-plane table), @code{merl_samples}
## (the whole hemisphere) or @code{merl_scene} (what a scene's pixels see)
## return, and optionally @code{weight} (N values, a row or a column,
## finite, >= 0, not all 0): each sample's weight in the least-squares
## objective and in the reported errors (for example a quadrature weight, so
## that the objective is an integral over directions); a sample of weight 0
## is left out.  Each channel has 1 + 3 @var{nlobes} parameters: rho_d, and
## Cxy, Cz, e per lobe (bounds rho_d >= 0, 0 <= e <= 1e7); @code{leasqr}
## gets the analytic Jacobian.
##
## The model sees a pair of directions only through a = ux vx + uy vy and
## c = uz vz, so samples with equal (a, c) are merged first (weights add,
## values average): the fit is the same and every evaluation cheaper.  A
## table of more than 20000 samples (such as every valid bin of the
## hemisphere, about 920000) is reduced to a 512 x 512 grid of (a, c) cells
## instead, finest around the mirror direction, at the weighted mean
## (a, c) of their samples (see @code{"reduce"}); on the MERL stand-ins the
## rmse on all samples then equals that of the fit on the exact groups to 6
## digits.  The data are divided by their largest magnitude before the fit,
## so that the fit does not depend on the data's units: fitting c*y gives c
## times the fit of y (to about 1e-12) for any c > 0.  A channel with no
## positive value raises the warning @code{lafortune:negativeData} (a BRDF
## is non-negative) and gets the zero model.
##
## Initialisation is deterministic: the (k+1)-lobe fit starts from the
## k-lobe solution plus one new lobe.  Candidate lobes (forward lobes from
## steep to flat, retro-reflective, near-normal; exponents 1 to 1e5) get
## their best amplitude, with a change of rho_d, by linear least squares on
## a coarse grid of about @code{"screen_samples"} cells, each represented by
## its group nearest the cell's centre with the cell's weight (a candidate that
## is non-negligible on fewer than 0.2% of them is skipped); the best
## candidate of each direction family is a start, best family first.  The
## first start is refined by Levenberg-Marquardt: a warm-up on the coarse
## grid (to a looser tolerance, 1e-4) when that is much smaller than the
## data and an iteration on all groups is costly (groups times parameters^2
## above 200000: on the in-plane table from 2 lobes on), then a run on all
## groups.  Without a warm-up (on the in-plane table, the first lobe), the
## best candidate is first refined the same way on a finer grid of
## directions and exponents around it.
##
## Every model returned is bounded: at most 10 times the data's largest
## value for every pair of directions with theta_i and theta_o in [0, 90]
## degrees, whatever angles the table covers.  A lobe that exceeds it (it
## fits a few samples and explodes between them, past the table's angles
## or toward grazing ones) is scaled down to the bound (Cxy and Cz by one
## factor) and kept if it still lowers the error, and the next start is
## tried as well; shared lobes are not scaled, and are rejected
## (@code{info.rejected} counts them).  As a start that adds a zero lobe
## reproduces the k-lobe error, the error never increases with more lobes.
## The one fit from @code{"start"} or @code{"init", "plain"} is checked when
## it ends: zero data give the zero model, a result above the bound is
## scaled down, and one that cannot be (rho_d alone above it, or shared
## lobes) is the error @code{lafortune:unboundedFit}, which says where it
## explodes.
##
## Options:
## @table @code
## @item "weight"
## the metric the fit minimises, by the names of @code{brdf_error},
## which reports the same sums (both take them from one definition):
## @code{"plain"} (default, as the paper: the rms error; for a scene table
## @code{"relative"} and for a hemisphere table of @code{merl_samples} the
## general fit, see below), @code{"cosine"}
## (residual times cos theta_i, as Ngan et al. 2005), @code{"relative"}
## (residual divided by max (y, delta)), @code{"log"} (log (f + delta) - log
## (y + delta), after Loew et al. 2012), @code{"cuberoot"} ((f + delta)^(1/3)
## - (y + delta)^(1/3), after Fores et al. 2012), delta = 0.01 times the
## (weighted) median of the positive data, and for a scene table from
## @code{merl_scene} (@code{S.kind} = @code{"scene"}) @code{"psnr"}: weights
## @code{S.weight .* S.irradiance .^ 2}, so that the fit minimises the
## image's MSE, that is maximises the render's PSNR; @code{"select"}, for
## a table with training views (@code{S.views} of @code{merl_samples}), the
## general fit below.  Every metric is a
## weighted sum of squares with one transform per channel, so merging equal
## (a, c) stays exact with per-sample weights.
## @item "max_iter"
## Levenberg-Marquardt iterations per run (default 100; leasqr's own
## default is only 20).
## @item "tol"
## leasqr's tolerance on the fractional improvement of the sum of squares
## (default 1e-7).  A run ends when an iteration improves the sum of
## squares by less than that (leasqr's test), or one iteration earlier when
## the Gauss-Newton step predicts less than half of that (MINPACK's
## predicted reduction, with a margin): that saves leasqr's last iteration,
## which tries five dampings before it gives up.  On the paper materials'
## in-plane tables a run then ends less than 0.8 @code{"tol"} of the sum of
## squares above where leasqr's test alone ends it.
## @item "tries"
## starts screened per added lobe (default 1, and Inf, every direction
## family, for a scene table and for @code{"psnr"}): with more, the best
## start of each of the first @code{"tries"} direction families gets
## @code{"screen_iter"} iterations (default 8) on the coarse grid and the
## best result goes on.  A picture's error has more local minima than the
## plain one (a highlight fitted by the wrong lobe).
## @item "screen_samples"
## about how many groups the coarse grid for starts has (default 500).
## @item "reduce"
## @code{"auto"} (default: exact (a, c) groups up to 20000 samples, else
## a 512 x 512 grid), @code{"exact"}, or n: an n x n grid of cells.
## @item "start"
## a model with @var{nlobes} lobes to start from instead (no growing).
## @item "init"
## @code{"grow"} (default, as above) or @code{"plain"}: the naive start
## rho_d = 0.1, lobe k: Cxy = -1, Cz = 1, e = 10 k (in the data's units).
## @item "jacobian"
## @code{"analytic"} (default) or @code{"numeric"} (leasqr's finite
## differences, @code{dfdp}).
## @item "bounds"
## true (default) or false (no bounds, as leasqr's defaults).
## @item "channels"
## which channels to fit (default 1:3); the others keep rho_d = 0 and zero
## lobes.
## @item "color"
## @code{"separate"} (default; the paper's): each channel is fitted alone,
## and each channel's lobe finds its own direction and exponent.
## @code{"shared"}: each lobe has one direction (Cxy, Cz) and one exponent
## for every channel and an amplitude per channel (after Ngan et al. 2005),
## rho_d per channel, all fitted in one leasqr run over the channels
## (3 + 5 @var{nlobes} parameters for three channels: the brightest
## channel's amplitude is the size of (Cxy, Cz), the others' are
## amplitudes t >= 0).  The objective is the sum of the channels' sums of
## squares, and the data of every channel are divided by one scale.  A
## highlight then keeps its colour across the sphere.  The result is an
## ordinary model: channel c's lobe is folded into its direction,
## C_c = t_c^(1/e) (Cxy, Cz), which is exact, so every export, renderer and
## tool takes it as it is.  Every table, metric and start works in both
## modes; with @code{"shared"}, @code{info}'s per-channel counts and times
## are those of the one run, and a channel's trace is its rmse along the
## joint run (the joint objective never rises, a single channel's rmse
## may).
## @end table
##
## @var{info} holds @code{weight} and @code{color} (the fit's, defaults
## resolved), @code{n} (samples), @code{groups} (how many the fit
## ran on) and @code{reduce} (@code{"exact"} or @code{"grid N"}), and per
## channel (1 x 3 arrays, each a mean weighted by @code{S.weight}, on all
## samples of @var{S}, a scene table's prior not included, with the models
## evaluated as @code{lafortune_eval} does, 0 on or below the horizon:
## equal to @code{brdf_error}'s values):
## @code{rmse} ("plain"), @code{rel_rmse} (rmse / rms of the data),
## @code{log_rmse} ("log"), @code{cos_rmse} ("cosine"; NaN when
## @code{S.measure} is already Ngan's cosine measure), @code{error} (the
## fitted metric, @code{"weight"}; a scalar, in dB, for @code{"psnr"}),
## @code{iterations},
## @code{full_iterations} (those on all groups), @code{rejected},
## @code{converged} (leasqr's flag), @code{time} (seconds), and
## @code{trace}, a 1 x 3 cell of K x 2 arrays [elapsed seconds, rmse]: the
## rmse of the best parameters found so far (best in the fit's own, possibly
## weighted, objective) against run time, over all lobe counts of the
## growing fit.  Only evaluations on all groups of accepted runs count (not
## the coarse grid, not rejected results), so the last row is
## @code{info.rmse}; with the plain weighting the rmse never rises.  With
## grid cells, the rows are the rmse on the cells and a last row the rmse on
## all samples.  @code{info.history} is nlobes x 3: rmse on all samples
## after each lobe count, and @code{info.lobe_time} (nlobes x 3) the seconds
## from the channel's start until that lobe count was done (growing mode).
## @var{models} is a cell with the fitted models for 1 .. @var{nlobes} lobes
## (growing mode).  When @var{S} has a non-empty @code{name} (as
## @code{merl_plane}, @code{merl_samples} and @code{merl_scene} tables do),
## @var{model} and every model in @var{models} get it as their @code{name},
## so that exports carry the material's name.
##
## A channel that did not converge within @code{max_iter} raises the
## warning @code{lafortune:notConverged}; its parameters are still finite.
##
## @strong{Which fit for the best picture.}  The paper's method (the in-plane
## table of @code{merl_plane}, plain weights, the default for any table but
## a scene's) follows the grazing values and is not what a render shows.
## To fit for a picture, fit the table of what that scene's pixels see:
## @code{lafortune_fit (merl_scene (brdf, scene), k)}.  For a scene table
## the defaults are the fit that looks best, judged as a viewer sees the
## renders (FLIP and CIEDE2000, @code{img_compare}, over the 26 materials of
## the project's data; the README gives the numbers): @code{"relative"}
## weights (each pixel's error relative to its radiance, as the eye sees
## brightness in ratios), every direction family screened for each lobe
## (@code{"tries"} Inf), each channel alone.  The image's own MSE
## (@code{"weight", "psnr"}) maximises PSNR, which the highlight's peak
## dominates: such fits match the peak and give up the body colour and the
## highlight's halo.  The table carries the whole hemisphere as a weak
## prior, which fixes what one view cannot.  A fit made for one scene is
## made for that scene, and is judged fairly only in light it was not made
## for.
##
## @strong{The general fit, when the scene is not known.}
## @code{lafortune_fit (merl_samples (brdf), k)} with no options fits the
## whole hemisphere with each candidate weighting (log and cube root),
## renders every fit of 1 to k lobes in the table's training views
## (@code{S.views}: a small sphere under three directional lights) and
## keeps for each lobe count the one that looks best there by FLIP, a fit
## of fewer lobes padded with lobes of zero amplitude when that looks
## better (two stages, as Bieron and Peers 2020).  @code{info.weight} is
## the weighting kept and @code{info.selection} the candidates' scores.
## This is the toolbox's recommended fit: the pipelines judge it, and every
## other fit, under held-out light (the README gives the numbers).  Giving
## a @code{"weight"} fits that weighting alone.
##
## @example
## @group
## brdf = merl_standin ("green-metallic-paint");
## S = merl_plane (brdf);                      # in plane, grazing left out
## [m, info, all] = lafortune_fit (S, 3);
## info.history                                 # rmse for 1, 2, 3 lobes
## brdf_export (all@{2@}, "gmp-2lobe.json", "json");
## H = merl_samples (brdf);                     # every valid bin
## m3 = lafortune_fit (H, 3);                   # the general fit
## m3p = lafortune_fit (H, 3, "weight", "plain"); # plain solid-angle weights
## m3l = lafortune_fit (H, 3, "weight", "log");  # another metric
## m3s = lafortune_fit (H, 3, "color", "shared"); # one lobe shape for R, G, B
## sc = scene_make ("sphere", "size", [64 64], "spp", 1);
## ms = lafortune_fit (merl_scene (brdf, sc), 2);  # the fit that looks best there
## @end group
## @end example
## @seealso{merl_plane, merl_samples, lafortune_eval, brdf_export}
## @end deftypefn
function [model, info, models] = lafortune_fit (S, nlobes, varargin)
  if (nargin < 2)
    print_usage ();
  endif
  if (! (isnumeric (nlobes) && isscalar (nlobes) && nlobes == fix (nlobes)
         && nlobes >= 1 && nlobes <= 8))
    error ("lafortune:badLobes", "lafortune_fit: NLOBES must be an integer from 1 to 8, got %s",
           num2str (nlobes));
  endif
  opt = __lafortune_parse_opts__ (varargin, "lafortune_fit",
                    struct ("weight", [], "max_iter", 100, "tol", 1e-7, "tries", [],
                            "screen_iter", 8, "screen_samples", 500, "reduce", "auto",
                            "start", [], "init", "grow", "jacobian", "analytic",
                            "bounds", true, "channels", 1:3, "color", []));
  opt = fit_defaults (opt, S);
  if (strcmp (opt.weight, "select"))    # the general fit: chosen by the table's views
    V = select_views (S, "lafortune_fit");
    S = rmfield (S, "views");
    [model, info, models] = fit_select (V, nlobes,
                                        @(w) lafortune_fit (S, nlobes, varargin{:}, "weight", w));
    return;
  endif
  opt = check_opts (opt, nlobes);
  ## the table as brdf_error checks it, with a scene table's prior
  [S, wt, n0] = fit_table (S, opt.weight, "lafortune_fit");
  pkg_load_optim ();

  opt.energy = false;
  [models, info] = fit_driver (S, wt, n0, __lafortune_model_def__ ("lafortune"), nlobes, opt,
                               "lafortune_fit");
  model = models{end};
  [model, models] = fit_table (S, model, models);   # the table's name
endfunction

## The options checked, as lafortune_fit's help describes them
function opt = check_opts (opt, nlobes)
  weights = metric_spec ();
  if (! ischar (opt.weight) || ! any (strcmp (opt.weight, weights)))
    error ("lafortune:badOption", "lafortune_fit: WEIGHT must be one of %s",
           strjoin (weights, ", "));
  endif
  if (! ischar (opt.init) || ! any (strcmp (opt.init, {"grow", "plain"})))
    error ("lafortune:badOption", "lafortune_fit: INIT must be \"grow\" or \"plain\"");
  endif
  if (! ischar (opt.color) || ! any (strcmpi (opt.color, {"separate", "shared"})))
    error ("lafortune:badOption", "lafortune_fit: COLOR must be \"separate\" or \"shared\"");
  endif
  opt.color = lower (opt.color);
  if (! ischar (opt.jacobian) || ! any (strcmp (opt.jacobian, {"analytic", "numeric"})))
    error ("lafortune:badOption", "lafortune_fit: JACOBIAN must be \"analytic\" or \"numeric\"");
  endif
  if (! isscalar (opt.max_iter) || ! (opt.max_iter >= 1))
    error ("lafortune:badOption", "lafortune_fit: MAX_ITER must be a positive integer");
  endif
  if (! isscalar (opt.tol) || ! (opt.tol >= 0))
    error ("lafortune:badOption", "lafortune_fit: TOL must be a scalar >= 0");
  endif
  if (! isscalar (opt.tries) || ! (opt.tries >= 1))
    error ("lafortune:badOption", "lafortune_fit: TRIES must be a positive integer");
  endif
  if (! isscalar (opt.screen_samples) || ! (opt.screen_samples >= 1))
    error ("lafortune:badOption", "lafortune_fit: SCREEN_SAMPLES must be a positive number");
  endif
  if (! ((ischar (opt.reduce) && any (strcmp (opt.reduce, {"auto", "exact"})))
         || (isnumeric (opt.reduce) && isscalar (opt.reduce) && opt.reduce >= 1
             && opt.reduce == fix (opt.reduce))))
    error ("lafortune:badOption",
           "lafortune_fit: REDUCE must be \"auto\", \"exact\" or a positive integer (grid cells per axis)");
  endif
  if (! isempty (opt.start))
    opt.start = __lafortune_check_model__ (opt.start, "lafortune_fit", "lafortune");
    if (rows (opt.start.Cxy) != nlobes)
      error ("lafortune:badOption", "lafortune_fit: START has %d lobes, NLOBES is %d",
             rows (opt.start.Cxy), nlobes);
    endif
  endif
  if (! isnumeric (opt.channels) || isempty (opt.channels) || any (! ismember (opt.channels, 1:3)))
    error ("lafortune:badOption", "lafortune_fit: CHANNELS must be a subset of 1:3");
  endif
endfunction

%!demo
%! ## the paper's flow on a synthetic material: in-plane table, 1/2/3 lobes
%! truth = struct ("rho_d", [0.05 0.1 0.02], "Cxy", [-1 -1 -1; -0.7 -0.7 -0.7], ...
%!                 "Cz", [1 1 1; 0.72 0.72 0.72], "e", [200 200 200; 8 8 8]);
%! brdf = merl_synth (truth, "noise", 0.02);
%! S = merl_plane (brdf);
%! [m, info, models] = lafortune_fit (S, 3);
%! printf ("rmse (R G B) for 1, 2, 3 lobes:\n"); disp (info.history);
%! k = S.theta_i == 30;
%! semilogy (S.theta_o(k), S.rgb(k,2), "k.", S.theta_o(k), lafortune_eval (models{1}, S.wi(k,:), S.wo(k,:))(:,2), ...
%!           S.theta_o(k), lafortune_eval (models{2}, S.wi(k,:), S.wo(k,:))(:,2));
%! legend ("data", "1 lobe", "2 lobes"); xlabel ("theta_o (deg)");

%!function S = __plane (m, ti, to, cls)
%!  if (nargin < 2)
%!    ti = 0:2:80;
%!  endif
%!  if (nargin < 3)
%!    to = -80:2:80;
%!  endif
%!  [TI, TO] = ndgrid (ti, to);
%!  wi = [sind(TI(:)) 0*TI(:) cosd(TI(:))];
%!  wo = [sind(TO(:)) 0*TO(:) cosd(TO(:))];
%!  S = struct ("wi", wi, "wo", wo, "rgb", lafortune_eval (m, wi, wo));
%!  if (nargin > 3)
%!    S.wi = cast (S.wi, cls); S.wo = cast (S.wo, cls); S.rgb = cast (S.rgb, cls);
%!  endif
%!endfunction
%!function S = __stiff (e)
%!  ## dense samples around the mirror direction, where a sharp lobe lives
%!  m = struct ("rho_d", [0.1 0.1 0.1], "Cxy", -[1 1 1], "Cz", [1 1 1], "e", e * [1 1 1]);
%!  w = sqrt (2 / e) * 180 / pi;     # lobe half-width in degrees
%!  ti = 5:10:75;
%!  [TI, D] = ndgrid (ti, [linspace(-6 * w, 6 * w, 61), -80:4:80]);
%!  TO = max (min (-TI + D, 85), -85);
%!  wi = [sind(TI(:)) 0*TI(:) cosd(TI(:))];
%!  wo = [sind(TO(:)) 0*TO(:) cosd(TO(:))];
%!  S = struct ("wi", wi, "wo", wo, "rgb", lafortune_eval (m, wi, wo), "e", e);
%!endfunction
%!function __check_stiff (e)
%!  S = __stiff (e);
%!  [m, info] = lafortune_fit (S, 1, "channels", 2);
%!  assert (all (isfinite ([m.rho_d m.Cxy(:)' m.Cz(:)' m.e(:)'])));
%!  assert (info.rel_rmse(2) < 1e-3);
%!  assert (m.e(2), e, 1e-2 * e);
%!endfunction

%!test
%! ## 1 lobe, noise free: recovered
%! truth = struct ("rho_d", [0.2 0.1 0.05], "Cxy", [-0.9 -1 -1.1], "Cz", [0.8 1 0.9], "e", [5 30 80]);
%! [m, info] = lafortune_fit (__plane (truth), 1);
%! assert (info.rel_rmse < 1e-3);
%! assert (m.e, truth.e, 1e-3 * max (truth.e));
%! assert (m.rho_d, truth.rho_d, 1e-4);

%!test
%! ## 2 and 3 lobes, noise free: recovered; error never grows with lobes
%! truth = struct ("rho_d", [0.05 0.1 0.02], "Cxy", [-1 -1 -1; -0.7 -0.6 -0.8; 0.5 0.5 0.5], ...
%!                 "Cz", [1 1 1; 0.72 0.65 0.8; 0.5 0.5 0.5], "e", [200 150 300; 8 6 10; 3 3 3]);
%! t2 = truth; t2.Cxy(3,:) = []; t2.Cz(3,:) = []; t2.e(3,:) = [];
%! [m2, info2] = lafortune_fit (__plane (t2), 2);
%! assert (info2.rel_rmse < 1e-3);
%! S3 = __plane (truth);
%! [m3, info3, ms] = lafortune_fit (S3, 3);
%! assert (info3.rel_rmse < 1e-3);
%! assert (all (diff (info3.history) <= 0));
%! assert (numel (ms), 3);
%! assert (rows (ms{2}.Cxy), 2);
%! ## the trace: elapsed time ascending, error of the best so far not increasing
%! for c = 1:3
%!   T = info3.trace{c};
%!   assert (columns (T), 2);
%!   assert (all (diff (T(:,1)) >= 0));
%!   assert (all (diff (T(:,2)) <= 1e-15));
%!   assert (T(end,2), info3.rmse(c), 1e-12);
%! endfor

%!test
%! ## on noisy data too the trace ends at the fit's error, and with the plain
%! ## weighting it never rises; with other weightings it ends there as well
%! truth = struct ("rho_d", [0.2 0.1 0.05], "Cxy", [-1 -1 -1; -0.6 -0.6 -0.6], ...
%!                 "Cz", [1 1 1; 0.65 0.65 0.65], "e", [60 60 60; 4 4 4]);
%! S = __plane (truth, 0:1:80, -80:1:80);
%! randn ("state", 7);
%! S.rgb .*= 1 + 0.1 * randn (size (S.rgb));
%! for w = {"plain", "cosine", "log"}
%!   [m, info] = lafortune_fit (S, 3, "weight", w{1}, "channels", 2, "screen_samples", 1000);
%!   T = info.trace{2};
%!   assert (T(end,2), info.rmse(2), 1e-12 * info.rmse(2));
%!   if (strcmp (w{1}, "plain"))
%!     assert (all (diff (T(:,2)) <= 0));
%!   endif
%! endfor

%!test __check_stiff (1)
%!test __check_stiff (10)
%!test __check_stiff (100)
%!test __check_stiff (1e3)
%!test __check_stiff (1e4)
%!test __check_stiff (1e5)

%!test
%! ## Cxy = -Cz exactly
%! truth = struct ("rho_d", [0.1 0.1 0.1], "Cxy", -[0.95 0.95 0.95], "Cz", [0.95 0.95 0.95], "e", [40 40 40]);
%! [m, info] = lafortune_fit (__plane (truth), 1, "channels", 1);
%! assert (info.rel_rmse(1) < 1e-3);
%! assert (m.Cxy(1), -m.Cz(1), 1e-3);

%!test
%! ## a channel that is all zero: zero fit, finite parameters, no error
%! truth = struct ("rho_d", [0.1 0 0.1], "Cxy", -[1 0 1], "Cz", [1 0 1], "e", [20 1 20]);
%! S = __plane (truth);
%! assert (all (S.rgb(:,2) == 0));
%! [m, info] = lafortune_fit (S, 2);
%! assert (all (isfinite ([m.rho_d m.Cxy(:)' m.Cz(:)' m.e(:)'])));
%! assert (info.rmse(2), 0);
%! assert (info.rel_rmse(2), 0);
%! assert (all (lafortune_eval (m, S.wi, S.wo)(:,2) == 0));

%!test
%! ## data spanning 1e-6 to 1e4, plain and log weighting
%! truth = struct ("rho_d", pi * 1e-6 * [1 1 1], "Cxy", -[1 1 1], "Cz", [1 1 1], "e", [300 300 300]);
%! truth.Cxy *= 1e4 ^ (1/300); truth.Cz *= 1e4 ^ (1/300);
%! S = __plane (truth, 0:2:80, [-80:0.5:80]);
%! assert (min (S.rgb(:)) < 2e-6 && max (S.rgb(:)) > 5e3);
%! [m, info] = lafortune_fit (S, 1, "channels", 1);
%! assert (all (isfinite ([m.rho_d(1) m.Cxy(1) m.Cz(1) m.e(1)])));
%! assert (info.rel_rmse(1) < 1e-3);
%! [m, info] = lafortune_fit (S, 1, "channels", 1, "weight", "log");
%! assert (info.log_rmse(1) < 1e-3);
%! [m, info] = lafortune_fit (S, 1, "channels", 1, "weight", "relative");
%! assert (info.rel_rmse(1) < 1e-3);

%!test
%! ## single-precision input
%! truth = struct ("rho_d", [0.2 0.1 0.05], "Cxy", [-0.9 -1 -1.1], "Cz", [0.8 1 0.9], "e", [5 30 80]);
%! [m, info] = lafortune_fit (__plane (truth, 0:2:80, -80:2:80, "single"), 1);
%! assert (isa (m.e, "double"));
%! assert (info.rel_rmse < 1e-3);

%!test
%! ## 20% multiplicative noise: finite, close to the truth, rmse at the noise level
%! truth = struct ("rho_d", [0.2 0.2 0.2], "Cxy", -[1 1 1], "Cz", [1 1 1], "e", [50 50 50]);
%! S = __plane (truth, 0:1:80, -80:1:80);
%! randn ("state", 42);
%! S.rgb .*= 1 + 0.2 * randn (size (S.rgb));
%! [m, info] = lafortune_fit (S, 1, "channels", 1);
%! assert (all (isfinite ([m.rho_d(1) m.Cxy(1) m.Cz(1) m.e(1)])));
%! assert (m.e(1), 50, 5);
%! assert (m.rho_d(1), 0.2, 0.01);
%! assert (info.rel_rmse(1) < 0.25);

%!test
%! ## a start whose second lobe has a negative base everywhere; duplicate lobes
%! truth = struct ("rho_d", [0.1 0.1 0.1], "Cxy", -[1 1 1], "Cz", [1 1 1], "e", [30 30 30]);
%! S = __plane (truth);
%! st = struct ("rho_d", [0.05 0.05 0.05], "Cxy", [-0.9 -0.9 -0.9; 0 0 0], "Cz", [0.9 0.9 0.9; -1 -1 -1], "e", [10 10 10; 5 5 5]);
%! [m, info] = lafortune_fit (S, 2, "start", st, "channels", 1);
%! assert (all (isfinite ([m.rho_d m.Cxy(:)' m.Cz(:)' m.e(:)'])));
%! assert (info.rel_rmse(1) < 1e-3);
%! dup = st; dup.Cxy(2,:) = dup.Cxy(1,:); dup.Cz(2,:) = dup.Cz(1,:); dup.e(2,:) = dup.e(1,:);
%! [m, info] = lafortune_fit (S, 2, "start", dup, "channels", 1);
%! assert (all (isfinite ([m.rho_d m.Cxy(:)' m.Cz(:)' m.e(:)'])));
%! assert (info.rel_rmse(1) < 1e-3);

%!test
%! ## whole hemisphere of a MERL-format material (samples at the grid points)
%! truth = struct ("rho_d", [0.1 0.05 0.02], "Cxy", -[1 1 1], "Cz", [0.9 0.9 0.9], "e", [20 40 60]);
%! S = merl_samples (merl_synth (truth), "max_samples", 20000, "views", false);
%! [m, info] = lafortune_fit (S, 1);
%! assert (info.rel_rmse < 1e-3);

%!test
%! ## cosine weighting; the paper's setup (numeric Jacobian, plain start, no bounds)
%! truth = struct ("rho_d", [0.2 0.1 0.05], "Cxy", [-0.9 -1 -1.1], "Cz", [0.8 1 0.9], "e", [5 30 80]);
%! S = __plane (truth);
%! [m, info] = lafortune_fit (S, 1, "weight", "cosine", "channels", 2);
%! assert (info.rel_rmse(2) < 1e-3);
%! [m, info] = lafortune_fit (S, 1, "init", "plain", "jacobian", "numeric", "bounds", false, "channels", 2);
%! assert (all (isfinite ([m.rho_d m.Cxy(:)' m.Cz(:)' m.e(:)'])));

%!test
%! ## scale invariance: fit (c*y) = c*fit (y) in every weighting, c = 1e-12 .. 1e12
%! truth = struct ("rho_d", [0.2 0.1 0.05], "Cxy", [-0.9 -1 -1.1], "Cz", [0.8 1 0.9], "e", [5 30 80]);
%! S = __plane (truth, 0:4:80, -80:4:80);
%! for w = {"plain", "cosine", "relative", "log"}
%!   [m1, i1] = lafortune_fit (S, 1, "weight", w{1});
%!   f1 = lafortune_eval (m1, S.wi, S.wo);
%!   for c = 10 .^ (-12:4:12)
%!     Sc = S; Sc.rgb = c * S.rgb;
%!     [mc, ic] = lafortune_fit (Sc, 1, "weight", w{1});
%!     fc = lafortune_eval (mc, S.wi, S.wo) / c;
%!     assert (max (abs (fc(:) - f1(:))) <= 1e-9 * max (abs (f1(:))), sprintf ("%s, c = %g", w{1}, c));
%!     assert (ic.rmse, c * i1.rmse, 1e-9 * c * max (S.rgb(:)));
%!     assert (ic.rel_rmse < 1e-3);
%!   endfor
%! endfor

%!test
%! ## scale invariance of the grown 3-lobe fit on noisy data
%! truth = struct ("rho_d", [0.05 0.1 0.02], "Cxy", [-1 -1 -1; -0.7 -0.6 -0.8; 0.5 0.5 0.5], ...
%!                 "Cz", [1 1 1; 0.72 0.65 0.8; 0.5 0.5 0.5], "e", [200 150 300; 8 6 10; 3 3 3]);
%! S = __plane (truth, 0:2:80, -80:2:80);
%! randn ("state", 3);
%! S.rgb .*= 1 + 0.05 * randn (size (S.rgb));
%! [m1, i1] = lafortune_fit (S, 3, "channels", 2);
%! f1 = lafortune_eval (m1, S.wi, S.wo)(:,2);
%! for c = [1e-12 1e12]
%!   Sc = S; Sc.rgb = c * S.rgb;
%!   mc = lafortune_fit (Sc, 3, "channels", 2);
%!   fc = lafortune_eval (mc, S.wi, S.wo)(:,2) / c;
%!   assert (max (abs (fc - f1)) <= 1e-9 * max (f1));
%! endfor

%!test
%! ## sample weights: an integer weight is the sample repeated; a zero weight
%! ## leaves the sample out
%! truth = struct ("rho_d", [0.2 0.2 0.2], "Cxy", -[1 1 1], "Cz", [1 1 1], "e", [50 50 50]);
%! S = __plane (truth, 0:2:80, -80:2:80);
%! randn ("state", 5);
%! S.rgb .*= 1 + 0.2 * randn (size (S.rgb));
%! n = rows (S.wi);
%! k = 1 + mod ((1:n)', 3);                 # weights 1, 2, 3
%! Sw = S; Sw.weight = k;
%! r = repelem ((1:n)', k);
%! Sr = struct ("wi", S.wi(r,:), "wo", S.wo(r,:), "rgb", S.rgb(r,:));
%! [mw, iw] = lafortune_fit (Sw, 1, "channels", 1);
%! [mr, ir] = lafortune_fit (Sr, 1, "channels", 1);
%! fw = lafortune_eval (mw, S.wi, S.wo)(:,1); fr = lafortune_eval (mr, S.wi, S.wo)(:,1);
%! assert (max (abs (fw - fr)) <= 1e-9 * max (fr));
%! assert (iw.rmse(1), ir.rmse(1), 1e-9 * ir.rmse(1));
%! z = mod ((1:n)', 4) == 0;
%! Sz = S; Sz.weight = double (! z); Sz.rgb(z,:) = 1e3;   # garbage where the weight is 0
%! So = struct ("wi", S.wi(! z,:), "wo", S.wo(! z,:), "rgb", S.rgb(! z,:));
%! [mz, iz] = lafortune_fit (Sz, 1, "channels", 1);
%! [mo, io] = lafortune_fit (So, 1, "channels", 1);
%! fz = lafortune_eval (mz, S.wi, S.wo)(:,1); fo = lafortune_eval (mo, S.wi, S.wo)(:,1);
%! assert (max (abs (fz - fo)) <= 1e-9 * max (fo));
%! assert (iz.rmse(1), io.rmse(1), 1e-9 * io.rmse(1));

%!test
%! ## grid cells in (a, c) against the exact groups: the same fit to a small,
%! ## bounded difference; noise-free data are recovered either way
%! truth = struct ("rho_d", [0.1 0.05 0.02], "Cxy", [-1 -1 -1; -0.6 -0.6 -0.6], ...
%!                 "Cz", [0.9 0.9 0.9; 0.7 0.7 0.7], "e", [60 60 60; 5 5 5]);
%! S = merl_samples (merl_synth (truth), "max_samples", 30000, "views", false);
%! [me, ie] = lafortune_fit (S, 2, "reduce", "exact", "channels", 2);
%! [mg, ig] = lafortune_fit (S, 2, "reduce", 128, "channels", 2);
%! assert (ie.reduce, "exact");
%! assert (ig.reduce, "grid 128");
%! assert (ig.groups < ie.groups / 2);
%! assert (ie.rel_rmse(2) < 1e-3);
%! assert (ig.rel_rmse(2) < 1e-3);
%! fe = lafortune_eval (me, S.wi, S.wo)(:,2); fg = lafortune_eval (mg, S.wi, S.wo)(:,2);
%! assert (max (abs (fg - fe)) <= 1e-2 * max (fe));
%! ## more than 20000 samples: cells by default
%! [~, ia] = lafortune_fit (S, 1, "channels", 2);
%! assert (ia.reduce, "grid 512");

%!warning id=lafortune:negativeData lafortune_fit (struct ("wi", repmat ([0 0 1], 5, 1), "wo", repmat ([0 0 1], 5, 1), "rgb", -ones (5, 3)), 1, "channels", 1);
%!test
%! ## all-negative data: a warning with an id, and the zero model
%! S = struct ("wi", [sind(0:10:80)' zeros(9,1) cosd(0:10:80)'], "wo", [-sind(0:10:80)' zeros(9,1) cosd(0:10:80)']);
%! S.rgb = -repmat ((1:9)', 1, 3);
%! warning ("off", "lafortune:notConverged", "local");
%! warning ("off", "lafortune:negativeData", "local");
%! [m, info] = lafortune_fit (S, 1, "channels", 2);
%! assert (info.rel_rmse(2), 1, 1e-12);
%! assert (lafortune_eval (m, S.wi, S.wo)(:,2), zeros (9, 1));

%!test
%! ## a run ends one iteration early when the Gauss-Newton step predicts
%! ## less than "tol" of improvement: it loses no more than that against a
%! ## run to a far tighter tolerance, from the grown start and from a start
%! ## at the optimum (on noisy data, a large-residual problem like MERL's)
%! truth = struct ("rho_d", [0.05 0.1 0.02], "Cxy", [-1 -1 -1; -0.7 -0.6 -0.8], ...
%!                 "Cz", [1 1 1; 0.72 0.65 0.8], "e", [200 150 300; 8 6 10]);
%! S = __plane (truth);
%! randn ("state", 7);
%! S.rgb .*= exp (0.2 * randn (size (S.rgb)));
%! for k = 1:2
%!   [m, i1] = lafortune_fit (S, k, "tol", 1e-6);
%!   [~, i2] = lafortune_fit (S, k, "tol", 1e-13, "max_iter", 400);
%!   assert (i1.rmse .^ 2 <= i2.rmse .^ 2 * (1 + 1e-6));
%!   [~, i3] = lafortune_fit (S, k, "start", m, "tol", 1e-6);
%!   assert (i3.iterations <= 2);
%!   assert (i3.rmse .^ 2 <= i1.rmse .^ 2 * (1 + 1e-12));
%! endfor

%!function m = __lobes3 (rho_d, C, e, t)
%!  ## a model whose lobes share direction C(k,:) and exponent e(k) across
%!  ## R, G, B, with amplitudes t(k,:)
%!  nl = rows (C);
%!  m = struct ("rho_d", rho_d, "Cxy", zeros (nl, 3), "Cz", zeros (nl, 3), "e", repmat (e(:), 1, 3));
%!  for k = 1:nl
%!    g = t(k,:) .^ (1 / e(k));
%!    m.Cxy(k,:) = g * C(k,1); m.Cz(k,:) = g * C(k,2);
%!  endfor
%!endfunction
%!function __assert_shared (m)
%!  ## one exponent and one direction per lobe
%!  assert (m.e(:,1) == m.e(:,2) & m.e(:,2) == m.e(:,3));
%!  for k = 1:rows (m.Cxy)
%!    C = [m.Cxy(k,:); m.Cz(k,:)];
%!    assert (abs (C(1,:) .* C(2,[2 3 1]) - C(2,:) .* C(1,[2 3 1])) <= 1e-12 * max (abs (C(:))) ^ 2);
%!  endfor
%!endfunction

%!test
%! ## shared lobes: a shared-lobe model is recovered from its own data at 1, 2
%! ## and 3 lobes (one of them with no blue), and the result has one
%! ## direction and exponent per lobe; the fits grow monotonically
%! truth = __lobes3 ([0.05 0.1 0.02], [-1 1; -0.7 0.72; 0.5 0.5], [200 8 3], [1 0.5 0.2; 0.3 0.6 1; 0.2 0.2 0]);
%! for n = 1:3
%!   t = truth; t.Cxy = t.Cxy(1:n,:); t.Cz = t.Cz(1:n,:); t.e = t.e(1:n,:);
%!   S = __plane (t);
%!   [m, info, ms] = lafortune_fit (S, n, "color", "shared");
%!   assert (info.color, "shared");
%!   assert (info.rel_rmse < 1e-6);
%!   __assert_shared (m);
%!   assert (sort (m.e(:,1)), sort (t.e(:,1)), 1e-5 * max (t.e(:)));
%!   assert (m.rho_d, t.rho_d, 1e-6);
%!   assert (all (diff (info.history) <= 1e-15));
%!   assert (numel (ms), n);
%! endfor

%!test
%! ## shared lobes on noisy data: one direction and exponent per lobe, every
%! ## metric, the trace ends at each channel's rmse; separate fits, with 2
%! ## more parameters per lobe, fit the plain error at least as well
%! truth = __lobes3 ([0.2 0.1 0.05], [-1 1; -0.6 0.65], [60 4], [1 0.8 0.5; 0.3 0.5 1]);
%! S = __plane (truth, 0:2:80, -80:2:80);
%! randn ("state", 11);
%! S.rgb .*= 1 + 0.1 * randn (size (S.rgb));
%! for w = {"plain", "cosine", "relative", "log", "cuberoot"}
%!   [m, info] = lafortune_fit (S, 2, "weight", w{1}, "color", "shared");
%!   __assert_shared (m);
%!   assert (all (isfinite ([m.rho_d m.Cxy(:)' m.Cz(:)' m.e(:)'])));
%!   for c = 1:3
%!     assert (info.trace{c}(end,2), info.rmse(c), 1e-9 * info.rmse(c));
%!   endfor
%!   assert (info.error, brdf_error (m, S, w{1}), 1e-9 * max (info.error));
%! endfor
%! [~, i1] = lafortune_fit (S, 2, "color", "shared");
%! [~, i2] = lafortune_fit (S, 2);
%! assert (sumsq (i2.rmse) <= sumsq (i1.rmse) * (1 + 1e-6));

%!test
%! ## shared lobes: scale invariance, also with one scale per channel
%! truth = __lobes3 ([0.2 0.1 0.05], [-0.9 0.8], 30, [1 0.4 0.1]);
%! S = __plane (truth, 0:4:80, -80:4:80);
%! for w = {"plain", "log"}
%!   m1 = lafortune_fit (S, 1, "weight", w{1}, "color", "shared");
%!   f1 = lafortune_eval (m1, S.wi, S.wo);
%!   for c = [1e-12 1e12]
%!     Sc = S; Sc.rgb = c * S.rgb;
%!     fc = lafortune_eval (lafortune_fit (Sc, 1, "weight", w{1}, "color", "shared"), S.wi, S.wo) / c;
%!     assert (max (abs (fc(:) - f1(:))) <= 1e-8 * max (abs (f1(:))), sprintf ("%s, c = %g", w{1}, c));
%!   endfor
%! endfor

%!test
%! ## shared lobes: stiff lobes (e = 1e4), values over ten decades, the
%! ## paper's plain start, a given start, channels 1 and 3 only, and the
%! ## numeric Jacobian
%! truth = __lobes3 (pi * 1e-6 * [1 2 3], [-1 1], 1e4, [1e4 3e3 1e3]);
%! S = __plane (truth, 0:2:80, -80:0.25:80);
%! [m, info] = lafortune_fit (S, 1, "color", "shared", "weight", "log");
%! __assert_shared (m);
%! assert (info.log_rmse < 1e-3);
%! assert (m.e(1), 1e4, 10);
%! t2 = __lobes3 ([0.05 0.1 0.02], [-1 1; -0.7 0.72], [200 8], [1 0.5 0.2; 0.3 0.6 1]);
%! S2 = __plane (t2);
%! [m, info] = lafortune_fit (S2, 2, "color", "shared", "start", t2);
%! assert (info.rel_rmse < 1e-9);
%! [m, info] = lafortune_fit (S2, 2, "color", "shared", "init", "plain");
%! assert (all (isfinite ([m.rho_d m.Cxy(:)' m.Cz(:)' m.e(:)'])));
%! [m, info] = lafortune_fit (S2, 2, "color", "shared", "channels", [1 3]);
%! assert (m.e(:,1), m.e(:,3));
%! assert (m.rho_d(2), 0);
%! assert (isnan (info.rmse(2)));
%! assert (info.rel_rmse([1 3]) < 1e-6);
%! [m, info] = lafortune_fit (S2, 1, "color", "shared", "jacobian", "numeric");
%! __assert_shared (m);

%!test
%! ## shared lobes on the whole hemisphere (grid cells) and on a scene table
%! ## with the image's weights: finite, shared, and the exported files give
%! ## back the same model
%! truth = __lobes3 ([0.1 0.05 0.02], [-1 0.9], 40, [1 0.6 0.3]);
%! brdf = merl_synth (truth);
%! [m, info] = lafortune_fit (merl_samples (brdf, "max_samples", 30000, "views", false), 1, "color", "shared");
%! __assert_shared (m);
%! assert (info.rel_rmse < 1e-3);
%! sc = scene_make ("sphere", "size", [24 24], "spp", 1);
%! T = merl_scene (brdf, sc);
%! [m, info] = lafortune_fit (T, 2, "color", "shared", "weight", "psnr");
%! __assert_shared (m);
%! assert (info.error > 40);
%! d = tempname (); mkdir (d);
%! unwind_protect
%!   f = fullfile (d, "m.json");
%!   brdf_export (m, f, "json");
%!   r = brdf_import (f);
%!   for fld = {"rho_d", "Cxy", "Cz", "e"}
%!     assert (isequal (r.(fld{1}), m.(fld{1})));
%!   endfor
%!   __assert_shared (r);
%! unwind_protect_cleanup
%!   confirm_recursive_rmdir (false, "local");
%!   rmdir (d, "s");
%! end_unwind_protect

%!test
%! ## a scene table's defaults: the fit that looks best (relative weights,
%! ## every direction family screened, each channel alone); any other
%! ## table: the paper's (plain weights)
%! truth = struct ("rho_d", [0.1 0.05 0.02], "Cxy", -[1 1 1], "Cz", [0.9 0.9 0.9], "e", [40 40 40]);
%! T = merl_scene (merl_synth (truth), scene_make ("sphere", "size", [16 16], "spp", 1));
%! [m, info] = lafortune_fit (T, 1);
%! assert ({info.weight, info.color}, {"relative", "separate"});
%! assert (info.rel_rmse < 0.02);            # (MERL's bins: not the model exactly)
%! assert (m.e, truth.e, 4);
%! [~, info] = lafortune_fit (T, 1, "weight", "psnr", "color", "shared");
%! assert ({info.weight, info.color}, {"psnr", "shared"});
%! [~, info] = lafortune_fit (__plane (truth), 1);
%! assert ({info.weight, info.color}, {"plain", "separate"});

%!warning <did not converge> lafortune_fit (__plane (struct ("rho_d", [0.2 0.1 0.05], "Cxy", [-0.9 -1 -1.1], "Cz", [0.8 1 0.9], "e", [5 30 80])), 1, "max_iter", 1, "channels", 1);

%!shared S0
%! S0 = struct ("wi", repmat ([0 0 1], 5, 1), "wo", repmat ([0 0 1], 5, 1), "rgb", ones (5, 3));
%!function pk = __peak_ratio (m, S)
%!  ## the model's bound on the whole hemisphere over the data's largest value
%!  pk = __lafortune_check_bounded__ (m) ./ max (abs (S.rgb), [], 1);
%!endfunction

%!test
%! ## a lobe that the table (to 40 degrees) supports and that explodes past
%! ## it (1e5 at grazing angles): the fit is bounded on the whole hemisphere
%! truth = struct ("rho_d", [0.1 0.1 0.1], "Cxy", -[1.3 1.3 1.3], "Cz", [1 1 1], "e", [50 50 50]);
%! S = __plane (truth, 0:2:40, -40:2:40);
%! ## (no bounded lobe follows a rise of 344 times within 40 degrees: the
%! ## fit is poor, but not worse than rho_d alone)
%! assert (max (__peak_ratio (truth, S)) > 1e3);
%! warning ("off", "lafortune:notConverged", "local");
%! [m, info] = lafortune_fit (S, 2, "channels", 2);
%! assert (__peak_ratio (m, S)(2) <= 10 + 1e-9);
%! assert (m.e(:,2) > 1);
%! assert (info.history(2,2) <= info.history(1,2) + eps);

%!test
%! ## from a given start that explodes: the fit is repaired to the bound
%! truth = struct ("rho_d", [0.1 0.1 0.1], "Cxy", -[1 1 1], "Cz", [1 1 1], "e", [20 20 20]);
%! S = __plane (truth, 0:2:60, -60:2:60);
%! boom = struct ("rho_d", [0.1 0.1 0.1], "Cxy", -[1.5 1.5 1.5], "Cz", [0.9 0.9 0.9], "e", [300 300 300]);
%! m = lafortune_fit (S, 1, "start", boom, "max_iter", 1);
%! assert (all (__peak_ratio (m, S) <= 10));
%! assert (all (m.e == 300) && all (m.Cxy < 0));

%!test
%! ## a forward lobe the data support up to 80 degrees is still fitted
%! truth = struct ("rho_d", [0.05 0.05 0.05], "Cxy", -[1.02 1.02 1.02], "Cz", [0.95 0.95 0.95],
%!                 "e", [30 30 30]);
%! [m, info] = lafortune_fit (__plane (truth), 1, "channels", 2);
%! assert (info.rel_rmse(2) < 1e-3);
%! assert ([m.Cxy(2) m.Cz(2) m.e(2)], [-1.02 0.95 30], [1e-3 1e-3 0.1]);

%!test
%! ## zero data from an exploding start: the zero model
%! S = __plane (struct ("rho_d", [0 0 0], "Cxy", [0 0 0], "Cz", [0 0 0], "e", [1 1 1]), 0:10:60, -60:10:60);
%! boom = struct ("rho_d", [0 0 0], "Cxy", -[1.5 1.5 1.5], "Cz", [0.9 0.9 0.9], "e", [300 300 300]);
%! m = lafortune_fit (S, 1, "start", boom, "max_iter", 1, "channels", 1);
%! assert (max (lafortune_eval (m, S.wi, S.wo)(:,1)), 0);

%!error id=lafortune:unboundedFit
%! ## shared lobes from an exploding start are not repaired: the error
%! truth = struct ("rho_d", [0.1 0.1 0.1], "Cxy", -[1 1 1], "Cz", [1 1 1], "e", [20 20 20]);
%! S = __plane (truth, 0:4:60, -60:4:60);
%! boom = struct ("rho_d", [0.1 0.1 0.1], "Cxy", -[1.5 1.5 1.5], "Cz", [0.9 0.9 0.9], "e", [300 300 300]);
%! warning ("off", "lafortune:notConverged", "local");
%! lafortune_fit (S, 1, "start", boom, "max_iter", 1, "color", "shared");

%!error <Invalid call> lafortune_fit (S0)
%!error <NLOBES must be an integer from 1 to 8> lafortune_fit (S0, 0)
%!error <NLOBES must be an integer from 1 to 8> lafortune_fit (S0, 9)
%!error id=lafortune:badLobes lafortune_fit (S0, 1.5)
%!error id=lafortune:badSamples lafortune_fit (struct ("wi", 1), 1)
%!error id=lafortune:badSamples lafortune_fit (setfield (S0, "rgb", ones (4, 3)), 1)
%!error id=lafortune:badSamples lafortune_fit (setfield (S0, "rgb", NaN (5, 3)), 1)
%!error id=lafortune:notUnit lafortune_fit (setfield (S0, "wi", repmat ([0 0 2], 5, 1)), 1)
%!error id=lafortune:badOption lafortune_fit (S0, 1, "weight", "huber")
%!error id=lafortune:badOption lafortune_fit (S0, 1, "init", "random")
%!error id=lafortune:badOption lafortune_fit (S0, 2, "start", struct ("rho_d", [0 0 0], "Cxy", [1 1 1], "Cz", [1 1 1], "e", [1 1 1]))
%!error id=lafortune:badModel lafortune_fit (S0, 1, "start", struct ("rho_d", [0 0 0]))
%!error <S.weight must be N x 1> lafortune_fit (setfield (S0, "weight", ones (4, 1)), 1)
%!error <S.weight must be N x 1> lafortune_fit (setfield (S0, "weight", [1 1 -1 1 1]'), 1)
%!error <S.weight must be N x 1> lafortune_fit (setfield (S0, "weight", zeros (5, 1)), 1)
%!error <S.weight must be N x 1> lafortune_fit (setfield (S0, "weight", [1 1 NaN 1 1]'), 1)
%!error <REDUCE must be> lafortune_fit (S0, 1, "reduce", "coarse")
%!error <REDUCE must be> lafortune_fit (S0, 1, "reduce", 0)
%!error <COLOR must be "separate" or "shared"> lafortune_fit (S0, 1, "color", "joint")
%!error id=lafortune:badOption lafortune_fit (S0, 1, "color", 3)

%!test
%! ## the general fit: every candidate weighting fitted, each lobe count's
%! ## best in the training views kept; the views' FLIP never rises
%! truth = struct ("rho_d", [0.05 0.1 0.02], "Cxy", [-1 -1 -1; -0.7 -0.7 -0.7], ...
%!                 "Cz", [1 1 1; 0.72 0.72 0.72], "e", [200 200 200; 8 8 8]);
%! S = merl_samples (merl_synth (truth), "max_samples", 4000);
%! [m, info, models] = lafortune_fit (S, 2);
%! sel = info.selection;
%! assert (sel.weights, {"log", "cuberoot"});
%! assert (size (sel.flip), [2 2]);
%! assert (sel.views, 3);
%! assert (any (strcmp (info.weight, sel.weights)));
%! assert (info.weight, sel.weights{sel.chosen(2)});
%! for k = 1:2
%!   assert (rows (models{k}.Cxy), k);
%!   assert (sel.lobes(k) <= k);
%!   assert (sel.flip(sel.chosen(k), sel.lobes(k)), min (min (sel.flip(:,1:k))));
%! endfor
%! assert (isequal (models{2}, m));
%! ## the kept fit is the fit of its weighting alone (padded with zero lobes)
%! S0 = rmfield (S, "views");
%! [~, ~, mw] = lafortune_fit (S0, 2, "weight", info.weight);
%! k = sel.lobes(2);
%! assert (m.rho_d, mw{k}.rho_d);
%! assert (m.e(1:k,:), mw{k}.e);
%! ## a table without views: log weights; "select" needs the views
%! [~, i0] = lafortune_fit (S0, 1);
%! assert (i0.weight, "log");
%!test
%! ## a candidate whose render is not finite in a view (on this stand-in a
%! ## log-weighted lobe beyond the grazing cut) scores Inf and is not kept:
%! ## the general fit renders finite in every view
%! S = merl_samples (merl_standin ("green-metallic-paint"), "max_samples", 5000);
%! [m, info] = lafortune_fit (S, 3);
%! sel = info.selection;
%! assert (all (isfinite (sel.flip(sub2ind (size (sel.flip), sel.chosen, sel.lobes)))), mat2str (sel.flip, 3));
%! for v = S.views(:)'
%!   assert (all (isfinite (rt_render (v.scene, m, "progress", false, "cache", v.cache)(:))));
%! endfor
%!error <needs a table with training views> lafortune_fit (merl_plane (merl_synth (struct ("rho_d", [0.1 0.1 0.1], "Cxy", -[1 1 1], "Cz", [1 1 1], "e", [10 10 10]))), 1, "weight", "select")
