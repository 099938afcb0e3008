## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {@var{ch} =} fit_channel (@var{D}, @var{R}, @var{nlobes}, @var{opt}, @var{G}, @var{p0})
## Fit one channel (private), or several with shared lobes (@code{D.nch} >
## 1, from fit_stack): @var{D} the data, @var{R} a coarser grouping of
## the same data for screening starts (both from fit_data, in the same
## scaled units; @code{D.s} the scale, @code{D.same} and @code{D.P} the
## plain metric, for the trace: see fit_objective), @var{G} the acceptance set (fit_guard).  With a start
## @var{p0} (not empty), one Levenberg-Marquardt run from it; else lobes are added one
## at a time: starts (fit_starts), runs (fit_lm), acceptance (fit_guard and
## a lower objective; a zero lobe keeps the previous error, so more lobes
## never fit worse).
##
## @var{ch}: @code{p} (scaled units), @code{ps} (cell, per lobe count),
## @code{ktime} (seconds until each lobe count was done), @code{iter},
## @code{full_iter}, @code{cvg}, @code{rejected}, and @code{trace}: rows
## [seconds, objective, rmse] of the evaluations on @var{D} of accepted runs.
## @end deftypefn
function ch = fit_channel (D, R, nlobes, opt, G, p0 = [])
  t0 = tic ();
  ch = struct ("p", [], "ps", {cell(1, nlobes)}, "ktime", nan (1, nlobes), "iter", 0, "full_iter", 0, "cvg", true,
               "rejected", 0, "trace", zeros (0, 2 + D.nch));
  if (! isempty (p0))
    [ch.p, ch.iter, ch.cvg, ch.trace] = fit_lm (D, p0, opt, t0);
    ch.full_iter = ch.iter;
    ch.ps{nlobes} = ch.p;
    return;
  endif
  ## 0 lobes: rho_d by weighted least squares (per channel)
  wl2 = reshape (D.wl .^ 2, [], D.nch);
  p = max (pi * sum (wl2 .* reshape (D.yl, [], D.nch), 1) ./ max (sum (wl2, 1), realmin), 0).';
  f0 = fit_eval (D, p);
  [obj, e0] = fit_objective (D, f0);
  ch.trace = [toc(t0), obj, e0];
  for k = 1:nlobes
    run = add_lobe (D, R, p, obj, opt, G, t0);
    p = run.p;
    obj = run.obj;
    ch.trace = [ch.trace; run.trace];
    ch.iter += run.iter;
    ch.full_iter += run.full_iter;
    ch.rejected += run.rejected;
    ch.cvg = run.cvg;
    ch.ps{k} = p;
    ch.ktime(k) = toc (t0);
  endfor
  ch.p = p;
endfunction

## One more lobe on top of P (objective OBJ).  When TRIES > 1, the best
## start of each of the first TRIES direction families gets up to SCREEN_ITER
## iterations on R and they are ranked by the result; the others follow in
## the order of fit_starts.  From the first start, a warm-up run on R (when
## that pays, see below) and last a run to convergence on D.  A result that
## fails the guard is rejected and the next start tried; a result that is
## not better keeps a zero lobe.
function run = add_lobe (D, R, p, obj, opt, G, t0)
  WARMUP_COST = 2e5;
  WARMUP_TOL = 1e-4;
  run = struct ("p", [p; 0; 0; 1; zeros(D.nch - 1, 1)], "obj", obj, "trace", zeros (0, 2 + D.nch), "iter", 0,
                "full_iter", 0, "rejected", 0, "cvg", true);
  ## a warm-up run on R pays only when R is much smaller than D and an
  ## iteration on D costs much more than leasqr's fixed cost per iteration
  ## (WARMUP_COST, in groups x parameters^2, an SVD's cost: the README's
  ## "Measurements behind the design" says where it was set); it stops at a looser
  ## tolerance, as it only brings the start closer.  Without one, the best
  ## start is refined on R (fit_starts)
  np = numel (p) + 2 + D.nch;
  coarse = 4 * rows (R.x) < rows (D.x) && rows (D.ty) * np ^ 2 > WARMUP_COST;
  starts = fit_starts (R, p, ! coarse);
  if (isempty (starts) || ! (obj > 0))
    return;
  endif
  warm = opt;
  warm.tol = max (opt.tol, WARMUP_TOL);
  ## a warm-up ends by leasqr's own test (fit_lm): its last iteration and
  ## the dampings that iteration tries are on the coarse grid, where they
  ## cost little, and ending it one iteration earlier can cost the run on D
  ## more iterations than it saves
  warm.flat = false;
  ntry = min (opt.tries, columns (starts));
  done = false (1, columns (starts));
  if (ntry > 1)
    screen = opt;
    screen.max_iter = min (opt.screen_iter, opt.max_iter);
    sobj = zeros (1, ntry);
    for i = 1:ntry
      [starts(:,i), it, done(i)] = fit_lm (R, starts(:,i), screen);
      run.iter += it;
      sobj(i) = fit_objective (R, fit_eval (R, starts(:,i)));
    endfor
    [~, so] = sort (sobj);
    starts(:,1:ntry) = starts(:,so);
    done(1:ntry) = done(so);
  endif
  for i = 1:columns (starts)
    ps = starts(:,i);
    if (coarse && ! done(i))
      [ps, it] = fit_lm (R, ps, warm);
      run.iter += it;
    endif
    [pj, it, cv, T] = fit_lm (D, ps, opt, t0);
    run.iter += it;
    run.full_iter += it;
    if (! accepted (D, pj, G))
      run.rejected += 1;
      continue;
    endif
    oj = fit_objective (D, fit_eval (D, pj));
    if (oj < run.obj)
      run.p = pj; run.obj = oj; run.cvg = cv; run.trace = T;
    endif
    break;
  endfor
endfunction

## The guard (fit_guard) on every channel of the parameters P of D
function ok = accepted (D, p, G)
  if (D.nch == 1)
    ok = fit_guard (p, G, D.ymax);
    return;
  endif
  P = shared_lobes ("split", p, D.ref, D.nch);
  ok = true;
  for c = 1:D.nch
    ok = ok && fit_guard (P{c}, G, D.ymax(c));
  endfor
endfunction
