## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn  {lafortune} {@var{model} =} lafortune_fit (@var{S}, @var{nlobes})
## @deftypefnx {lafortune} {@var{model} =} lafortune_fit (@var{S}, @var{nlobes}, @var{name}, @var{value}, @dots{})
## @deftypefnx {lafortune} {[@var{model}, @var{info}, @var{models}] =} lafortune_fit (@dots{})
## Fit an isotropic Lafortune model with @var{nlobes} lobes (1 to 8) to a
## table of BRDF samples, separately per RGB channel, with the optim
## package's @code{leasqr} (Levenberg-Marquardt).
##
## @var{S} is a struct with fields @code{wi}, @code{wo} (N x 3 unit
## directions, local frame) and @code{rgb} (N x 3), such as
## @code{merl_plane} (the paper's in-plane table) or @code{merl_samples}
## (the whole hemisphere) return.  Each channel has 1 + 3 @var{nlobes}
## parameters: rho_d, and Cxy, Cz, e per lobe (bounds rho_d >= 0,
## 0 <= e <= 1e7); @code{leasqr} gets the analytic Jacobian.
##
## Initialisation is deterministic: the (k+1)-lobe fit starts from the
## k-lobe solution plus one new lobe, chosen among candidate starts
## (forward/specular, retro-reflective, off-specular, near-normal; exponents
## 1 to 1e5) by the best linear least-squares amplitude (a candidate that is
## non-negligible on fewer than 0.2% of the samples is skipped); the best
## start of each of the @code{"tries"} most promising direction families is
## refined by Levenberg-Marquardt and the best result kept.  A result that
## exceeds 10 times the data's maximum anywhere in the data's angular range
## (checked on a 0.5-degree in-plane grid, where every lobe's base reaches its
## extremes) is rejected: such a lobe fits a few samples and explodes between
## them or toward grazing angles; the next start is tried instead
## (@code{info.rejected} counts them).  As a start that adds a zero lobe reproduces the k-lobe error, the
## error never increases with more lobes.
##
## Options:
## @table @code
## @item "weight"
## residual weighting: @code{"plain"} (default, as the paper),
## @code{"cosine"} (residual times cos theta_i, as Ngan et al. 2005),
## @code{"relative"} (residual divided by max (y, delta)) or @code{"log"}
## (log (f + delta) - log (y + delta)); delta = 0.01 times the median of the
## positive data.
## @item "max_iter"
## Levenberg-Marquardt iterations per run (default 100; leasqr's own
## default is only 20).
## @item "tol"
## leasqr's tolerance on the fractional improvement of the sum of squares
## (default 1e-7).
## @item "tries"
## candidate starts refined per added lobe (default 2): each gets
## @code{"screen_iter"} iterations (default 8) on an evenly spaced subset of
## about @code{"screen_samples"} samples (default 2000); the best is then
## run to convergence on the subset and, from there, on all samples.
## @item "start"
## a model with @var{nlobes} lobes to start from instead (no growing).
## @item "init"
## @code{"grow"} (default, as above) or @code{"plain"}: the naive start
## rho_d = 0.1, lobe k: Cxy = -1, Cz = 1, e = 10 k.
## @item "jacobian"
## @code{"analytic"} (default) or @code{"numeric"} (leasqr's finite
## differences, @code{dfdp}).
## @item "bounds"
## true (default) or false (no bounds, as leasqr's defaults).
## @item "channels"
## which channels to fit (default 1:3); the others keep rho_d = 0 and zero
## lobes.
## @end table
##
## @var{info} holds, per channel (1 x 3 arrays): @code{rmse},
## @code{rel_rmse} (rmse / rms of the data), @code{log_rmse},
## @code{cos_rmse} (residual times cos theta_i), @code{iterations},
## @code{converged} (leasqr's flag), @code{time} (seconds), and
## @code{trace}, a 1 x 3 cell of K x 2 arrays [elapsed seconds, rmse]: the
## rmse of the best parameters found so far (best in the fit's own, possibly
## weighted, objective) against run time, over all lobe counts of the growing
## fit.  Only evaluations on all samples of accepted runs count (not the
## screening on a subset, not rejected results), so the last row is
## @code{info.rmse}; with the plain weighting the rmse never rises.  @code{info.history} is nlobes x 3: rmse
## after each lobe count, and @code{info.lobe_time} (nlobes x 3) the seconds
## from the channel's start until that lobe count was done (growing mode).  @var{models} is a cell with the fitted models for
## 1 .. @var{nlobes} lobes (growing mode).
##
## A channel that did not converge within @code{max_iter} raises the
## warning @code{lafortune:notConverged}; its parameters are still finite.
##
## @example
## @group
## brdf = merl_standin ("green-metallic-paint");
## S = merl_plane (brdf);                      # in plane, grazing left out
## [m, info, all] = lafortune_fit (S, 3);
## info.history                                 # rmse for 1, 2, 3 lobes
## lafortune_export (all@{2@}, "gmp-2lobe.json", "json");
## @end group
## @end example
## @seealso{merl_plane, merl_samples, lafortune_eval, lafortune_export}
## @end deftypefn
function [model, info, models] = lafortune_fit (S, nlobes, varargin)
  if (nargin < 2)
    print_usage ();
  endif
  S = check_samples (S);
  if (! (isnumeric (nlobes) && isscalar (nlobes) && nlobes == fix (nlobes)
         && nlobes >= 1 && nlobes <= 8))
    error ("lafortune:badLobes", "lafortune_fit: NLOBES must be an integer from 1 to 8, got %s",
           num2str (nlobes));
  endif
  opt = parse_opts (varargin, "lafortune_fit",
                    struct ("weight", "plain", "max_iter", 100, "tol", 1e-7, "tries", 2,
                            "screen_iter", 8, "screen_samples", 2000,
                            "start", [], "init", "grow", "jacobian", "analytic",
                            "bounds", true, "channels", 1:3));
  weights = {"plain", "cosine", "relative", "log"};
  if (! ischar (opt.weight) || ! any (strcmp (opt.weight, weights)))
    error ("lafortune:badOption", "lafortune_fit: WEIGHT must be one of %s",
           strjoin (weights, ", "));
  endif
  if (! ischar (opt.init) || ! any (strcmp (opt.init, {"grow", "plain"})))
    error ("lafortune:badOption", "lafortune_fit: INIT must be \"grow\" or \"plain\"");
  endif
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
  if (! isempty (opt.start))
    opt.start = check_model (opt.start, "lafortune_fit");
    if (rows (opt.start.Cxy) != nlobes)
      error ("lafortune:badOption", "lafortune_fit: START has %d lobes, NLOBES is %d",
             rows (opt.start.Cxy), nlobes);
    endif
  endif
  if (! isnumeric (opt.channels) || any (! ismember (opt.channels, 1:3)))
    error ("lafortune:badOption", "lafortune_fit: CHANNELS must be a subset of 1:3");
  endif
  pkg_load_optim ();

  x = [S.wi(:,1) .* S.wo(:,1) + S.wi(:,2) .* S.wo(:,2), S.wi(:,3) .* S.wo(:,3)];
  cosi = S.wi(:,3);
  opt.guard = guard_set (S);
  z = zeros (nlobes, 3);
  model = struct ("rho_d", [0 0 0], "Cxy", z, "Cz", z, "e", z);
  models = cell (1, nlobes);
  for k = 1:nlobes
    models{k} = struct ("rho_d", [0 0 0], "Cxy", zeros (k, 3), "Cz", zeros (k, 3), "e", ones (k, 3));
  endfor
  model.e(:) = 1;
  nan3 = nan (1, 3);
  info = struct ("nlobes", nlobes, "weight", opt.weight, "n", rows (x),
                 "rmse", nan3, "rel_rmse", nan3, "log_rmse", nan3, "cos_rmse", nan3,
                 "iterations", zeros (1, 3), "full_iterations", zeros (1, 3), "rejected", zeros (1, 3), "converged", true (1, 3), "time", zeros (1, 3),
                 "trace", {cell(1, 3)}, "history", nan (nlobes, 3),
                 "lobe_time", nan (nlobes, 3));
  for c = opt.channels(:)'
    y = S.rgb(:,c);
    t0 = tic ();
    fit_trace ("start");
    opt.channel = c;
    ch = fit_channel (x, y, cosi, nlobes, opt);
    info.time(c) = toc (t0);
    p = ch.p;
    model.rho_d(c) = p(1);
    L = reshape (p(2:end), 3, []).';
    model.Cxy(:,c) = L(:,1); model.Cz(:,c) = L(:,2); model.e(:,c) = L(:,3);
    for k = 1:numel (ch.ps)
      if (isempty (ch.ps{k}))
        continue;
      endif
      Lk = reshape (ch.ps{k}(2:end), 3, []).';
      models{k}.rho_d(c) = ch.ps{k}(1);
      models{k}.Cxy(:,c) = Lk(:,1); models{k}.Cz(:,c) = Lk(:,2); models{k}.e(:,c) = Lk(:,3);
    endfor
    f = lafortune_core (p, x(:,1), x(:,2));
    e = error_stats (f, y, cosi);
    info.rmse(c) = e.rmse; info.rel_rmse(c) = e.rel_rmse;
    info.log_rmse(c) = e.log_rmse; info.cos_rmse(c) = e.cos_rmse;
    info.iterations(c) = ch.iter;
    info.full_iterations(c) = ch.full_iter;
    info.rejected(c) = ch.rejected;
    info.converged(c) = ch.cvg;
    info.history(1:numel (ch.hist),c) = ch.hist(:);
    info.lobe_time(1:numel (ch.ktime),c) = ch.ktime(:);
    T = fit_trace ("get");
    if (isempty (T))
      info.trace{c} = [info.time(c), e.rmse];
    else
      [~, best] = cummin (T(:,2));
      info.trace{c} = [T(:,1), T(best,3)];
    endif
    if (! ch.cvg)
      warning ("lafortune:notConverged",
               "lafortune_fit: channel %d (%d lobes) did not converge in %d iterations; the parameters are finite but may not be optimal",
               c, nlobes, opt.max_iter);
    endif
  endfor
  if (! strcmp (opt.init, "grow") || ! isempty (opt.start))
    models = {model};
  endif
endfunction

function S = check_samples (S)
  if (! isstruct (S) || ! isscalar (S) || ! all (isfield (S, {"wi", "wo", "rgb"})))
    error ("lafortune:badSamples",
           "lafortune_fit: S must be a struct with fields wi, wo, rgb (see merl_plane)");
  endif
  [S.wi, S.wo] = check_dirs (S.wi, S.wo, "lafortune_fit");
  if (! isnumeric (S.rgb) || ! isreal (S.rgb) || ! isequal (size (S.rgb), [rows(S.wi) 3]))
    error ("lafortune:badSamples", "lafortune_fit: S.rgb must be real N x 3 with N = rows (S.wi) = %d",
           rows (S.wi));
  endif
  if (! all (isfinite (S.rgb(:))))
    error ("lafortune:badSamples", "lafortune_fit: S.rgb must be finite (drop invalid samples)");
  endif
  if (rows (S.wi) < 4)
    error ("lafortune:badSamples", "lafortune_fit: S needs at least 4 samples, got %d", rows (S.wi));
  endif
  S.rgb = double (S.rgb);
endfunction

## Direction pairs that span the data's angular range: the in-plane pairs,
## which reach the extremes of every lobe's base (ux vx + uy vy is largest in
## size in the plane).  A fitted model may not exceed GUARD_FACTOR times the
## data's maximum on them: a lobe that fits a few samples and explodes
## between them (or toward grazing angles) is rejected.
function G = guard_set (S)
  amax = acosd (max (min ([S.wi(:,3); S.wo(:,3)]), 0));
  t = linspace (0, amax, max (2, ceil (amax / 0.5) + 1));
  [TI, TO] = ndgrid (t, [-fliplr(t(2:end)), t]);
  G = [sind(TI(:)) .* sind(TO(:)), cosd(TI(:)) .* cosd(TO(:))];
endfunction

function ok = guard_ok (p, G, ymax)
  g = lafortune_core (p, G(:,1), G(:,2));
  ok = all (isfinite (g)) && max (g) <= 10 * max (ymax, realmin);
endfunction

function e = error_stats (f, y, cosi)
  r = f - y;
  e.rmse = sqrt (mean (r .^ 2));
  e.rel_rmse = e.rmse / max (sqrt (mean (y .^ 2)), realmin);
  if (e.rmse == 0)
    e.rel_rmse = 0;
  endif
  d = log_delta (y);
  e.log_rmse = sqrt (mean ((log (max (f, 0) + d) - log (max (y, 0) + d)) .^ 2));
  e.cos_rmse = sqrt (mean ((r .* cosi) .^ 2));
endfunction

function d = log_delta (y)
  yp = y(y > 0);
  if (isempty (yp))
    d = 1;
  else
    d = 0.01 * median (yp);
  endif
endfunction

## --- one channel ----------------------------------------------------------
## The objective is sum_i (w_i (ty_i - tf(f_i)))^2, tf = identity or log.
## Samples with the same (sxy, sz) have the same model value, so they are
## merged first (weights add, targets average): the minimiser is exactly the
## same and every evaluation is cheaper (the in-plane table holds each pair
## of angles twice, as (ti, to) and (-to, -ti)).
function D = make_data (x, y, ty, w, wlin)
  [xg, ~, j] = unique (x, "rows");
  W = accumarray (j, w .^ 2);
  Wl = accumarray (j, wlin .^ 2);
  cnt = accumarray (j, 1);
  D.x = xg;
  D.w = sqrt (W);
  D.ty = accumarray (j, w .^ 2 .* ty) ./ max (W, realmin);
  D.wl = sqrt (Wl);
  D.yl = accumarray (j, wlin .^ 2 .* y) ./ max (Wl, realmin);
  D.cnt = cnt;
  D.ybar = accumarray (j, y) ./ cnt;
  D.n = numel (y);
  D.ssw = sum ((y - D.ybar(j)) .^ 2);              # plain, within groups
  D.wsw = sum ((w .* (ty - D.ty(j))) .^ 2);        # weighted, within groups
endfunction

function E = subset (D, k)
  E = D;
  for f = {"x", "w", "ty", "wl", "yl", "cnt", "ybar"}
    E.(f{1}) = D.(f{1})(k,:);
  endfor
  ## a subset's own within-group terms are not needed: it only ranks starts
  E.n = sum (E.cnt); E.ssw = 0; E.wsw = 0;
endfunction

function e = plain_rmse (D, f)
  e = sqrt ((sum (D.cnt .* (D.ybar - f) .^ 2) + D.ssw) / D.n);
endfunction

function o = objective (D, f, islog, dl)
  o = sqrt ((sum ((D.w .* (D.ty - tfun (f, islog, dl))) .^ 2) + D.wsw) / D.n);
endfunction

function ch = fit_channel (x, y, cosi, nlobes, opt)
  dl = log_delta (y);
  switch (opt.weight)
    case {"plain", "log"}
      w = ones (size (y));
    case "cosine"
      w = cosi;
    case "relative"
      w = 1 ./ max (y, dl);
  endswitch
  islog = strcmp (opt.weight, "log");
  if (islog)
    ty = log (max (y, 0) + dl);
    wlin = 1 ./ (max (y, 0) + dl);     # first-order weights for amplitudes
  else
    ty = y;
    wlin = w;
  endif
  D = make_data (x, y, ty, w, wlin);
  F = @(p) lafortune_core (p, D.x(:,1), D.x(:,2));

  ch = struct ("p", [], "ps", {{}}, "hist", [], "iter", 0, "cvg", true, "full_iter", 0,
               "rejected", 0);
  if (! isempty (opt.start) || strcmp (opt.init, "plain"))
    if (! isempty (opt.start))
      p0 = start_params (opt.start, opt.channel);
    else
      p0 = [0.1; repmat([-1; 1; 0], nlobes, 1)];
      p0(4:3:end) = 10 * (1:nlobes);
    endif
    [ch.p, ch.iter, ch.cvg] = run_lm (D, p0, opt, islog, dl, true);
    fit_trace ("commit");
    ch.full_iter = ch.iter;
    ch.ps = cell (1, nlobes);
    ch.ps{nlobes} = ch.p;
    ch.hist = nan (1, nlobes);
    ch.hist(nlobes) = plain_rmse (D, F (ch.p));
    ch.ktime = nan (1, nlobes);
    return;
  endif

  t0 = tic ();
  ch.ktime = nan (1, nlobes);
  ## 0 lobes: rho_d by weighted least squares
  rho = pi * sum (D.wl .^ 2 .* D.yl) / max (sum (D.wl .^ 2), realmin);
  p = max (rho, 0);
  cur_obj = objective (D, F (p), islog, dl);
  fit_trace ("add", cur_obj, plain_rmse (D, F (p)));
  fit_trace ("commit");
  dirs = [-1 1; 1 1; -1 0.7; -1 1.3; 0 1];
  ## candidate starts are screened on an evenly spaced subset
  m = rows (D.x);
  sub = (1:max (1, floor (m / opt.screen_samples)):m)';
  Ds = subset (D, sub);
  min_support = min (max (8, 0.002 * m), m);
  expo = [1 3 10 30 100 300 1e3 3e3 1e4 3e4 1e5];
  for k = 1:nlobes
    fcur = F (p);
    r = D.yl - fcur;
    cand = zeros (0, 5);     # [obj, cxy, cz, e, family]
    for i = 1:rows (dirs)
      for e = expo
        g = lafortune_core ([0; dirs(i,:)'; e], D.x(:,1), D.x(:,2));
        gg = sum ((D.wl .* g) .^ 2);
        if (gg <= 0)
          continue;
        endif
        s = max (sum (D.wl .^ 2 .* g .* r) / gg, 0);
        if (s <= 0)
          continue;
        endif
        a = s ^ (1 / e);
        if (! isfinite (a) || a <= 0)
          continue;
        endif
        ## a lobe that lives on a handful of samples is no start: skip it
        if (nnz (g > 1e-3 * max (g)) < min_support)
          continue;
        endif
        cand(end+1,:) = [objective(D, fcur + s * g, islog, dl), a * dirs(i,:), e, i];
      endfor
    endfor
    best_p = [p; 0; 0; 1];   # a zero lobe: the k-1 lobe error exactly
    best_obj = cur_obj;
    best_iter = 0; best_cvg = true;
    if (! isempty (cand) && cur_obj > 0)
      ## the best start of each direction family, best families first; each
      ## of the first TRIES gets a few iterations on the subset, the best
      ## then converges on the subset and last on all samples
      [~, order] = sort (cand(:,1));
      [~, first] = unique (cand(order,5), "first");
      order = order(sort (first));
      screen = opt;
      screen.max_iter = min (opt.screen_iter, opt.max_iter);
      it_sum = 0;
      ntry = min (opt.tries, numel (order));
      if (ntry == 1)
        starts = [p; cand(order(1),2:4)'];     # a single start needs no screening
      else
        starts = zeros (numel (p) + 3, ntry);
        sobj = zeros (1, ntry);
        for i = 1:ntry
          [starts(:,i), it] = run_lm (Ds, [p; cand(order(i),2:4)'], screen, islog, dl);
          it_sum += it;
          sobj(i) = objective (Ds, lafortune_core (starts(:,i), Ds.x(:,1), Ds.x(:,2)), islog, dl);
        endfor
        ## the best screened start first
        [~, so] = sort (sobj);
        starts = starts(:,so);
      endif
      ## a result that explodes between the samples is rejected and the next
      ## start tried
      for ps = starts
        if (numel (sub) < m)
          [ps, it] = run_lm (Ds, ps, opt, islog, dl);
          it_sum += it;
        endif
        [pj, it, cv] = run_lm (D, ps, opt, islog, dl, true);
        it_sum += it;
        ch.full_iter += it;
        oj = objective (D, F (pj), islog, dl);
        if (! guard_ok (pj, opt.guard, max (abs (y))))
          ch.rejected += 1;
          fit_trace ("drop");
          continue;
        endif
        if (oj < best_obj)
          best_obj = oj; best_p = pj; best_cvg = cv;
          fit_trace ("commit");
        else
          fit_trace ("drop");
        endif
        break;
      endfor
      best_iter = it_sum;
    endif
    p = best_p;
    cur_obj = best_obj;
    ch.iter += best_iter;
    ch.cvg = best_cvg;
    ch.ps{k} = p;
    ch.hist(k) = plain_rmse (D, F (p));
    ch.ktime(k) = toc (t0);
  endfor
  ch.p = p;
endfunction

function t = tfun (f, islog, d)
  if (islog)
    t = log (max (f, 0) + d);
  else
    t = f;
  endif
endfunction

function p0 = start_params (m, c)
  p0 = [m.rho_d(c); reshape([m.Cxy(:,c) m.Cz(:,c) m.e(:,c)].', [], 1)];
endfunction

## Levenberg-Marquardt on one channel through leasqr
function [p, iter, cvg] = run_lm (D, p0, opt, islog, dl, record = false)
  np = numel (p0);
  F = @(xx, pp) model_fun (D, pp, islog, dl, record);
  lb = -Inf (np, 1); ub = Inf (np, 1);
  lb(1) = 0;
  lb(4:3:end) = 0; ub(4:3:end) = 1e7;
  p0 = min (max (p0, lb), ub);
  options = struct ();
  if (opt.bounds)
    options.bounds = [lb ub];
  endif
  dp = 1e-3 * ones (np, 1);
  if (strcmp (opt.jacobian, "analytic"))
    dFdp = @(xx, f, pp, dpp, FF, varargin) model_jac (D, pp, islog, dl);
  else
    dFdp = "dfdp";
  endif
  ## leasqr reads the global 'verbose'; it must be false here.  Leave the
  ## global space as it was found.
  had = any (strcmp ("verbose", who ("global")));
  global verbose;
  old = verbose;
  verbose = false;
  unwind_protect
    [~, p, cvg, iter] = quiet_leasqr (D.x, D.ty, p0, F, opt.tol, opt.max_iter, D.w, dp, dFdp, options);
  unwind_protect_cleanup
    if (had)
      verbose = old;
    else
      clear -global verbose;
    endif
  end_unwind_protect
  p = real (p(:));
  if (! all (isfinite (p)))
    p = p0;
    cvg = false;
  endif
  if (opt.bounds)
    p = min (max (p, lb), ub);
  endif
endfunction

function varargout = quiet_leasqr (varargin)
  ## leasqr prints " CONVERGENCE NOT ACHIEVED! " itself; we warn instead
  args = varargin;
  [out, varargout{1:4}] = evalc ("leasqr (args{:})");
endfunction

## F for leasqr; on all samples (RECORD) each evaluation is noted for the
## error-against-time trace, kept only if the run's result is accepted
function f = model_fun (D, p, islog, dl, record)
  f = lafortune_core (p, D.x(:,1), D.x(:,2));
  if (record)
    ferr = plain_rmse (D, f);
  endif
  if (islog)
    f = log (max (f, 0) + dl);
  endif
  if (record)
    fit_trace ("add", sqrt ((sum ((D.w .* (D.ty - f)) .^ 2) + D.wsw) / D.n), ferr);
  endif
endfunction

function J = model_jac (D, p, islog, dl)
  [f, J] = lafortune_core (p, D.x(:,1), D.x(:,2));
  if (islog)
    J ./= (max (f, 0) + dl);
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
%! S = merl_samples (merl_synth (truth), "max_samples", 20000);
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

%!warning <did not converge> lafortune_fit (__plane (struct ("rho_d", [0.2 0.1 0.05], "Cxy", [-0.9 -1 -1.1], "Cz", [0.8 1 0.9], "e", [5 30 80])), 1, "max_iter", 1, "channels", 1);

%!shared S0
%! S0 = struct ("wi", repmat ([0 0 1], 5, 1), "wo", repmat ([0 0 1], 5, 1), "rgb", ones (5, 3));
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
